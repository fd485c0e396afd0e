#pragma once
/// @file json_writer.hpp
/// @brief A minimal JSON object writer for stats files (flat keys; strings escaped; non-finite -> null).
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

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
      if (c == '"' || c == '\\') out += '\\', out += c;
      else if (c == '\n') out += "\\n";
      else if (static_cast<unsigned char>(c) < 0x20) out += ' ';
      else out += c;
    }
    return out + "\"";
  }

 private:
  std::string mBody;
};

}  // namespace lucent::cli
