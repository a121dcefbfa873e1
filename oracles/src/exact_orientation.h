// The judges' own orientation predicate, exact: the oracles decide with it rather than with the
// clipper's, so that a bug in the clipper's predicates cannot hide itself.
#pragma once

#include "ghclip/region.h"

namespace gh::oracle {

// Sign of (b - a) x (p - a) as -1, 0 or 1, exactly: Shewchuk's filter in doubles, GMP when it
// cannot decide (or when a difference overflows or a product underflows).
int orientation(Point a, Point b, Point p);

}  // namespace gh::oracle
