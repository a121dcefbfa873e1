// Google Benchmark bodies shared by the timing programs: one method on one prepared workload.
// Peers convert their operands before the timed loop (prepare()); our variants are timed through
// gh::clip, validation included. After the loop each answer is checked once by the sampling
// oracle (outside the timed region): a wrong answer is reported as counter "wrong" = 1, never
// hidden.
#pragma once

#include <benchmark/benchmark.h>

#include <algorithm>
#include <map>
#include <memory>
#include <vector>
#include <string>

#include "crossing_floor.h"
#include "ghclip/clip.h"
#include "ghclip/measure.h"
#include "ghoracle/exact_oracle.h"
#include "ghpeers/peer.h"
#include "ghoracle/sampling_oracle.h"
#include "ghwork/generators.h"

namespace gh::experiments {

// The pool of a timing table: kPoolSize seeded pairs of a workload (seeds 1000, 1001, ...), made
// once per (workload, n) and shared by every program that times on it, so their cells compare.
inline constexpr std::size_t kPoolSize = 16;
inline const std::vector<work::Workload>& seededPool(const std::string& workload, std::size_t n) {
  static std::map<std::pair<std::string, std::size_t>, std::vector<work::Workload>> cache;
  auto& p = cache[{workload, n}];
  if (p.empty()) {
    for (std::size_t k = 0; k < kPoolSize; ++k) p.push_back(work::generate(workload, n, 1000 + k));
  }
  return p;
}

// Our variants by the name of their combination of arithmetic and search (gh::parseOptions:
// "naive", "sweep", "exact", "exact-allpairs", "exact-sweep"; "@all" or "@N" after it for every core
// or N threads, one otherwise), a peer ("clipper6", ...), or "crossings" / "crossings-simd", the floor
// under phase 1 (crossing_floor.h: its answers are not clips, not checked), on a pool of workloads: iteration i clips pool[i % size], as the paper
// averaged over fresh random polygons. Every answer of the last round through the pool is
// checked (exact oracle for small inputs, sampling oracle otherwise).
inline void runMethodOnPool(benchmark::State& state, const std::string& method, const std::vector<work::Workload>& pool,
                            Op op) {
  if (method == "crossings" || method == "crossings-simd") {
    // The floor (clipper/src/crossing_floor.h): every pair tested, every crossing constructed;
    // -simd: through the vectorized pair test.
    std::vector<detail::Crossing> crossings;
    std::size_t i = 0, found = 0;
    for (auto _ : state) {
      const auto& w = pool[i++ % pool.size()];
      found += detail::crossingFloor(w.subject, w.clip, crossings, method == "crossings-simd");
      benchmark::DoNotOptimize(crossings.data());
    }
    state.counters["intersections"] = static_cast<double>(found) / static_cast<double>(std::max<std::size_t>(i, 1));
    return;
  }
  std::vector<Region> results(pool.size());
  std::vector<Stats> stats(pool.size());
  std::size_t i = 0;
  if (const peers::Peer* peer = peers::findPeer(method)) {
    std::vector<std::unique_ptr<peers::Prepared>> s, c;
    try {
      for (const auto& w : pool) s.push_back(peer->prepare(w.subject)), c.push_back(peer->prepare(w.clip));
    } catch (const std::exception& e) {
      state.SkipWithError(e.what());
      return;
    }
    for (auto _ : state) {
      const std::size_t k = i++ % pool.size();
      results[k] = peer->run(*s[k], *c[k], op);
      benchmark::DoNotOptimize(results[k].data());
    }
  } else {
    // "name@all": on every core (Options::threads = 0), "name@N": on N threads; else one.
    const auto at = method.find('@');
    Options o = *parseOptions(method.substr(0, at));
    if (at != std::string::npos) {
      const std::string threads = method.substr(at + 1);
      o.threads = threads == "all" ? 0 : static_cast<unsigned>(std::stoul(threads));
    }
    for (auto _ : state) {
      const std::size_t k = i++ % pool.size();
      results[k] = clip(pool[k].subject, pool[k].clip, op, o, &stats[k]);
      benchmark::DoNotOptimize(results[k].data());
    }
  }
  double intersections = 0, outputVertices = 0, wrong = 0, filterFailures = 0, pairs = 0, constructions = 0,
         expansions = 0;
  const std::size_t checked = std::min<std::size_t>(i, pool.size());
  // Answers are deterministic: check them in the first repetition only (the others would
  // recheck the same answers), and remember the verdict for the later ones.
  static std::map<std::string, double> verdicts;
  const std::string key = method + "/" + std::string(name(op)) + "/" + std::to_string(vertexCount(pool[0].subject)) +
                          "/" + std::to_string(pool.size());
  const bool checkNow = !verdicts.count(key);
  for (std::size_t k = 0; k < checked; ++k) {
    intersections += static_cast<double>(stats[k].intersections);
    filterFailures += static_cast<double>(stats[k].filterFailures);
    expansions += static_cast<double>(stats[k].expansionDecisions);
    constructions += static_cast<double>(stats[k].exactConstructions);
    pairs += static_cast<double>(stats[k].candidatePairs);
    outputVertices += static_cast<double>(vertexCount(results[k]));
    if (!checkNow) continue;
    const auto& w = pool[k];
    const std::size_t size = vertexCount(w.subject) + vertexCount(w.clip) + vertexCount(results[k]);
    bool ok;
    if (size <= 400) {
      ok = oracle::exactCheck(w.subject, w.clip, op, results[k], {false, false, false}).pass;
    } else {
      // Each sampled point costs a pass over every edge: fewer points for huge answers.
      oracle::SampleOptions so;
      so.uniformPoints = size <= 100000 ? 400 : 100;
      so.nearVertices = size <= 5000;
      ok = oracle::sampleCheck(w.subject, w.clip, op, results[k], so).pass();
    }
    wrong += ok ? 0 : 1;
  }
  if (checkNow) verdicts[key] = wrong;
  wrong = verdicts[key];
  const double m = checked ? static_cast<double>(checked) : 1;
  if (!peers::findPeer(method)) {
    state.counters["intersections"] = intersections / m;
    state.counters["filter_failures"] = filterFailures / m;
    state.counters["expansion_decisions"] = expansions / m;
    state.counters["exact_constructions"] = constructions / m;
    state.counters["candidate_pairs"] = pairs / m;
  }
  state.counters["output_vertices"] = outputVertices / m;
  state.counters["wrong"] = wrong;
  state.counters["checked"] = static_cast<double>(checked);
}

// One workload: a pool of one.
inline void runMethod(benchmark::State& state, const std::string& method, const work::Workload& w, Op op) {
  runMethodOnPool(state, method, std::vector<work::Workload>{w}, op);
}

// Removes "--full" from argv (Google Benchmark rejects flags it does not know); true if present.
inline bool takeFullFlag(int& argc, char** argv) {
  bool full = false;
  int kept = 0;
  for (int i = 0; i < argc; ++i) {
    if (std::string(argv[i]) == "--full") {
      full = true;
    } else {
      argv[kept++] = argv[i];
    }
  }
  argc = kept;
  return full;
}

}  // namespace gh::experiments
