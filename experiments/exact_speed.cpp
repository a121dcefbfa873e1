// What exactness costs: the exact variant against the paper's naive variant on the paper's random
// workload (two random n-gons in the unit square, intersection), n = 10, 100, 1000, each timed
// iteration clipping the next pair of the same pool of 16 seeded pairs as Table 1. Many
// repetitions, interleaved in random order, so that the machine's drift hits both alike; the
// report gives medians, the ratio, and how often exact arithmetic was needed. Google Benchmark's
// JSON goes beside the report (OUT.json) and the report is made from it. A second table times
// the construction of crossing points alone: the paper's double formula against the certified
// construction, on this processor's code path and on the one for processors without fma. A third
// times the exact variant on the same pairs scaled to near 1e-301 and 1e150.
//   exact_speed OUT.md [google benchmark flags]
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "common/bench_json.h"
#include "common/bench_run.h"
#include "common/bench_methods.h"
#include "common/provenance.h"
#include "predicates/construction.h"
#include "ghio/formats.h"
#include "predicates/orientation.h"
#include "tool_main.h"

using namespace gh;
using namespace gh::experiments;

namespace {

constexpr int kRepetitions = 25;
const long kSizes[] = {10, 100, 1000};
const char* const kMethods[] = {"naive", "exact"};

// kCrossings pairs of segments in the unit square that cross properly (decided exactly: the
// construction's precondition). Coordinates are the top 53 bits of std::mt19937_64 (seed
// 20261122), whose output the standard fixes.
constexpr long kCrossings = 4096;
struct SegmentPair {
  Point p1, p2, q1, q2;
};
const std::vector<SegmentPair>& crossingSegments() {
  static const std::vector<SegmentPair> pairs = [] {
    std::mt19937_64 rng(20261122);
    auto point = [&rng] {
      const double x = std::ldexp(static_cast<double>(rng() >> 11), -53);
      return Point{x, std::ldexp(static_cast<double>(rng() >> 11), -53)};
    };
    auto opposite = [](detail::Sign a, detail::Sign b) {
      return a != detail::Sign::Zero && b != detail::Sign::Zero && a != b;
    };
    std::vector<SegmentPair> out;
    detail::ExactCounters counters;
    auto orientation = [&counters](Point a, Point b, Point c) { return detail::orientation(a, b, c, counters); };
    while (static_cast<long>(out.size()) < kCrossings) {
      const SegmentPair s{point(), point(), point(), point()};
      if (opposite(orientation(s.p1, s.p2, s.q1), orientation(s.p1, s.p2, s.q2)) &&
          opposite(orientation(s.q1, s.q2, s.p1), orientation(s.q1, s.q2, s.p2))) {
        out.push_back(s);
      }
    }
    return out;
  }();
  return pairs;
}

// The paper's construction in doubles (what the naive variant does), unchecked.
Point doubleCrossing(Point p1, Point p2, Point q1, Point q2, detail::ExactCounters&) {
  const double w1 = (q2.x - q1.x) * (p1.y - q1.y) - (q2.y - q1.y) * (p1.x - q1.x);
  const double w2 = (q2.x - q1.x) * (p2.y - q1.y) - (q2.y - q1.y) * (p2.x - q1.x);
  const double t = w1 / (w1 - w2);
  return {p1.x + t * (p2.x - p1.x), p1.y + t * (p2.y - p1.y)};
}

struct Construction {
  const char* name;
  const char* label;
  Point (*construct)(Point, Point, Point, Point, detail::ExactCounters&);
};
const Construction kConstructions[] = {
    {"double", "the paper's formula in doubles (naive; not certified)", doubleCrossing},
    {"certified",
     "certified, this processor's path (double-double, fma instruction where the processor has it)",
     detail::constructCrossing},
    {"certified-base", "certified, the path for processors without fma (fma by library call)",
     detail::constructCrossingWithoutFmaInstruction},
};

// The exact variant on the same random pairs scaled by powers of two (workloads/: +tiny is 2^-997,
// near 1e-301; +huge brings the largest coordinate to about 2^497, near 1e150): the filters must
// decide there as at 1 (points are scaled towards 1 before them, difference_products.h).
struct Magnitude {
  const char* name;
  const char* suffix;
  const char* label;
};
const Magnitude kMagnitudes[] = {
    {"unit", "", "unit square"},
    {"tiny", "+tiny", "scaled by 2^-997 (~1e-301)"},
    {"huge", "+huge", "scaled to ~2^497 (~1e150)"},
};
constexpr long kMagnitudeSize = 100;

}  // namespace

