// How much error area a correct double-precision answer may have.
//
// A correct result differs from the exact answer only in its constructed points: every vertex of
// R that is not a vertex of S or C is an intersection point rounded to doubles. A correctly
// rounded point is within half an ulp per coordinate; we allow kConstructionUlps ulps of the
// largest coordinate M per coordinate, i.e. a displacement |d| <= kConstructionUlps * ulp(M) * sqrt 2.
// Moving a vertex v by d changes the region by at most the two triangles its edges sweep:
// |d| * (|e_prev| + |e_next|) / 2. The tolerance is the sum of that bound over the constructed
// vertices of R (and, in the exact oracle, of the exact answer too: rounding may flatten a ring of
// constructed points to nothing, which then has no vertex in R). Vertices equal to input
// vertices get nothing, so a moved input vertex, a dropped
// ring or a confused operation is never within tolerance unless its area is below rounding.
#pragma once

#include "ghclip/region.h"

namespace gh::oracle {

inline constexpr double kConstructionUlps = 4;

double roundingTolerance(const Region& subject, const Region& clip, const Region& result);

// The parts: the allowed displacement of one constructed point, kConstructionUlps * ulp(M) * sqrt 2,
// and the tolerance for a given displacement (judges working on a scaled copy of the problem
// scale the original's displacement with it).
double constructionDisplacement(const Region& subject, const Region& clip, const Region& result);
double roundingTolerance(const Region& subject, const Region& clip, const Region& result, double displacement);

}  // namespace gh::oracle
