// Doubles as text: std::from_chars and std::to_chars (shortest form that reads back the same
// double), the fastest correct conversions the standard library has.
#pragma once

#include <charconv>
#include <optional>
#include <string>
#include <string_view>
#include <cstdlib>

namespace gh::io {

struct ParsedNumber {
  double value;
  std::size_t length;  // characters used
};

// A number at the start of text ("1", "-2.5e-3", "+4", "inf", "nan"); nullopt if there is none.
inline std::optional<ParsedNumber> parseNumber(std::string_view text) {
  std::size_t skip = !text.empty() && text[0] == '+' ? 1 : 0;
  double value = 0;
  const char* first = text.data() + skip;
  const auto [end, error] = std::from_chars(first, text.data() + text.size(), value);
  if (end == first) return std::nullopt;
  // Out of range: from_chars leaves value unset; the nearest double is what a reader means
  // (1e999 is infinite, which validation refuses; 1e-999 is 0).
  if (error == std::errc::result_out_of_range) {
    const std::string digits(first, end);
    value = std::strtod(digits.c_str(), nullptr);
  } else if (error != std::errc()) {
    return std::nullopt;
  }
  return ParsedNumber{value, static_cast<std::size_t>(end - text.data())};
}

inline void appendNumber(std::string& out, double v) {
  char buffer[32];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, v);
  out.append(buffer, end);
}

}  // namespace gh::io
