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

// Throws tools::BadInput naming the file when it is missing, is not Google Benchmark JSON or
// holds no results (e.g. a --benchmark_filter that matched nothing).
BenchFile readBenchJson(const std::string& path);

// The row of `family` at n, or nullptr.
const BenchRow* findRow(const BenchFile& f, const std::string& family, long n);

// A counter of a row (0 when the row or the counter is missing).
double counterOf(const BenchRow* r, const std::string& name);

// How the reports print numbers: 3 significant digits below 1, else 4.
std::string reportNumber(double v);

// "median [min–max]" of a row's times in ms times `scale` (the range only with repetitions).
std::string timeRange(const BenchRow& r, double scale = 1);

}  // namespace gh::experiments
