#include "bench_run.h"

#include <benchmark/benchmark.h>

#include <vector>

#include "tool_main.h"

namespace gh::experiments {

std::optional<BenchFile> runInterleaved(int argc, char** argv, int first, const std::string& json) {
  std::vector<char*> args{argv[0]};
  bool listing = false;
  for (int i = first; i < argc; ++i) {
    args.push_back(argv[i]);
    listing = listing || std::string(argv[i]).rfind("--benchmark_list_tests", 0) == 0;
  }
  std::string interleave = "--benchmark_enable_random_interleaving=true", outFlag = "--benchmark_out=" + json,
              formatFlag = "--benchmark_out_format=json";
  for (std::string* flag : {&interleave, &outFlag, &formatFlag}) args.push_back(flag->data());
  int n = static_cast<int>(args.size());
  benchmark::Initialize(&n, args.data());
  const std::size_t ran = benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  if (listing) return std::nullopt;
  if (ran == 0) throw tools::BadInput("no benchmark matched the --benchmark_filter given");
  return readBenchJson(json);
}

}  // namespace gh::experiments
