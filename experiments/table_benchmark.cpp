// The paper's evaluation (Section 6, Table 1) on this machine, and Table 2 beyond the paper.
//   Table 1: the paper's random workload, n in {10, 20, 50, 100, 200, 500, 1000, 2000} (+5000 with
//            --full): Vatti (Clipper 6.4.2) and our three variants, all five operations; for the
//            intersection also the floor under phase 1 (crossing_floor.h: scalar and vectorized)
//            and naive and exact on every core.
//   Table 2: simple, holes and realistic workloads at a few sizes, every variant and every peer,
//            intersection and union.
// Each timed iteration clips the next pair of a pool of 16 seeded pairs per size (the paper
// averaged over fresh random polygons); repetitions give medians and spread.
//   table_benchmark [--full] [google benchmark flags]
#include <benchmark/benchmark.h>

#include <map>
#include <string>
#include <vector>

#include "common/bench_methods.h"

using namespace gh;

namespace {

void add(const std::string& table, const std::string& workload, const std::string& method, Op op,
         const std::vector<long>& sizes) {
  const std::string family = table + "-" + workload + "-" + std::string(name(op)) + "/" + method;
  auto* b = benchmark::RegisterBenchmark(family.c_str(), [workload, method, op](benchmark::State& s) {
    experiments::runMethodOnPool(s, method, experiments::seededPool(workload, static_cast<std::size_t>(s.range(0))), op);
  });
  for (long n : sizes) b->Arg(n);
  b->Unit(benchmark::kMillisecond)->MinTime(0.2);
}

}  // namespace

int main(int argc, char** argv) {
  const bool full = experiments::takeFullFlag(argc, argv);
  std::vector<long> t1{10, 20, 50, 100, 200, 500, 1000, 2000};
  if (full) t1.push_back(5000);
  for (Op op : kAllOps) {
    for (const char* m : {"clipper6", "naive", "sweep", "exact"}) add("t1", "random", m, op, t1);
    if (op == Op::Intersection) {
      // The floor does not trace: the same for every operation, timed once.
      for (const char* m : {"crossings", "crossings-simd", "naive@all", "exact@all"}) add("t1", "random", m, op, t1);
    }
  }
  const std::map<std::string, std::vector<long>> t2{{"simple", {100, 1000}},
                                                     {"holes", {100, 1000}},
                                                     {"circles", {1000, 10000, 100000}},
                                                     {"coastline", {1000, 10000, 100000}}};
  for (const auto& [workload, sizes] : t2) {
    for (Op op : {Op::Intersection, Op::Union}) {
      for (const char* m : {"naive", "sweep", "exact", "clipper6", "geos", "boost", "cgal"}) {
        std::vector<long> use = sizes;
        // The paper's all-pairs search is quadratic: 10^5-vertex outlines take it seconds per clip.
        if (std::string(m) == "naive" && use.back() > 10000) use.pop_back();
        add("t2", workload, m, op, use);
      }
    }
  }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
