// The file that pins what the clip targets' judges find (tests/golden/judge_verdicts.golden): one
// line per fuzz input, "<input in hex> | <naive> | <sweep> | <exact>", '#' lines comments. Read by
// its test (tests/golden/judge_verdicts_test.cpp) and by experiments/judge_cost.cpp, which times
// the targets' stages on the same inputs.
#pragma once

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

namespace gh::fuzz {

inline std::string hexOf(const std::vector<std::uint8_t>& bytes) {
  static const char digits[] = "0123456789abcdef";
  std::string out;
  for (std::uint8_t b : bytes) out += digits[b >> 4], out += digits[b & 15];
  return out;
}

inline std::vector<std::uint8_t> bytesOfHex(const std::string& hex) {
  auto value = [](char c) { return c <= '9' ? c - '0' : c - 'a' + 10; };
  std::vector<std::uint8_t> out;
  for (std::size_t i = 0; i + 1 < hex.size(); i += 2) out.push_back(static_cast<std::uint8_t>(value(hex[i]) * 16 + value(hex[i + 1])));
  return out;
}

struct JudgePin {
  std::string hex;       // the input
  std::string verdicts;  // " | <naive> | <sweep> | <exact>", as written
};

// Every pin of the file in order; none when it cannot be read.
inline std::vector<JudgePin> readJudgePins(const std::string& path) {
  std::ifstream in(path);
  std::vector<JudgePin> pins;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const std::size_t bar = line.find(" | ");
    pins.push_back({line.substr(0, bar), bar == std::string::npos ? "" : line.substr(bar)});
  }
  return pins;
}

}  // namespace gh::fuzz
