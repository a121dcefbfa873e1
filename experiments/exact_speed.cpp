// What exactness costs: the exact variant against the paper's naive variant on the paper's random
// workload (two random n-gons in the unit square, intersection), n = 10, 100, 1000, each timed
// iteration clipping the next pair of the same pool of 16 seeded pairs as Table 1. Many
// repetitions, interleaved in random order, so that the machine's drift hits both alike; the
// report gives medians, the ratio, and how often exact arithmetic was needed.
//   exact_speed OUT.md [google benchmark flags]
#include <benchmark/benchmark.h>

#include <algorithm>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "common/bench_methods.h"
#include "common/provenance.h"
#include "ghio/formats.h"

using namespace gh;

namespace {

constexpr std::size_t kPool = 16;
constexpr int kRepetitions = 25;
const long kSizes[] = {10, 100, 1000};
const char* const kMethods[] = {"naive", "exact"};

const std::vector<work::Workload>& pool(std::size_t n) {
  static std::map<std::size_t, std::vector<work::Workload>> cache;
  auto& p = cache[n];
  if (p.empty()) {
    for (std::size_t k = 0; k < kPool; ++k) p.push_back(work::generate("random", n, 1000 + k));
  }
  return p;
}

// The console reporter, also keeping every repetition's time (ms) and counters by "method/n".
class Collector : public benchmark::ConsoleReporter {
 public:
  struct Series {
    std::vector<double> ms;
    std::map<std::string, double> counters;
  };
  std::map<std::string, Series> series;

  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& r : runs) {
      if (r.run_type != Run::RT_Iteration || r.error_occurred) continue;
      Series& s = series[r.run_name.function_name + "/" + r.run_name.args];
      s.ms.push_back(r.GetAdjustedRealTime() * (r.time_unit == benchmark::kMillisecond ? 1 : 1e-3));
      for (const auto& [name, c] : r.counters) s.counters[name] = c.value;
    }
    ConsoleReporter::ReportRuns(runs);
  }
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n == 0 ? 0 : n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

std::string num(double v, int precision = 4) {
  std::ostringstream s;
  s.precision(precision);
  s << v;
  return s.str();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || std::string(argv[1]).rfind("--", 0) == 0) {
    std::cerr << "exact_speed: usage: exact_speed OUT.md [google benchmark flags]\n";
    return 2;
  }
  const std::string out = argv[1];
  for (const char* m : kMethods) {
    auto* b = benchmark::RegisterBenchmark(m, [m](benchmark::State& s) {
      experiments::runMethodOnPool(s, m, pool(static_cast<std::size_t>(s.range(0))), Op::Intersection);
    });
    for (long n : kSizes) b->Arg(n);
    b->Unit(benchmark::kMicrosecond)->MinTime(0.2)->Repetitions(kRepetitions);
  }
  std::vector<char*> args{argv[0]};
  for (int i = 2; i < argc; ++i) args.push_back(argv[i]);
  std::string interleave = "--benchmark_enable_random_interleaving=true";
  args.push_back(interleave.data());
  int n = static_cast<int>(args.size());
  benchmark::Initialize(&n, args.data());
  Collector collector;
  benchmark::RunSpecifiedBenchmarks(&collector);
  benchmark::Shutdown();

  std::ostringstream md;
  md << "# What exactness costs: exact against naive on the paper's random workload\n\n"
     << experiments::markdown(experiments::provenance(argc, argv)) << "\n"
     << "Two random n-gons in the unit square, intersection; each timed iteration clips the next of the "
        "16 seeded pairs of Table 1 (seeds 1000-1015). "
     << kRepetitions << " repetitions per method and size, run in random interleaved order; times are "
        "medians over the repetitions, [min-max] beside them. The exact variant picks all pairs here, as "
        "naive does (clipper/src/search_choice.h), so the ratio is the cost of exact predicates, Simulation "
        "of Simplicity and certified constructions. Target (issue 6): exact within 1.5x of naive.\n\n"
     << "| n | naive µs | exact µs | exact / naive | crossings per clip | exact: filter failures per candidate pair | "
        "exact: constructions rounded from rationals per crossing |\n|---|---|---|---|---|---|---|\n";
  for (long size : kSizes) {
    const auto& nv = collector.series["naive/" + std::to_string(size)];
    const auto& ex = collector.series["exact/" + std::to_string(size)];
    auto cell = [](const Collector::Series& s) {
      if (s.ms.empty()) return std::string("–");
      return num(median(s.ms) * 1000) + " [" + num(*std::min_element(s.ms.begin(), s.ms.end()) * 1000) + "–" +
             num(*std::max_element(s.ms.begin(), s.ms.end()) * 1000) + "]";
    };
    auto counter = [](const Collector::Series& s, const char* name) {
      const auto it = s.counters.find(name);
      return it == s.counters.end() ? 0.0 : it->second;
    };
    const double crossings = counter(ex, "intersections"), pairs = counter(ex, "candidate_pairs");
    md << "| " << size << " | " << cell(nv) << " | " << cell(ex) << " | "
       << (nv.ms.empty() || ex.ms.empty() ? "–" : num(median(ex.ms) / median(nv.ms), 3)) << " | " << num(crossings)
       << " | " << (pairs > 0 ? num(counter(ex, "filter_failures") / pairs, 3) : "–") << " | "
       << (crossings > 0 ? num(counter(ex, "exact_constructions") / crossings, 3) : "–") << " |\n";
  }
  io::writeText(out, md.str());
  std::cout << "wrote " << out << "\n";
  return 0;
}
