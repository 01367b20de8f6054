// One CSV field per RFC 4180: quoted when it holds a comma, a quote or a
// line break, with quotes doubled.
#pragma once

#include <string>

namespace particles::cli {

inline std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

}  // namespace particles::cli