int run(int argc, char** argv) {
  if (argc < 2 || std::string(argv[1]).rfind("--", 0) == 0) {
    return tools::usageError("exact_speed", "usage: exact_speed OUT.md [google benchmark flags]");
  }
  const std::string out = argv[1];
  const std::string json = std::filesystem::path(out).replace_extension(".json").string();
  for (const char* m : kMethods) {
    auto* b = benchmark::RegisterBenchmark(
        (std::string("random/") + m).c_str(), [m](benchmark::State& s) {
          runMethodOnPool(s, m, seededPool("random", static_cast<std::size_t>(s.range(0))),
                          Op::Intersection);
        });
    for (long n : kSizes) b->Arg(n);
    b->Unit(benchmark::kMicrosecond)->MinTime(0.2)->Repetitions(kRepetitions);
  }
  for (const Magnitude& m : kMagnitudes) {
    auto* b = benchmark::RegisterBenchmark(
        (std::string("magnitude/") + m.name).c_str(), [m](benchmark::State& s) {
          runMethodOnPool(s, "exact", seededPool(std::string("random") + m.suffix, static_cast<std::size_t>(s.range(0))),
                          Op::Intersection);
        });
    b->Arg(kMagnitudeSize)->Unit(benchmark::kMicrosecond)->MinTime(0.2)->Repetitions(kRepetitions);
  }
  for (const Construction& c : kConstructions) {
    auto* b = benchmark::RegisterBenchmark(
        (std::string("construction/") + c.name).c_str(), [c](benchmark::State& s) {
          const auto& pairs = crossingSegments();
          detail::ExactCounters counters;
          for (auto _ : s) {
            for (const SegmentPair& p : pairs)
              benchmark::DoNotOptimize(c.construct(p.p1, p.p2, p.q1, p.q2, counters));
          }
          s.counters["exact_constructions"] =
              static_cast<double>(counters.exactConstructions) /
              static_cast<double>(s.iterations() * pairs.size());
        });
    b->Arg(kCrossings)->Unit(benchmark::kMicrosecond)->MinTime(0.2)->Repetitions(kRepetitions);
  }
  const std::optional<BenchFile> ran = runInterleaved(argc, argv, 2, json);
  if (!ran) return 0;  // listed only
  const BenchFile& f = *ran;

  std::ostringstream md;
  md << "# What exactness costs: exact against naive on the paper's random workload\n\n"
     << markdown(provenance(argc, argv)) << "\n"
     << "Two random n-gons in the unit square, intersection; each timed iteration clips the next "
        "of the "
        "16 seeded pairs of Table 1 (seeds 1000-1015). "
     << kRepetitions
     << " repetitions per method and size, run in random interleaved order; times are "
        "medians over the repetitions, [min-max] beside them. The exact variant picks all pairs "
        "here, as "
        "naive does (clipper/src/search_choice.h), so the ratio is the cost of exact predicates, "
        "Simulation "
        "of Simplicity and certified constructions. Target (issue 6): exact within 1.5x of "
        "naive.\n\n"
     << "| n | naive µs | exact µs | exact / naive | crossings per clip | exact: filter failures "
        "per candidate pair | "
        "exact: constructions rounded from rationals per crossing "
        "|\n|---|---|---|---|---|---|---|\n";
  for (long size : kSizes) {
    const BenchRow* nv = findRow(f, "random/naive", size);
    const BenchRow* ex = findRow(f, "random/exact", size);
    auto cell = [](const BenchRow* r) {
      return r ? timeRange(*r, 1000) : std::string("–");
    };  // ms -> µs
    const double crossings = counterOf(ex, "intersections"),
                 pairs = counterOf(ex, "candidate_pairs");
    md << "| " << size << " | " << cell(nv) << " | " << cell(ex) << " | "
       << (nv && ex ? reportNumber(ex->medianMs / nv->medianMs) : "–") << " | "
       << reportNumber(crossings) << " | "
       << (pairs > 0 ? reportNumber(counterOf(ex, "filter_failures") / pairs) : "–") << " | "
       << (crossings > 0 ? reportNumber(counterOf(ex, "exact_constructions") / crossings) : "–")
       << " |\n";
  }
  md << "\n## Far from 1\n\n"
     << "The exact variant on the same " << kMagnitudeSize
     << "-gon pairs scaled by a power of two, medians of " << kRepetitions
     << " interleaved repetitions. Near 1e-300 the filters' products fall below the normal range and "
        "near 1e150 beyond it; the predicates scale their points towards 1 first (exactly), so the "
        "same decisions are taken at the same stages.\n\n"
     << "| coordinates | exact µs | / unit square | filter failures per candidate pair | decided by "
        "expansions per candidate pair |\n|---|---|---|---|---|\n";
  const BenchRow* unit = findRow(f, "magnitude/unit", kMagnitudeSize);
  for (const Magnitude& m : kMagnitudes) {
    const BenchRow* r = findRow(f, std::string("magnitude/") + m.name, kMagnitudeSize);
    const double pairs = counterOf(r, "candidate_pairs");
    md << "| " << m.label << " | " << (r ? timeRange(*r, 1000) : "–") << " | "
       << (r && unit ? reportNumber(r->medianMs / unit->medianMs) : "–") << " | "
       << (pairs > 0 ? reportNumber(counterOf(r, "filter_failures") / pairs) : "–") << " | "
       << (pairs > 0 ? reportNumber(counterOf(r, "expansion_decisions") / pairs) : "–") << " |\n";
  }
  md << "\n## The construction of crossing points alone\n\n"
     << kCrossings
     << " pairs of crossing segments in the unit square (splitmix64, seed 20261122); each timed "
     << "iteration constructs all of them; medians of " << kRepetitions
     << " repetitions, interleaved with the "
     << "runs above. Certified: each coordinate is a faithful rounding of the exact crossing "
        "(clipper/src/predicates/construction.h), GMP only when the double-double bound cannot certify.\n\n"
     << "| construction | ns per crossing | / double | taken by GMP, per crossing "
        "|\n|---|---|---|---|\n";
  const BenchRow* base = findRow(f, "construction/double", kCrossings);
  for (const Construction& c : kConstructions) {
    const BenchRow* r = findRow(f, std::string("construction/") + c.name, kCrossings);
    const double perCrossing = 1e6 / kCrossings;  // ms per iteration -> ns per crossing
    md << "| " << c.label << " | " << (r ? timeRange(*r, perCrossing) : "–") << " | "
       << (r && base ? reportNumber(r->medianMs / base->medianMs) : "–") << " | "
       << (r ? reportNumber(counterOf(r, "exact_constructions")) : "–") << " |\n";
  }
  io::writeText(out, md.str());
  std::cout << "wrote " << out << "\n";
  return 0;
}

int main(int argc, char** argv) {
  return tools::guardedMain("exact_speed", argc, argv, run);
}
