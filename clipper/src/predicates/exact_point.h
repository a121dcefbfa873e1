// Points as exact rationals, for the one place that must reason about the plane between doubles:
// the OGC layout's snap rounding (layout/snap_rounding.h). GMP's C++ numbers: slow, and used only
// where every faster way has given up.
#pragma once

#include <gmpxx.h>

#include "ghclip/region.h"

namespace gh::detail {

struct ExactPoint {
  mpq_class x, y;
};

inline ExactPoint exactPoint(Point p) { return {mpq_class(p.x), mpq_class(p.y)}; }

// The crossing of the lines through p1, p2 and q1, q2 (not parallel), exactly.
ExactPoint exactCrossingPoint(Point p1, Point p2, Point q1, Point q2);

// The double nearest to v (ties to the one of even significand, as the hardware rounds), exactly.
double nearestDouble(const mpq_class& v);

}  // namespace gh::detail
