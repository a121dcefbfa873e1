// Reading Google Benchmark's JSON output (the only input of the table generators).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace gh::experiments {

struct BenchRow {
  std::string family;  // e.g. "circles/sweep"
  long n = 0;
  double medianMs = 0, minMs = 0, maxMs = 0;  // over repetitions (all equal without repetitions)
  int repetitions = 0;
  long iterations = 0;
  std::map<std::string, double> counters;
};

struct BenchFit {
  std::string bigO;  // "N", "NlgN", "N^2", ...
  double coefficient = 0;
  double rms = 0;
};

struct BenchFile {
  std::map<std::string, std::map<long, BenchRow>> rows;  // family -> n -> row
  std::map<std::string, BenchFit> fits;                  // family -> complexity fit
  std::map<std::string, std::string> context;            // host, date, cpu info
};

// Throws std::runtime_error on unreadable JSON.
BenchFile readBenchJson(const std::string& path);

}  // namespace gh::experiments
