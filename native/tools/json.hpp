#pragma once
// A minimal JSON writer for the CLI's --json output: objects of numbers, strings and nested
// objects, keys in insertion order so that output is stable.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <type_traits>
#include <vector>

namespace hbc::cli {

class JsonWriter {
 public:
  JsonWriter& begin(const char* key = nullptr) {
    sep(key);
    out_ += '{';
    first_ = true;
    ++depth_;
    return *this;
  }
  JsonWriter& end() {
    --depth_;
    out_ += '\n';
    indent();
    out_ += '}';
    first_ = false;
    return *this;
  }
  JsonWriter& num(const char* key, int64_t v) {
    sep(key);
    out_ += std::to_string(v);
    return *this;
  }
  JsonWriter& real(const char* key, double v, int digits = 6) {
    sep(key);
    if (!std::isfinite(v)) {
      out_ += "null";
      return *this;
    }
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", digits, v);
    out_ += buf;
    return *this;
  }
  JsonWriter& str(const char* key, const std::string& v) {
    sep(key);
    out_ += '"';
    for (char c : v) {
      if (c == '"' || c == '\\') {
        out_ += '\\';
        out_ += c;
      } else if (static_cast<unsigned char>(c) < 0x20) {
        char buf[8];
        std::snprintf(buf, sizeof buf, "\\u%04x", c);
        out_ += buf;
      } else {
        out_ += c;
      }
    }
    out_ += '"';
    return *this;
  }
  // A one-line array of numbers (integers as such, reals with `digits` decimals, null if not finite).
  template <class T>
  JsonWriter& array(const char* key, const std::vector<T>& v, int digits = 6) {
    sep(key);
    out_ += '[';
    for (size_t i = 0; i < v.size(); ++i) {
      if (i) out_ += ", ";
      char buf[64];
      if constexpr (std::is_integral_v<T>) std::snprintf(buf, sizeof buf, "%lld", static_cast<long long>(v[i]));
      else if (!std::isfinite(v[i])) std::snprintf(buf, sizeof buf, "null");
      else std::snprintf(buf, sizeof buf, "%.*f", digits, static_cast<double>(v[i]));
      out_ += buf;
    }
    out_ += ']';
    return *this;
  }
  const std::string& text() const { return out_; }

 private:
  void indent() { out_.append(static_cast<size_t>(2 * depth_), ' '); }
  void sep(const char* key) {
    if (depth_ > 0) {
      if (!first_) out_ += ',';
      out_ += '\n';
      indent();
    }
    first_ = false;
    if (key) {
      out_ += '"';
      out_ += key;
      out_ += "\": ";
    }
  }
  std::string out_;
  bool first_ = true;
  int depth_ = 0;
};

}  // namespace hbc::cli
