// Judging at a comfortable scale.
//
// Multiplying every coordinate by 2^k is exact in binary floating point while nothing leaves the
// double range or loses bits below the smallest subnormal, and it multiplies every area by 4^k:
// a verdict on the scaled problem is the verdict on the original. The judges bring problems
// whose largest coordinate M lies outside [2^-256, 2^256] towards M ~ 1 first, so that their
// floating-point filters, tolerances and sampling distances neither underflow (subnormal inputs)
// nor overflow (1e300 inputs). A problem that spans more than the double range allows (1e300
// next to 1e-300) is scaled only as far as every coordinate stays exact.
#pragma once

#include <vector>

#include "ghclip/region.h"

namespace gh::oracle {

// k such that every coordinate times 2^k is exact, 2^k * M as close to [1, 2) as that allows,
// where M is the largest |coordinate| of the regions; 0 when M is already moderate (or 0).
int judgingExponent(const Region& a, const Region& b, const Region& c);
int judgingExponent(const std::vector<const Region*>& regions);

// Every coordinate times 2^k.
Region scaledBy(const Region& region, int k);
Point scaledBy(Point p, int k);

}  // namespace gh::oracle
