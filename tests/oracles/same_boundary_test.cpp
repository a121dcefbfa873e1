#include "ghoracle/same_boundary.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace gh::oracle {
namespace {

const Ring kSquare{{0, 0}, {2, 0}, {2, 2}, {0, 2}};
const Ring kHole{{0.5, 0.5}, {1.5, 0.5}, {1.5, 1.5}, {0.5, 1.5}};

Ring reversed(Ring r) { return Ring(r.rbegin(), r.rend()); }
Ring rotated(Ring r, std::size_t k) {
  std::rotate(r.begin(), r.begin() + static_cast<std::ptrdiff_t>(k), r.end());
  return r;
}

TEST(SameBoundary, ReorderedReorientedAndRotatedRingsAreTheSame) {
  EXPECT_TRUE(sameBoundaryModTwo({kSquare, kHole}, {reversed(kHole), rotated(kSquare, 2)}));
  EXPECT_TRUE(sameBoundaryModTwo({}, {}));
}

TEST(SameBoundary, EdgesTwiceCancelSoARingCutAtATouchIsTheSame) {
  // Two triangles touching at (1, 1) as one ring through it twice, and as two rings.
  const Ring bow{{0, 0}, {1, 1}, {2, 0}, {2, 2}, {1, 1}, {0, 2}};
  EXPECT_TRUE(sameBoundaryModTwo({bow}, {{{0, 0}, {1, 1}, {0, 2}}, {{1, 1}, {2, 0}, {2, 2}}}));
  // A square drawn twice is no boundary at all.
  EXPECT_TRUE(sameBoundaryModTwo({kSquare, reversed(kSquare)}, {}));
}

TEST(SameBoundary, AMissingRingAMovedVertexOrAnEdgeCutElsewhereDiffer) {
  EXPECT_FALSE(sameBoundaryModTwo({kSquare, kHole}, {kSquare}));
  Ring moved = kSquare;
  moved[2].x = std::nextafter(2.0, 3.0);
  EXPECT_FALSE(sameBoundaryModTwo({kSquare}, {moved}));
  // The same interior with an edge cut at its midpoint: not proved the same (a judge decides).
  EXPECT_FALSE(sameBoundaryModTwo({kSquare}, {{{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}}}));
}

}  // namespace
}  // namespace gh::oracle
