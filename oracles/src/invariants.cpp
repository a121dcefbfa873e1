#include "ghoracle/invariants.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

#include "ghclip/measure.h"
#include "ghoracle/tolerance.h"
#include "ghoracle/exact_orientation.h"
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

// Whether every vertex of ring lies on one line, decided exactly.
bool allOnOneLine(const Ring& ring) {
  const auto distinct = std::find_if(ring.begin(), ring.end(), [&](const Point& p) { return p != ring.front(); });
  if (distinct == ring.end()) return true;
  return std::all_of(ring.begin(), ring.end(), [&](const Point& p) { return orientation(ring.front(), *distinct, p) == 0; });
}

// The first vertex b where the ring turns straight back (a -> b -> c on one line, c behind b), if
// any; decided exactly, along an axis on which a and b differ. Zero-length edges are reported
// on their own and skipped here.
std::optional<std::size_t> spikeTip(const Ring& ring) {
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point a = ring[(i + n - 1) % n], b = ring[i], c = ring[(i + 1) % n];
    if (a == b || b == c || orientation(a, b, c) != 0) continue;
    const bool backwards = a.x != b.x ? (b.x > a.x) != (c.x > b.x) : (b.y > a.y) != (c.y > b.y);
    if (backwards) return i;
  }
  return std::nullopt;
}

// The area inequalities of op, on a problem at a comfortable scale (a and b: the areas of S and C).
void areaViolations(const Region& S, const Region& C, double a, double b, Op op, const Region& R, int k,
                    std::vector<std::string>& out) {
  const double r = evenOddArea(R);
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

// The checks on the answer's rings alone; false when a coordinate is not finite (then no others
// are made, and areas would be meaningless).
bool ringViolations(const Region& result, std::vector<std::string>& out) {
  for (std::size_t r = 0; r < result.size(); ++r) {
    const Ring& ring = result[r];
    for (std::size_t i = 0; i < ring.size(); ++i) {
      if (!std::isfinite(ring[i].x) || !std::isfinite(ring[i].y)) {
        out.push_back("ring " + std::to_string(r + 1) + " has a non-finite coordinate");
        return false;
      }
      if (ring[i] == ring[(i + 1) % ring.size()]) {
        out.push_back("ring " + std::to_string(r + 1) + " has a zero-length edge");
      }
    }
    // A ring needs three vertices off one line to enclose anything; one that does not is debris
    // the clean-up should have removed (and no GIS reader accepts it).
    if (ring.size() < 3) {
      out.push_back("ring " + std::to_string(r + 1) + " has fewer than 3 vertices");
    } else if (allOnOneLine(ring)) {
      out.push_back("ring " + std::to_string(r + 1) + " has all its vertices on one line");
    } else if (const auto i = spikeTip(ring)) {
      out.push_back("ring " + std::to_string(r + 1) + " folds back on itself at vertex " + std::to_string(*i + 1) + " (a zero-width spike)");
    }
  }
  return true;
}

// Areas are measured on a copy at a comfortable scale (judging_scale.h): at subnormal or 1e300
// magnitudes the floating-point measurement itself would under- or overflow.
void areaViolations(const Region& subject, const Region& clip, Op op, const Region& result, int k,
                    std::vector<std::string>& out) {
  if (k == 0) {
    areaViolations(subject, clip, evenOddArea(subject), evenOddArea(clip), op, result, 0, out);
    return;
  }
  const Region s = scaledBy(subject, k), c = scaledBy(clip, k);
  areaViolations(s, c, evenOddArea(s), evenOddArea(c), op, scaledBy(result, k), k, out);
}

}  // namespace

std::vector<std::string> invariantViolations(const Region& subject, const Region& clip, Op op,
                                             const Region& result) {
  std::vector<std::string> out;
  if (!ringViolations(result, out)) return out;
  areaViolations(subject, clip, op, result, judgingExponent(subject, clip, result), out);
  return out;
}

InvariantJudge::InvariantJudge(const Region& subject, const Region& clip)
    : subject_(subject), clip_(clip), k_(judgingExponent(subject, clip, {})) {
  if (k_ != 0) scaledSubject_ = scaledBy(subject, k_), scaledClip_ = scaledBy(clip, k_);
  subjectArea_ = evenOddArea(k_ == 0 ? subject_ : scaledSubject_);
  clipArea_ = evenOddArea(k_ == 0 ? clip_ : scaledClip_);
}

std::vector<std::string> InvariantJudge::violations(Op op, const Region& result) const {
  std::vector<std::string> out;
  if (!ringViolations(result, out)) return out;
  // An answer that changes the judging scale (only a wrong one can) is measured at its own.
  const int k = judgingExponent(subject_, clip_, result);
  if (k != k_) {
    areaViolations(subject_, clip_, op, result, k, out);
    return out;
  }
  const Region scaled = k == 0 ? Region() : scaledBy(result, k);
  areaViolations(k == 0 ? subject_ : scaledSubject_, k == 0 ? clip_ : scaledClip_, subjectArea_, clipArea_, op,
                 k == 0 ? result : scaled, k, out);
  return out;
}

}  // namespace gh::oracle
