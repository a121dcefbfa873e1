#include "exact_orientation.h"

#include <gmpxx.h>

#include <cmath>

namespace gh::oracle {

int orientation(Point a, Point b, Point p) {
  const double l = (b.x - a.x) * (p.y - a.y), r = (b.y - a.y) * (p.x - a.x);
  const double det = l - r, magnitude = std::abs(l) + std::abs(r);
  if (std::isfinite(magnitude) && magnitude > 0x1p-900 && std::abs(det) > 0x1.0000000000002p-51 * magnitude) {
    return det > 0 ? 1 : -1;
  }
  const mpq_class bx(b.x), by(b.y), ax(a.x), ay(a.y), px(p.x), py(p.y);
  const mpq_class exact = (bx - ax) * (py - ay) - (by - ay) * (px - ax);
  return sgn(exact);
}

}  // namespace gh::oracle
