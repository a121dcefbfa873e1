// The one place where the exact arithmetic constructs new points: the crossing of two segments,
// rounded to doubles with a certificate. Every coordinate is within one ulp of the exact crossing
// (a faithful rounding, so the point also lies in both segments' bounding boxes), whatever the
// magnitudes: subnormal and huge coordinates included.
#pragma once

#include <cstdint>

#include "ghclip/region.h"
#include "predicates/exact_counters.h"

namespace gh::detail {

// The crossing of segments p1p2 and q1q2, which must cross at a single point that is interior to
// both or an endpoint of one (the caller has decided this exactly).
//   1. Interpolated along p (then along q) from its first endpoint in double-double arithmetic
//      (error-free transformations, fma): a forward error bound of about 2^-90 certifies the
//      rounding to double of almost every point. Segments near the origin too small for that
//      (products below 2^-800) are tried again at a power-of-two scale.
//   2. Otherwise the exact rational crossing, rounded to the nearest double (GMP), counted in
//      counters.exactConstructions.
Point constructCrossing(Point p1, Point p2, Point q1, Point q2, ExactCounters& counters);

// Every faithful rounding of the crossing of p1p2 and q1q2 (the same precondition): per coordinate
// the largest double at most the exact value and the smallest at least it, one double when the
// value is one. Exact (GMP), for the few nodes whose rounding the OGC layout must choose
// (layout/node_rounding.h).
struct CrossingRoundings {
  double x0, x1, y0, y1;
};
CrossingRoundings crossingRoundings(Point p1, Point p2, Point q1, Point q2);

// The same through the code compiled for the base instruction set (fma a library call), which
// constructCrossing uses only on processors without fma: so that tests run it everywhere.
Point constructCrossingWithoutFmaInstruction(Point p1, Point p2, Point q1, Point q2, ExactCounters& counters);

}  // namespace gh::detail
