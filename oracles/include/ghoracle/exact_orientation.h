// The judges' own orientation predicate, exact: the oracles decide with it rather than with the
// clipper's, so that a bug in the clipper's predicates cannot hide itself.
#pragma once

#include "ghclip/region.h"

namespace gh::oracle {

// Sign of (b - a) x (p - a) as -1, 0 or 1, exactly: Shewchuk's filter in doubles; where it
// cannot decide, a comparison of the two products when the differences and products are exact
// doubles (collinear grid points), else Shewchuk's exact expansions of doubles where every
// coordinate is 0 or of magnitude in [2^-480, 2^500], else GMP integers. Finite coordinates only.
int orientation(Point a, Point b, Point p);

// Whether |(b - a) x (p - a)| <= bound (a finite bound >= 0), exactly, by the same stages beyond
// the filter: p within bound / |b - a| of the line ab. The caller filters in doubles first.
bool crossAtMost(Point a, Point b, Point p, double bound);

}  // namespace gh::oracle
