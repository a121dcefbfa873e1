// Running the registered Google Benchmarks the way every report generator here does.
#pragma once

#include <optional>
#include <string>

#include "bench_json.h"

namespace gh::experiments {

// Runs the registered benchmarks with the user's flags (argv[first] on) plus random interleaving
// and JSON output to `json`, and reads the results back; nullopt when the flags only list the
// benchmarks (--benchmark_list_tests). Throws tools::BadInput when no benchmark matched a
// --benchmark_filter.
std::optional<BenchFile> runInterleaved(int argc, char** argv, int first, const std::string& json);

}  // namespace gh::experiments
