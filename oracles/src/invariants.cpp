#include "ghoracle/invariants.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "ghclip/measure.h"
#include "ghoracle/tolerance.h"
#include "judging_scale.h"

namespace gh::oracle {
namespace {

// A bound on the error of evenOddArea over these regions: every edge contributes to at most each
// slab of the x-extent W, with heights up to the largest |y| computed in a few roundings, and
// every operation may lose a denormal's worth below the normal range.
double measurementError(const Region& a, const Region& b, const Region& c) {
  double minX = 0, maxX = 0, maxY = 0, edges = 0;
  bool any = false;
  for (const Region* r : {&a, &b, &c}) {
    for (const Ring& ring : *r) {
      edges += static_cast<double>(ring.size());
      for (const Point& p : ring) {
        if (!any) minX = maxX = p.x, any = true;
        minX = std::min(minX, p.x), maxX = std::max(maxX, p.x), maxY = std::max(maxY, std::abs(p.y));
      }
    }
  }
  return 16 * 0x1p-53 * edges * (maxX - minX) * maxY + 16 * edges * edges * std::numeric_limits<double>::denorm_min();
}

// The area inequalities of op, on a problem at a comfortable scale.
void areaViolations(const Region& S, const Region& C, Op op, const Region& R, int k, std::vector<std::string>& out) {
  const double a = evenOddArea(S), b = evenOddArea(C), r = evenOddArea(R);
  // Slack: the rounding allowance of R's constructed vertices (tolerance.h), the measurement's own error
  // (each slab trapezoid is measured with a few roundings of heights up to the largest |y|, and
  // results below the normal range lose absolute precision), and a relative 1e-9 of the areas.
  const double slack = roundingAllowance(S, C, R, kComparisonUlps, std::ldexp(std::numeric_limits<double>::denorm_min(), std::max(k, 0))) + measurementError(S, C, R) + 1e-9 * (a + b + r);
  auto require = [&](bool ok, const char* what) {
    if (ok) return;
    std::ostringstream s;
    s.precision(17);
    s << name(op) << ": " << what << " (area S " << a << ", C " << b << ", result " << r << ")";
    out.push_back(s.str());
  };
  switch (op) {
    case Op::Intersection:
      require(r <= std::min(a, b) + slack, "intersection larger than an operand");
      break;
    case Op::Union:
      require(r + slack >= std::max(a, b), "union smaller than an operand");
      require(r <= a + b + slack, "union larger than the sum of the operands");
      break;
    case Op::Difference:
      require(r <= a + slack, "difference larger than the subject");
      require(r + slack >= a - b, "difference smaller than area(S) - area(C)");
      break;
    case Op::ReverseDifference:
      require(r <= b + slack, "reverse difference larger than the clip");
      require(r + slack >= b - a, "reverse difference smaller than area(C) - area(S)");
      break;
    case Op::Xor:
      require(r <= a + b + slack, "xor larger than the sum of the operands");
      require(r + slack >= std::abs(a - b), "xor smaller than |area(S) - area(C)|");
      break;
  }
}

}  // namespace

std::vector<std::string> invariantViolations(const Region& subject, const Region& clip, Op op,
                                             const Region& result) {
  std::vector<std::string> out;
  for (std::size_t r = 0; r < result.size(); ++r) {
    const Ring& ring = result[r];
    for (std::size_t i = 0; i < ring.size(); ++i) {
      if (!std::isfinite(ring[i].x) || !std::isfinite(ring[i].y)) {
        out.push_back("ring " + std::to_string(r + 1) + " has a non-finite coordinate");
        return out;  // areas are meaningless now
      }
      if (ring[i] == ring[(i + 1) % ring.size()]) {
        out.push_back("ring " + std::to_string(r + 1) + " has a zero-length edge");
      }
    }
  }
  // Areas are measured on a copy at a comfortable scale (judging_scale.h): at subnormal or
  // 1e300 magnitudes the floating-point measurement itself would under- or overflow.
  const int k = judgingExponent(subject, clip, result);
  if (k == 0) {
    areaViolations(subject, clip, op, result, 0, out);
  } else {
    areaViolations(scaledBy(subject, k), scaledBy(clip, k), op, scaledBy(result, k), k, out);
  }
  return out;
}

}  // namespace gh::oracle
