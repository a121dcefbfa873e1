// The judges' orientation of a rational point against a line through two doubles, exactly: the
// exact oracle's rounding zones have corners that are doubles, and the arrangement's vertices
// that are crossings are rationals. Private to the oracles (it takes GMP's rationals).
#pragma once

#include <gmp.h>

#include "ghclip/region.h"

namespace gh::oracle {

// Sign of (b - a) x (p - a) for p = (px, py), -1, 0 or 1, exactly, in integers: a and b over
// their smallest power of two, p over its two denominators (no common factors divided out, as
// rationals do after every operation). a and b finite.
int orientationOfRational(Point a, Point b, const mpq_t px, const mpq_t py);

}  // namespace gh::oracle
