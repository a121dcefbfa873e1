// Exact signs of the polynomial predicates everything else is built from: a floating-point filter
// (approx.h) with an exact GMP fallback, counted.
#pragma once

#include <cstdint>

#include "ghclip/region.h"

namespace gh::detail {

enum class Sign { Negative = -1, Zero = 0, Positive = 1 };

inline Sign toSign(int s) { return s > 0 ? Sign::Positive : s < 0 ? Sign::Negative : Sign::Zero; }

// Sign of a - b for doubles: exact (a comparison, no subtraction).
inline int signOfDifference(double a, double b) { return (a > b) - (a < b); }

// Sign of (b - a) x (c - a): Positive when a, b, c turn counter-clockwise.
Sign orientation(Point a, Point b, Point c);

// Sign of (b - a) x (d - c), the cross product of two edge directions.
Sign crossSign(Point a, Point b, Point c, Point d);

// Exact fallbacks taken by this thread so far (the filter could not decide).
std::uint64_t& exactFallbacks();

}  // namespace gh::detail
