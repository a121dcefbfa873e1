// Judging at a comfortable scale.
//
// Multiplying every coordinate by 2^k is exact in binary floating point while nothing leaves the
// normal range, and it multiplies every area by 4^k: a verdict on the scaled problem is the
// verdict on the original. The judges bring problems whose largest coordinate M lies outside
// [2^-256, 2^256] to M ~ 1 first, so that their floating-point filters, tolerances and sampling
// distances neither underflow (subnormal inputs) nor overflow (1e300 inputs).
#pragma once

#include "ghclip/region.h"

namespace gh::oracle {

// M: the largest |coordinate| of the three regions (0 when they are empty).
double largestMagnitude(const Region& a, const Region& b, const Region& c);

// k such that 2^k * M lies in [1, 2); 0 when M is already moderate or when some coordinate would
// not survive the scaling exactly (the problem then spans more than the double range).
int judgingExponent(const Region& a, const Region& b, const Region& c);

// Every coordinate times 2^k.
Region scaledBy(const Region& region, int k);
Point scaledBy(Point p, int k);

}  // namespace gh::oracle
