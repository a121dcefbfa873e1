// The one place where the exact variant constructs new points: the crossing of two segments,
// rounded to doubles with a certificate. Every coordinate is within one ulp of the exact crossing
// (a faithful rounding, so the point also lies in both segments' bounding boxes), whatever the
// magnitudes: subnormal and huge coordinates included.
#pragma once

#include <cstdint>

#include "ghclip/region.h"

namespace gh::detail {

// The crossing of segments p1p2 and q1q2, which must cross at a single point that is interior to
// both or an endpoint of one (the caller has decided this exactly).
//   1. Interpolated along p (then along q) from its first endpoint in long double (64-bit
//      significand, 15-bit exponent where the platform has it): no product of doubles under- or
//      overflows there, and a forward error bound certifies the rounding to double of most points.
//   2. Otherwise the exact rational crossing, rounded to the nearest double (GMP).
Point constructCrossing(Point p1, Point p2, Point q1, Point q2);

// Crossings this thread constructed with exact arithmetic so far (step 2 above).
std::uint64_t& exactConstructions();

}  // namespace gh::detail
