#pragma once
/// @file json_writer.hpp
/// @brief A minimal JSON object writer for stats files (flat keys; strings escaped; non-finite ->
/// null).
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace lucent::cli {

class JsonObject {
 public:
  JsonObject& add(const std::string& key, double v) {
    std::ostringstream s;
    if (std::isfinite(v)) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.10g", v);
      s << buf;
    } else {
      s << "null";
    }
    return raw(key, s.str());
  }
  JsonObject& add(const std::string& key, const std::string& v) { return raw(key, quote(v)); }
  JsonObject& add(const std::string& key, const char* v) { return raw(key, quote(v)); }
  JsonObject& add(const std::string& key, const JsonObject& v) { return raw(key, v.str()); }
  JsonObject& raw(const std::string& key, const std::string& json) {
    mBody += (mBody.empty() ? "" : ",\n  ") + quote(key) + ": " + json;
    return *this;
  }
  std::string str() const { return "{\n  " + mBody + "\n}"; }

  static std::string quote(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
      if (c == '"' || c == '\\')
        out += '\\', out += c;
      else if (c == '\n')
        out += "\\n";
      else if (static_cast<unsigned char>(c) < 0x20)
        out += ' ';
      else
        out += c;
    }
    return out + "\"";
  }

 private:
  std::string mBody;
};

/// "[a, b]" of JSON values written already.
inline std::string jsonArray(const std::vector<std::string>& json) {
  std::string s = "[";
  for (std::size_t i = 0; i < json.size(); ++i) s += (i ? ", " : "") + json[i];
  return s + "]";
}

/// "[\"a\", \"b\"]" of strings.
inline std::string jsonStrings(const std::vector<std::string>& items) {
  std::vector<std::string> quoted;
  for (const auto& item : items) quoted.push_back(JsonObject::quote(item));
  return jsonArray(quoted);
}

}  // namespace lucent::cli
