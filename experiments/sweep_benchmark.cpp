// The sweep variant's speed on the realistic workload: two slightly perturbed circles of n
// vertices each, crossing twice, intersected; sweep vs naive vs exact vs every peer, side by side
// in one run, with Google Benchmark's complexity fit per method. Also the paper's random
// workload, where P ~ n*m and the sweep cannot win.
//   sweep_benchmark [--full] [google benchmark flags]
// Bounded (default): n = 10^3..10^5 (naive to 3*10^4 plus one run at 10^5); --full: to 10^6.
#include <benchmark/benchmark.h>

#include <map>
#include <string>
#include <vector>

#include "common/bench_methods.h"

using namespace gh;

namespace {

const work::Workload& cached(const std::string& name, std::size_t n) {
  static std::map<std::pair<std::string, std::size_t>, work::Workload> cache;
  auto it = cache.find({name, n});
  if (it == cache.end()) it = cache.emplace(std::make_pair(name, n), work::generate(name, n, 1)).first;
  return it->second;
}

void registerFamily(const std::string& workload, const std::string& method, const std::vector<long>& sizes) {
  auto* b = benchmark::RegisterBenchmark((workload + "/" + method).c_str(), [workload, method](benchmark::State& s) {
    const auto n = static_cast<std::size_t>(s.range(0));
    experiments::runMethod(s, method, cached(workload, n), Op::Intersection);
    s.SetComplexityN(s.range(0));
  });
  for (long n : sizes) b->Arg(n);
  b->Unit(benchmark::kMillisecond)->Complexity();
  // Slow cases run once per repetition instead of until the minimum time is reached.
  b->MinTime(0.2);
}

}  // namespace

int main(int argc, char** argv) {
  const bool full = experiments::takeFullFlag(argc, argv);
  const std::vector<long> fast = full ? std::vector<long>{1000, 10000, 100000, 1000000} : std::vector<long>{1000, 10000, 100000};
  for (const char* m : {"sweep", "exact", "clipper6", "geos", "boost"}) registerFamily("circles", m, fast);
  registerFamily("circles", "cgal", full ? std::vector<long>{1000, 10000, 100000, 1000000} : std::vector<long>{1000, 10000, 100000});
  registerFamily("circles", "naive", {1000, 3000, 10000, 30000, 100000});
  // The paper's workload: every box overlaps every other, so the sweep reports ~n*m pairs too.
  for (const char* m : {"sweep", "naive", "exact", "exact-allpairs"}) registerFamily("random", m, {10, 100, 1000});
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
