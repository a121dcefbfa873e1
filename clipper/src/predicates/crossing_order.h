// Where two lines cross a third, in which order: the predicate that orders crossings along an
// edge (phase 1 of the exact arithmetic, without and with its perturbation) and places the OGC
// layout's nodes along the lines of the answer's edges (layout/exact_noding.h).
//
// Along line A (a1 -> a2), its crossing with line M (m1 m2) has the parameter t_M = A_M / D_M,
//   A_M = cross(m2 - m1, a1 - m1),  D_M = cross(m2 - m1, a1 - a2),
// and likewise t_N, so (t_M - t_N) D_M D_N = F0 = A_M D_N - A_N D_M, a polynomial of degree 4 in
// differences of the coordinates.
#pragma once

#include "ghclip/region.h"
#include "predicates/exact_counters.h"
#include "predicates/sign.h"

namespace gh::detail {

// The sign of F0, exactly: the filter, then F0 exactly in doubles, then GMP (filtered_predicate.h),
// each fallback counted. Any finite coordinates (the points are scaled towards 1 first).
Sign crossingOrderTerm(Point a1, Point a2, Point m1, Point m2, Point n1, Point n2, ExactCounters& counters);

// The order along line A, from a1 towards a2, of its crossings with lines M and N, neither of
// them parallel to A: -1 when M's comes first, +1 when N's does, 0 when they are one point.
// Exact; nothing is perturbed.
int orderOfCrossings(Point a1, Point a2, Point m1, Point m2, Point n1, Point n2, ExactCounters& counters);

}  // namespace gh::detail
