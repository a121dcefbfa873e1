// What exactness costs: the exact variant against the paper's naive variant on the paper's random
// workload (two random n-gons in the unit square, intersection), n = 10, 100, 1000, each timed
// iteration clipping the next pair of the same pool of 16 seeded pairs as Table 1. Many
// repetitions, interleaved in random order, so that the machine's drift hits both alike; the
// report gives medians, the ratio, and how often exact arithmetic was needed. Google Benchmark's
// JSON goes beside the report (OUT.json) and the report is made from it.
//   exact_speed OUT.md [google benchmark flags]
#include <benchmark/benchmark.h>

#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "common/bench_json.h"
#include "common/bench_methods.h"
#include "common/provenance.h"
#include "ghio/formats.h"
#include "tool_main.h"

using namespace gh;
using namespace gh::experiments;

namespace {

constexpr int kRepetitions = 25;
const long kSizes[] = {10, 100, 1000};
const char* const kMethods[] = {"naive", "exact"};

}  // namespace

int run(int argc, char** argv) {
  if (argc < 2 || std::string(argv[1]).rfind("--", 0) == 0) {
    return tools::usageError("exact_speed", "usage: exact_speed OUT.md [google benchmark flags]");
  }
  const std::string out = argv[1];
  const std::string json = std::filesystem::path(out).replace_extension(".json").string();
  for (const char* m : kMethods) {
    auto* b = benchmark::RegisterBenchmark((std::string("random/") + m).c_str(), [m](benchmark::State& s) {
      runMethodOnPool(s, m, seededPool("random", static_cast<std::size_t>(s.range(0))), Op::Intersection);
    });
    for (long n : kSizes) b->Arg(n);
    b->Unit(benchmark::kMicrosecond)->MinTime(0.2)->Repetitions(kRepetitions);
  }
  std::vector<char*> args{argv[0]};
  bool listing = false;
  for (int i = 2; i < argc; ++i) {
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
  if (listing) return 0;
  if (ran == 0) throw tools::BadInput("no benchmark matched the --benchmark_filter given");
  const BenchFile f = readBenchJson(json);

  std::ostringstream md;
  md << "# What exactness costs: exact against naive on the paper's random workload\n\n"
     << markdown(provenance(argc, argv)) << "\n"
     << "Two random n-gons in the unit square, intersection; each timed iteration clips the next of the "
        "16 seeded pairs of Table 1 (seeds 1000-1015). "
     << kRepetitions << " repetitions per method and size, run in random interleaved order; times are "
        "medians over the repetitions, [min-max] beside them. The exact variant picks all pairs here, as "
        "naive does (clipper/src/search_choice.h), so the ratio is the cost of exact predicates, Simulation "
        "of Simplicity and certified constructions. Target (issue 6): exact within 1.5x of naive.\n\n"
     << "| n | naive µs | exact µs | exact / naive | crossings per clip | exact: filter failures per candidate pair | "
        "exact: constructions rounded from rationals per crossing |\n|---|---|---|---|---|---|---|\n";
  for (long size : kSizes) {
    const BenchRow* nv = findRow(f, "random/naive", size);
    const BenchRow* ex = findRow(f, "random/exact", size);
    auto cell = [](const BenchRow* r) { return r ? timeRange(*r, 1000) : std::string("–"); };  // ms -> µs
    const double crossings = counterOf(ex, "intersections"), pairs = counterOf(ex, "candidate_pairs");
    md << "| " << size << " | " << cell(nv) << " | " << cell(ex) << " | "
       << (nv && ex ? reportNumber(ex->medianMs / nv->medianMs) : "–") << " | " << reportNumber(crossings) << " | "
       << (pairs > 0 ? reportNumber(counterOf(ex, "filter_failures") / pairs) : "–") << " | "
       << (crossings > 0 ? reportNumber(counterOf(ex, "exact_constructions") / crossings) : "–") << " |\n";
  }
  io::writeText(out, md.str());
  std::cout << "wrote " << out << "\n";
  return 0;
}

int main(int argc, char** argv) { return tools::guardedMain("exact_speed", argc, argv, run); }
