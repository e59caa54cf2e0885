// A minimal ordered JSON object writer (numbers, strings, bools, arrays, nested objects): the
// --json outputs of the CLI and the data of the HTML report's viewer.
#pragma once
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace msmesh {

class Json {
 public:
  Json& add(const std::string& key, double v) { return raw(key, number(v)); }
  Json& add(const std::string& key, long long v) { return raw(key, std::to_string(v)); }
  Json& add(const std::string& key, int v) { return raw(key, std::to_string(v)); }
  Json& add(const std::string& key, long v) { return raw(key, std::to_string(v)); }
  Json& add(const std::string& key, bool v) { return raw(key, v ? "true" : "false"); }
  Json& add(const std::string& key, const char* v) { return raw(key, quote(v)); }
  Json& add(const std::string& key, const std::string& v) { return raw(key, quote(v)); }
  Json& add(const std::string& key, const Json& v) { return raw(key, v.str()); }
  Json& add(const std::string& key, const std::vector<double>& v) {
    std::string s = "[";
    for (size_t i = 0; i < v.size(); ++i) s += (i ? "," : "") + number(v[i]);
    return raw(key, s + "]");
  }
  Json& add(const std::string& key, const std::vector<int>& v) {
    std::string s = "[";
    for (size_t i = 0; i < v.size(); ++i) s += (i ? "," : "") + std::to_string(v[i]);
    return raw(key, s + "]");
  }
  Json& add(const std::string& key, const std::vector<Json>& v) {
    std::string s = "[";
    for (size_t i = 0; i < v.size(); ++i) s += (i ? "," : "") + v[i].str();
    return raw(key, s + "]");
  }
  Json& raw(const std::string& key, const std::string& value) {
    items_.emplace_back(key, value);
    return *this;
  }
  std::string str() const {
    std::string s = "{";
    for (size_t i = 0; i < items_.size(); ++i) s += (i ? "," : "") + quote(items_[i].first) + ":" + items_[i].second;
    return s + "}";
  }
  static std::string number(double v) {
    if (!std::isfinite(v)) return "null";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return buf;
  }
  static std::string quote(const std::string& s) {
    std::string o = "\"";
    for (char c : s) {
      switch (c) {
        case '"':
          o += "\\\"";
          break;
        case '\\':
          o += "\\\\";
          break;
        case '\n':
          o += "\\n";
          break;
        case '\t':
          o += "\\t";
          break;
        default:
          if (static_cast<unsigned char>(c) < 0x20) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04x", c);
            o += buf;
          } else {
            o += c;
          }
      }
    }
    return o + "\"";
  }

 private:
  std::vector<std::pair<std::string, std::string>> items_;
};

}  // namespace msmesh
