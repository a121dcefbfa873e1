#include "ghoracle/invariants.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "ghclip/measure.h"
#include "ghoracle/tolerance.h"

namespace gh::oracle {

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
  const double a = evenOddArea(subject), b = evenOddArea(clip), r = evenOddArea(result);
  // Slack: the rounding tolerance plus a relative 1e-9 of the areas involved for the
  // floating-point area measurement itself.
  const double slack = roundingTolerance(subject, clip, result) + 1e-9 * (a + b + r);
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
  return out;
}

}  // namespace gh::oracle
