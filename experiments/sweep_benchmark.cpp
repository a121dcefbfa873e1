// The sweep variant's speed beyond the paper's workload, every method side by side in one run with
// Google Benchmark's complexity fit per method:
//   circles      two slightly perturbed circles of n vertices each, crossing twice, intersection:
//                n = 10^3..10^6 (naive to 10^5, CGAL to 10^5; --full: CGAL to 10^6)
//   archipelago  islands holding lakes holding islets, ~n vertices in ~n/15 rings, union:
//                n = 10^3..10^5 (--full: 10^6)
//   pie, flower  K triangles or petals sharing the origin against the same turned, intersection:
//                K = 256, 512, 1024 (many edges through one point; the valid-input peers refuse it)
//   random       the paper's workload, where P ~ n*m and the sweep cannot win
//   sweep_benchmark [--full] [google benchmark flags]
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

void registerFamily(const std::string& workload, const std::string& method, const std::vector<long>& sizes,
                    Op op = Op::Intersection) {
  auto* b = benchmark::RegisterBenchmark((workload + "/" + method).c_str(), [workload, method, op](benchmark::State& s) {
    const auto n = static_cast<std::size_t>(s.range(0));
    experiments::runMethod(s, method, cached(workload, n), op);
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
  const std::vector<long> circles{1000, 10000, 100000, 1000000};
  for (const char* m : {"sweep", "sweep@all", "exact", "exact@all", "clipper6", "geos", "boost"}) {
    registerFamily("circles", m, circles);
  }
  registerFamily("circles", "cgal", full ? circles : std::vector<long>{1000, 10000, 100000});
  registerFamily("circles", "naive", {1000, 3000, 10000, 30000, 100000});
  const std::vector<long> islands = full ? std::vector<long>{1000, 10000, 100000, 1000000} : std::vector<long>{1000, 10000, 100000};
  for (const char* m : {"sweep", "exact", "exact@all", "clipper6", "geos", "boost", "cgal"}) {
    registerFamily("archipelago", m, islands, Op::Union);
  }
  for (const char* workload : {"pie", "flower"}) {
    for (const char* m : {"naive", "exact", "clipper6"}) registerFamily(workload, m, {256, 512, 1024});
  }
  // The paper's workload: every box overlaps every other, so the sweep reports ~n*m pairs too.
  for (const char* m : {"sweep", "naive", "exact", "exact-allpairs"}) registerFamily("random", m, {10, 100, 1000});
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
