// The orchestrator: validate, phase 1, phase 2, phase 3, clean-up (clipper/src/README.md maps the
// paper's sections to the files). The arithmetic policy is chosen once here; the paper's
// perturbation wraps phase 1 for the paper arithmetic only. Clipping keeps phases 1 and 2 for
// phase 3 of several operations; clip() is a Clipping asked once.
#include "ghclip/clip.h"

#include <chrono>
#include <optional>
#include <type_traits>

#include "arithmetic/exact_arithmetic.h"
#include "arithmetic/paper_arithmetic.h"
#include "cleanup.h"
#include "layout/traced_lines.h"
#include "ghclip/clipping.h"
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

}  // namespace

// Phases 1 and 2, kept for phase 3 of every operation asked. The graph refers to `crossings`
// (its operands and lists), so a Prepared never moves: it lives behind Clipping's pointer.
struct Clipping::Prepared {
  std::optional<Phase1Result> crossings;  // set once phase 1 has run
  VertexGraph graph;
  bool dissolve = false;   // the arithmetic's clean-up dissolves zero-width seams
  bool exact = false;      // the exact arithmetic: the traced edges lie on the operands' edges
  ExactCounters counters;  // phases 1 and 2's; each operation adds its clean-up's to a copy
  Stats stats;             // phases 1 and 2's
  unsigned threads = 1;

  ~Prepared() {
    if (!crossings) return;
    giveBack<Spare::SubjectNodes>(crossings->subjectNodes);
    giveBack<Spare::ClipNodes>(crossings->clipNodes);
  }

  template <class Arithmetic>
  void run(Operand s, Operand c, const Options& options) {
    const Arithmetic arithmetic(counters);
    threads = options.threads == 0 ? availableThreads() : options.threads;
    auto t = Clock::now();
    const bool sweep = options.search == Search::Auto ? autoSweeps(arithmetic, s, c) : options.search == Search::Sweep;
    crossings.emplace(sweep ? phase1(std::move(s), std::move(c), SweepSearch{}, arithmetic, stats, threads)
                            : phase1(std::move(s), std::move(c), AllPairsSearch{}, arithmetic, stats, threads));
    stats.phase1Seconds = secondsSince(t);

    t = Clock::now();
    graph = buildVertexGraph(*crossings);
    locateRingStarts(graph, arithmetic, threads);
    markEntryExit(graph);
    stats.phase2Seconds = secondsSince(t);
    dissolve = Arithmetic::kLeavesZeroWidthParts;
    exact = std::is_same_v<Arithmetic, ExactArithmetic>;
  }
};

Clipping::Clipping(const Region& subject, const Region& clip, const Options& options)
    : prepared_(std::make_unique<Prepared>()) {
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
  Prepared& p = *prepared_;
  p.stats.subjectVertices = s.size();
  p.stats.clipVertices = c.size();
  if (options.arithmetic == Arithmetic::Exact) {
    p.run<ExactArithmetic>(std::move(s), std::move(c), options);
  } else {
    p.run<PaperArithmetic>(std::move(s), std::move(c), options);
  }
}

Clipping::~Clipping() = default;
Clipping::Clipping(Clipping&&) noexcept = default;
Clipping& Clipping::operator=(Clipping&&) noexcept = default;

Region Clipping::result(Op op, Stats* stats) {
  Prepared& p = *prepared_;
  Stats local = p.stats;
  ExactCounters counters = p.counters;
  const auto t = Clock::now();
  FlatRings traced;
  borrow<Spare::TracedPoints>(traced.points);
  traceResult(p.graph, op, traced, p.threads);
  Region result = cleanedUp(traced, p.dissolve, counters);
  local.phase3Seconds = secondsSince(t);
  giveBack<Spare::TracedPoints>(traced.points);
  local.filterFailures = counters.filterFailures;
  local.expansionDecisions = counters.expansionDecisions;
  local.exactConstructions = counters.exactConstructions;
  local.outputRings = result.size();
  local.outputVertices = vertexCount(result);
  if (stats) *stats = local;
  return result;
}

std::vector<PolygonWithHoles> Clipping::polygons(Op op, Stats* stats, LayoutStats* layout) {
  Prepared& p = *prepared_;
  // The paper arithmetic's edges lie on perturbed copies of the operands' edges, and its points
  // are not faithful roundings: its rings are laid out as rings that know nothing more.
  if (!p.exact) return ogcLayout(result(op, stats), layout);
  Stats local = p.stats;
  const auto t = Clock::now();
  FlatRings traced;
  std::vector<std::uint32_t> lines;
  traceResult(p.graph, op, traced, p.threads, &lines);
  ExactCounters counters = p.counters;
  const LinedRings rings = tracedLines(traced, lines, p.crossings->subject, p.crossings->clip, counters);
  local.phase3Seconds = secondsSince(t);
  local.filterFailures = counters.filterFailures;
  local.expansionDecisions = counters.expansionDecisions;
  local.exactConstructions = counters.exactConstructions;
  std::vector<PolygonWithHoles> polygons = ogcLayout(rings, layout);
  local.outputRings = 0, local.outputVertices = 0;
  for (const PolygonWithHoles& polygon : polygons) {
    local.outputRings += 1 + polygon.holes.size();
    local.outputVertices += polygon.shell.size();
    for (const Ring& hole : polygon.holes) local.outputVertices += hole.size();
  }
  if (stats) *stats = local;
  return polygons;
}

Region clip(const Region& subject, const Region& clip, Op op, const Options& options, Stats* stats) {
  return Clipping(subject, clip, options).result(op, stats);
}

std::vector<PolygonWithHoles> clipPolygons(const Region& subject, const Region& clip, Op op, const Options& options,
                                           Stats* stats, LayoutStats* layout) {
  return Clipping(subject, clip, options).polygons(op, stats, layout);
}

}  // namespace gh
