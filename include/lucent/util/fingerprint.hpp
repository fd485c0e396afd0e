#pragma once
/// @file fingerprint.hpp
/// @brief 64-bit FNV-1a, chained: a fingerprint of the bytes, strings and arrays it is fed. Used
/// to tell whether what a cached result was built from has changed (the report's result cache,
/// the VTK filter's kept precomputation); not for security.
#include <cstdint>
#include <cstdio>
#include <string>
#include <type_traits>
#include <vector>

namespace lucent::util {

class Fingerprint {
 public:
  Fingerprint& addBytes(const void* data, std::size_t n) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i) {
      mHash ^= bytes[i];
      mHash *= 1099511628211ull;
    }
    return *this;
  }
  /// A string and a separator, so ("ab", "c") differs from ("a", "bc").
  Fingerprint& add(const std::string& text) {
    addBytes(text.data(), text.size());
    return addBytes("", 1);
  }
  /// A trivially copyable value's bytes (numbers, glm vectors).
  template <class T, class = std::enable_if_t<std::is_trivially_copyable_v<T>>>
  Fingerprint& addValue(const T& value) {
    return addBytes(&value, sizeof value);
  }
  /// The array's length and its elements' bytes.
  template <class T, class = std::enable_if_t<std::is_trivially_copyable_v<T>>>
  Fingerprint& addArray(const std::vector<T>& values) {
    addValue(std::uint64_t(values.size()));
    return addBytes(values.data(), values.size() * sizeof(T));
  }
  std::uint64_t value() const { return mHash; }
  std::string hex() const {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(mHash));
    return text;
  }

 private:
  std::uint64_t mHash = 14695981039346656037ull;
};

}  // namespace lucent::util
