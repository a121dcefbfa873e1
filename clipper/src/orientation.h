// Exact orientation of three double points: the one predicate the shared code (output clean-up)
// needs. A floating-point filter with Shewchuk's error bound, and an exact GMP fallback when the
// filter cannot decide or the products may have under- or overflowed.
#pragma once

#include "ghclip/region.h"

namespace gh::detail {

enum class Sign { Negative = -1, Zero = 0, Positive = 1 };

// Sign of (b - a) x (c - a): Positive when a, b, c turn counter-clockwise.
Sign orientation(Point a, Point b, Point c);

}  // namespace gh::detail
