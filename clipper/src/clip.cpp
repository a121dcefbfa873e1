// The orchestrator: validate, phase 1, phase 2, phase 3, clean-up (clipper/src/README.md maps the
// paper's sections to the files). The arithmetic policy is chosen once here; the paper's
// perturbation wraps phase 1 for the paper arithmetic only.
#include "ghclip/clip.h"

#include <chrono>

#include "arithmetic/exact_arithmetic.h"
#include "arithmetic/paper_arithmetic.h"
#include "cleanup.h"
#include "ghclip/measure.h"
#include "paper_perturbation.h"
#include "phase1_intersections.h"
#include "phase2_marking.h"
#include "phase3_tracing.h"
#include "recycled.h"
#include "search/all_pairs_search.h"
#include "search/search_choice.h"
#include "search/sweep_search.h"
#include "vertex_graph.h"

namespace gh {
namespace {

using Clock = std::chrono::steady_clock;
using namespace detail;

double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// Phase 1 as each arithmetic needs it: the exact one plain, the paper's inside its perturbation loop.
template <class CandidateSearch>
Phase1Result phase1(Operand s, Operand c, const CandidateSearch& search, const ExactArithmetic& a, Stats& stats,
                    unsigned threads) {
  return findIntersections(std::move(s), std::move(c), search, a, stats, nullptr, threads);
}
template <class CandidateSearch>
Phase1Result phase1(Operand s, Operand c, const CandidateSearch& search, const PaperArithmetic& a, Stats& stats,
                    unsigned threads) {
  return findIntersectionsPerturbed(std::move(s), std::move(c), search, a, stats, threads);
}

// Search::Auto resolved: the paper arithmetic tests all pairs, as in the paper; the exact one
// whichever pays (search/search_choice.h).
bool autoSweeps(const PaperArithmetic&, const Operand&, const Operand&) { return false; }
bool autoSweeps(const ExactArithmetic&, const Operand& s, const Operand& c) { return sweepPays(s, c); }

template <class Arithmetic>
Region clipWith(Operand s, Operand c, Op op, const Options& options, Stats& stats) {
  ExactCounters counters;
  const Arithmetic arithmetic(counters);

  const unsigned threads = options.threads == 0 ? availableThreads() : options.threads;
  auto t = Clock::now();
  const bool sweep = options.search == Search::Auto ? autoSweeps(arithmetic, s, c) : options.search == Search::Sweep;
  Phase1Result crossings =
      sweep ? phase1(std::move(s), std::move(c), SweepSearch{}, arithmetic, stats, threads)
            : phase1(std::move(s), std::move(c), AllPairsSearch{}, arithmetic, stats, threads);
  stats.phase1Seconds = secondsSince(t);

  t = Clock::now();
  VertexGraph graph = buildVertexGraph(crossings);
  locateRingStarts(graph, arithmetic, threads);
  markEntryExit(graph);
  stats.phase2Seconds = secondsSince(t);

  t = Clock::now();
  FlatRings traced;
  borrow<Spare::TracedPoints>(traced.points);
  traceResult(graph, op, traced, threads);
  Region result = cleanedUp(traced, Arithmetic::kLeavesZeroWidthParts, counters);
  stats.phase3Seconds = secondsSince(t);

  giveBack<Spare::SubjectNodes>(crossings.subjectNodes);
  giveBack<Spare::ClipNodes>(crossings.clipNodes);
  giveBack<Spare::TracedPoints>(traced.points);
  stats.filterFailures = counters.filterFailures;
  stats.expansionDecisions = counters.expansionDecisions;
  stats.exactConstructions = counters.exactConstructions;
  return result;
}

}  // namespace

Region clip(const Region& subject, const Region& clip, Op op, const Options& options, Stats* stats) {
  Stats local;
  // Validation copies the input once, straight into phase 1's flat arrays; a refusal names the
  // operand it concerns.
  auto validated = [&](const Region& region, const char* operand) {
    try {
      return Operand(region, options.sanitize);
    } catch (const InvalidInput& e) {
      throw InvalidInput(operand, e.what());
    }
  };
  Operand s = validated(subject, "subject");
  Operand c = validated(clip, "clip");
  local.subjectVertices = s.size();
  local.clipVertices = c.size();
  Region result = options.arithmetic == Arithmetic::Exact
                      ? clipWith<ExactArithmetic>(std::move(s), std::move(c), op, options, local)
                      : clipWith<PaperArithmetic>(std::move(s), std::move(c), op, options, local);
  local.outputRings = result.size();
  local.outputVertices = vertexCount(result);
  if (stats) *stats = local;
  return result;
}

}  // namespace gh
