// The paper's perturbation (paper_perturbation.h), wrapped around phase 1: degenerate vertices are
// moved by 2^-42 of the largest coordinate, the clip's first, and phase 1 runs again; where no
// perturbation helps, ClipFailure after kMaxPerturbationRounds rounds.
#include <gtest/gtest.h>

#include <cmath>

#include "ghclip/errors.h"
#include "ghwork/generators.h"
#include "paper_perturbation.h"
#include "search/all_pairs_search.h"

namespace gh::detail {
namespace {

Ring rect(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

TEST(PaperPerturbation, MovesTheFlaggedClipVerticesByTheScaledVector) {
  Operand s({rect(0, 0, 4, 4)}), c({rect(4, 0, 8, 4)});
  Degeneracies d;
  d.subject = {1, 2};
  d.clip = {0, 3};
  EXPECT_EQ(perturb(s, c, d, 0), 2u);
  EXPECT_EQ(s.vertices[1].x, 4);  // the subject is left alone when the clip has flagged vertices
  const double length = kPerturbationScale * 8;
  const double dx = c.vertices[0].x - 4, dy = c.vertices[0].y - 0;
  EXPECT_NEAR(std::hypot(dx, dy), length, 1e-3 * length);
  EXPECT_EQ(c.vertices[3].x - 4, dx);
  EXPECT_EQ(c.vertices[1], (Point{8, 0}));
}

TEST(PaperPerturbation, ResolvesASharedEdge) {
  ExactCounters counters;
  Stats stats;
  const Phase1Result r = findIntersectionsPerturbed(Operand({rect(0, 0, 4, 4)}), Operand({rect(4, 1, 8, 3)}),
                                                    AllPairsSearch{}, PaperArithmetic(counters), stats);
  EXPECT_GT(stats.perturbationRounds, 0u);
  EXPECT_GT(stats.perturbations, 0u);
  EXPECT_EQ(r.clipNodes.size(), r.subjectNodes.size());  // ordered: the degeneracies are gone
  // Phase 1 alone reports them and leaves the crossings unordered.
  Degeneracies d;
  Stats once;
  const Phase1Result raw = findIntersections(Operand({rect(0, 0, 4, 4)}), Operand({rect(4, 1, 8, 3)}),
                                             AllPairsSearch{}, PaperArithmetic(counters), once, &d);
  EXPECT_FALSE(d.empty());
  EXPECT_TRUE(raw.clipNodes.empty());
}

// Near 1e-300 every product underflows: window-edge coordinates are 0 however far the
// perturbation (2^-42 of 1e-300) moves a vertex, and the paper gives up.
TEST(PaperPerturbation, GivesUpWhereNoPerturbationHelps) {
  const work::Workload w = work::generate("grid+tiny", 20, 1);
  ExactCounters counters;
  Stats stats;
  EXPECT_THROW(findIntersectionsPerturbed(Operand(w.subject, false), Operand(w.clip, false), AllPairsSearch{},
                                          PaperArithmetic(counters), stats),
               ClipFailure);
  EXPECT_EQ(stats.perturbationRounds, static_cast<std::uint64_t>(kMaxPerturbationRounds - 1));
}

}  // namespace
}  // namespace gh::detail
