#pragma once
// The JSON text builder of the reports of cmx::map_to_domain and the CLI: objects with keys in
// insertion order and the reports' fixed layout, strings escaped by nlohmann-json (api/json.cpp),
// doubles printed with 17 significant digits (round-trip; non-finite as null). Exact rationals go
// in as strings.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace cmx::api {

// `text` as a JSON string (nlohmann-json's escaping; bytes that are not UTF-8 become U+FFFD, so
// the output is always valid JSON).
std::string json_quote(const std::string& text);

inline std::string json_number(double x) {
  if (!std::isfinite(x)) return "null";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

class JsonObject {
 public:
  JsonObject& raw(const std::string& key, const std::string& json_text) {
    fields_.push_back(json_quote(key) + ": " + json_text);
    return *this;
  }
  JsonObject& str(const std::string& key, const std::string& v) { return raw(key, json_quote(v)); }
  JsonObject& num(const std::string& key, double v) { return raw(key, json_number(v)); }
  JsonObject& num(const std::string& key, std::uint64_t v) { return raw(key, std::to_string(v)); }
  JsonObject& num(const std::string& key, std::int64_t v) { return raw(key, std::to_string(v)); }
  JsonObject& flag(const std::string& key, bool v) { return raw(key, v ? "true" : "false"); }
  JsonObject& obj(const std::string& key, const JsonObject& v) { return raw(key, v.text()); }

  std::string text(int indent = 0) const {
    if (fields_.empty()) return "{}";
    const std::string pad(std::size_t(indent + 2), ' '), end_pad(std::size_t(indent), ' ');
    std::string out = "{\n";
    for (std::size_t i = 0; i < fields_.size(); ++i) {
      out += pad;
      out += fields_[i];
      out += i + 1 < fields_.size() ? ",\n" : "\n";
    }
    out += end_pad;
    out += '}';
    return out;
  }

 private:
  std::vector<std::string> fields_;
};

}  // namespace cmx::api
