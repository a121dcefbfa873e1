// The candidate searches (clipper/src/search/): the sweep reports every pair whose boxes overlap,
// so with the same arithmetic policy phase 1 finds the same crossings (same edges, same alpha
// values, same points, same order along every edge) and the same perturbations as with all pairs:
// bit for bit, on every workload, for both arithmetics. Checked by RapidCheck over workload
// names, sizes and seeds (alpha values are not compared: phase 1 keeps only the order they give).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cstring>

#include "arithmetic/exact_arithmetic.h"
#include "arithmetic/paper_arithmetic.h"
#include "ghclip/clip.h"
#include "ghclip/errors.h"
#include "ghclip/validate.h"
#include "ghwork/generators.h"
#include "paper_perturbation.h"
#include "phase1_intersections.h"
#include "search/all_pairs_search.h"
#include "search/sweep_search.h"

namespace gh {
namespace {

using namespace detail;

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Compares the two phase-1 results; returns "" when identical.
std::string difference(const Phase1Result& a, const Phase1Result& b) {
  if (a.crossingCount() != b.crossingCount()) return "crossing counts differ";
  for (std::size_t k = 0; k < a.crossingCount(); ++k) {
    if (a.subjectEdge(k) != b.subjectEdge(k) || a.clipEdge(k) != b.clipEdge(k) || !sameBits(a.point(k).x, b.point(k).x) ||
        !sameBits(a.point(k).y, b.point(k).y)) {
      return "crossing " + std::to_string(k) + " along the subject differs";
    }
    if (a.clipOrder(k) != b.clipOrder(k)) return "order along the clip differs";
  }
  for (std::size_t v = 0; v < a.subject.size(); ++v) {
    if (!sameBits(a.subject.vertices[v].x, b.subject.vertices[v].x) ||
        !sameBits(a.subject.vertices[v].y, b.subject.vertices[v].y)) {
      return "perturbed subject vertices differ";
    }
  }
  for (std::size_t v = 0; v < a.clip.size(); ++v) {
    if (!sameBits(a.clip.vertices[v].x, b.clip.vertices[v].x) || !sameBits(a.clip.vertices[v].y, b.clip.vertices[v].y)) {
      return "perturbed clip vertices differ";
    }
  }
  return "";
}

RC_GTEST_PROP(SweepEquivalence, SameCrossingsAsAllPairsOnEveryWorkload, ()) {
  std::vector<std::string> names = work::workloadNames();
  for (const auto& suffix : work::variantSuffixes()) names.push_back("grid+" + suffix);
  const std::string name = *rc::gen::elementOf(names);
  const auto n = static_cast<std::size_t>(*rc::gen::inRange(3, 60));
  const auto seed = static_cast<std::uint64_t>(*rc::gen::inRange(0, 100000));
  RC_TAG(name);
  const work::Workload w = work::generate(name, n, seed);
  const Region s = normalized(w.subject, OnBadRing::Drop), c = normalized(w.clip, OnBadRing::Drop);
  Stats sa, sb;
  std::string failA, failB;
  Phase1Result a{Operand({}), Operand({}), {}, {}}, b = a;
  ExactCounters counters;
  const PaperArithmetic paper(counters);
  try {
    a = findIntersectionsPerturbed(Operand(s), Operand(c), AllPairsSearch{}, paper, sa);
  } catch (const ClipFailure& e) {
    failA = e.what();
  }
  try {
    b = findIntersectionsPerturbed(Operand(s), Operand(c), SweepSearch{}, paper, sb);
  } catch (const ClipFailure& e) {
    failB = e.what();
  }
  RC_ASSERT(failA == failB);
  RC_ASSERT(sa.perturbations == sb.perturbations);
  RC_ASSERT(sa.perturbationRounds == sb.perturbationRounds);
  RC_ASSERT(sb.candidatePairs <= sa.candidatePairs);
  RC_ASSERT(difference(a, b) == "");
  // The exact arithmetic: no perturbation, the same crossings either way.
  const ExactArithmetic exact(counters);
  Stats ea, eb;
  RC_ASSERT(difference(findIntersections(Operand(s), Operand(c), AllPairsSearch{}, exact, ea),
                       findIntersections(Operand(s), Operand(c), SweepSearch{}, exact, eb)) == "");
}

// Large realistic inputs, where the sweep's chains matter: same crossings, far fewer pairs.
TEST(SweepEquivalence, RealisticInputsOfTenThousandVertices) {
  for (const char* name : {"circles", "coastline"}) {
    const work::Workload w = work::generate(name, 10000, 7);
    Stats sa, sb;
    ExactCounters counters;
    const PaperArithmetic paper(counters);
    const auto a = findIntersectionsPerturbed(Operand(w.subject), Operand(w.clip), AllPairsSearch{}, paper, sa);
    const auto b = findIntersectionsPerturbed(Operand(w.subject), Operand(w.clip), SweepSearch{}, paper, sb);
    EXPECT_EQ(difference(a, b), "") << name;
    EXPECT_GT(a.crossingCount(), 0u) << name;
    EXPECT_LT(sb.candidatePairs * 100, sa.candidatePairs) << name;
  }
}

}  // namespace
}  // namespace gh
