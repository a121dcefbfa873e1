// How much two correct double answers' areas may differ: for checks that compare areas (the
// metamorphic properties, the differential fuzz target), not for the exact oracle, whose verdict
// is topological (exact_oracle.h).
//
// A correct answer differs from the exact one only in its constructed vertices (those that are not
// vertices of S or C). Each is off its exact crossing by at most `ulps` ulps of its *own*
// coordinates, a displacement |d| <= ulps * ulp(max(|x|, |y|)) * sqrt 2; moving a vertex v by d
// changes the area by at most the two triangles its edges sweep, |d| * (|e_prev| + |e_next|) / 2.
// The allowance is the sum of that over the constructed vertices of R. Input vertices get
// nothing, and a vertex near the origin gets an allowance of its own magnitude, however large
// the rest of the problem.
#pragma once

#include <limits>

#include "ghclip/region.h"

namespace gh::oracle {

// The exact variant rounds each crossing faithfully (1 ulp); the paper's arithmetic computes it
// in a few roundings. Area comparisons allow this many.
inline constexpr int kComparisonUlps = 4;

// ulpFloor: the smallest ulp, denorm_min at the original scale; a caller measuring a copy scaled
// by 2^k (judging_scale.h) passes denorm_min * 2^k, the original's subnormal spacing there.
double roundingAllowance(const Region& subject, const Region& clip, const Region& result,
                         int ulps = kComparisonUlps,
                         double ulpFloor = std::numeric_limits<double>::denorm_min());

}  // namespace gh::oracle
