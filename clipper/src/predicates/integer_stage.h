// The last, exact stage of the clipper's sign predicates, in GMP integers. Every double is an
// integer times a power of two, so over the smallest power among a predicate's coordinates all of
// them are integers; the polynomials below are homogeneous in differences of coordinates, so
// their signs are unchanged by that (positive) scaling. The integers are kept per thread and grow
// to the largest problem seen, so that a call allocates nothing once warm: the rationals (GMP
// mpq) that this stage replaced allocated and reduced by a gcd at every step, and under the fuzz
// build's AddressSanitizer their allocations were a tenth of fuzz_clip_exact's time (inputs with
// a subnormal coordinate beside normal ones reach this stage, by design: difference_products.h).
#pragma once

#include "ghclip/region.h"
#include "predicates/sign.h"

namespace gh::detail {

// The sign of (b - a) x (d - c), exactly. Finite coordinates.
Sign integerCrossSign(Point a, Point b, Point c, Point d);

// The sign of F0 = A_M D_N - A_N D_M (sos_predicates.cpp), exactly, with
//   A_M = cross(m2 - m1, a1 - m1), A_N = cross(n2 - n1, a1 - n1),
//   D_M = cross(m2 - m1, a1 - a2), D_N = cross(n2 - n1, a1 - a2). Finite coordinates.
Sign integerOrderTerm(Point a1, Point a2, Point m1, Point m2, Point n1, Point n2);

}  // namespace gh::detail
