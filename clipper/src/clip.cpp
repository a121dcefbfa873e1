// The orchestrator: validate, phase 1 (variant-specific), phase 2, phase 3, clean-up.
#include "ghclip/clip.h"

#include <chrono>
#include <string>

#include "all_pairs_search.h"
#include "cleanup.h"
#include "ghclip/errors.h"
#include "ghclip/measure.h"
#include "ghclip/validate.h"
#include "exact_arithmetic.h"
#include "naive_arithmetic.h"
#include "phase1_intersections.h"
#include "phase3_tracing.h"
#include "search_choice.h"
#include "sweep_search.h"
#include "vertex_graph.h"

namespace gh {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

template <class Arithmetic>
detail::Phase1Result withSearch(detail::Operand subject, detail::Operand clip, bool sweep, Stats& stats) {
  if (sweep) {
    return detail::findIntersections(std::move(subject), std::move(clip), detail::SweepSearch{}, Arithmetic{}, stats);
  }
  return detail::findIntersections(std::move(subject), std::move(clip), detail::AllPairsSearch{}, Arithmetic{}, stats);
}

detail::Phase1Result runPhase1(detail::Operand subject, detail::Operand clip, const Options& o, Stats& stats) {
  bool sweep = o.search == Search::Sweep;
  if (o.search == Search::Default) {
    // naive: the paper's all pairs; sweep: the sweep; exact: whichever pays (search_choice.h).
    sweep = o.variant == Variant::Sweep || (o.variant == Variant::Exact && detail::sweepPays(subject, clip));
  }
  if (o.variant == Variant::Exact) {
    return withSearch<detail::ExactArithmetic>(std::move(subject), std::move(clip), sweep, stats);
  }
  return withSearch<detail::NaiveArithmetic>(std::move(subject), std::move(clip), sweep, stats);
}

}  // namespace

bool isImplemented(Variant) { return true; }

Region clip(const Region& subject, const Region& clip, Op op, const Options& options,
            Stats* stats) {
  Stats local;
  // Validation copies the input once, straight into phase 1's flat arrays.
  detail::Operand s(subject, options.sanitize);
  detail::Operand c(clip, options.sanitize);
  local.subjectVertices = s.size();
  local.clipVertices = c.size();

  auto t = Clock::now();
  const detail::Phase1Result phase1 = runPhase1(std::move(s), std::move(c), options, local);
  local.phase1Seconds = secondsSince(t);

  t = Clock::now();
  detail::VertexGraph graph = detail::buildVertexGraph(phase1);
  detail::markEntryExit(graph);
  local.phase2Seconds = secondsSince(t);

  t = Clock::now();
  Region result = detail::cleanedUp(detail::traceResult(graph, op), options.variant == Variant::Exact);
  local.phase3Seconds = secondsSince(t);

  local.outputRings = result.size();
  local.outputVertices = vertexCount(result);
  if (stats) *stats = local;
  return result;
}

}  // namespace gh
