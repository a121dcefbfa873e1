#include "judging_scale.h"

#include <algorithm>
#include <cmath>

namespace gh::oracle {
namespace {

// The exponent of v's lowest set bit (v = odd * 2^e); v != 0 and finite.
int lowestBitExponent(double v) {
  int e;
  double m = std::frexp(std::abs(v), &e);  // v = m * 2^e, m in [0.5, 1)
  // m has at most 53 significant bits: shift them all above the point, then strip trailing zeros.
  double integer = std::ldexp(m, 53);
  int low = e - 53;
  while (std::fmod(integer, 2.0) == 0) integer /= 2, ++low;
  return low;
}

}  // namespace

int judgingExponent(const std::vector<const Region*>& regions) {
  double m = 0;
  for (const Region* r : regions) {
    for (const Ring& ring : *r) {
      for (const Point& p : ring) m = std::max({m, std::abs(p.x), std::abs(p.y)});
    }
  }
  if (m == 0 || !std::isfinite(m) || (m >= 0x1p-256 && m <= 0x1p256)) return 0;
  const int target = -std::ilogb(m);
  if (target > 0) return target;  // scaling up is exact: M * 2^k < 2 keeps everything finite
  // Scaling down loses the low bits of small coordinates: stop where the lowest one would.
  int lowest = -2200;  // the smallest k that keeps every coordinate exact
  for (const Region* r : regions) {
    for (const Ring& ring : *r) {
      for (const Point& p : ring) {
        for (double v : {p.x, p.y}) {
          if (v != 0) lowest = std::max(lowest, -1074 - lowestBitExponent(v));
        }
      }
    }
  }
  return std::max(target, lowest);
}

int judgingExponent(const Region& a, const Region& b, const Region& c) { return judgingExponent({&a, &b, &c}); }

Point scaledBy(Point p, int k) { return {std::ldexp(p.x, k), std::ldexp(p.y, k)}; }

Region scaledBy(const Region& region, int k) {
  Region out = region;
  for (Ring& ring : out) {
    for (Point& p : ring) p = scaledBy(p, k);
  }
  return out;
}

}  // namespace gh::oracle
