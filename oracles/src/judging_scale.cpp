#include "judging_scale.h"

#include <algorithm>
#include <cmath>

namespace gh::oracle {

double largestMagnitude(const Region& a, const Region& b, const Region& c) {
  double m = 0;
  for (const Region* r : {&a, &b, &c}) {
    for (const Ring& ring : *r) {
      for (const Point& p : ring) m = std::max({m, std::abs(p.x), std::abs(p.y)});
    }
  }
  return m;
}

int judgingExponent(const Region& a, const Region& b, const Region& c) {
  const double m = largestMagnitude(a, b, c);
  if (m == 0 || !std::isfinite(m) || (m >= 0x1p-256 && m <= 0x1p256)) return 0;
  const int k = -std::ilogb(m);
  auto exact = [k](double v) { return std::ldexp(std::ldexp(v, k), -k) == v; };
  for (const Region* r : {&a, &b, &c}) {
    for (const Ring& ring : *r) {
      for (const Point& p : ring) {
        if (!exact(p.x) || !exact(p.y)) return 0;
      }
    }
  }
  return k;
}

Point scaledBy(Point p, int k) { return {std::ldexp(p.x, k), std::ldexp(p.y, k)}; }

Region scaledBy(const Region& region, int k) {
  Region out = region;
  for (Ring& ring : out) {
    for (Point& p : ring) p = scaledBy(p, k);
  }
  return out;
}

}  // namespace gh::oracle
