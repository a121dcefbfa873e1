#include "properties.h"

#include <cmath>
#include <sstream>

#include "ghclip/clip.h"
#include "ghclip/errors.h"
#include "ghoracle/exact_oracle.h"
#include "ghoracle/sampling_oracle.h"
#include "ghoracle/tolerance.h"

namespace gh::props {
namespace {

// A clip whose ClipFailure becomes a violation message instead of an exception.
struct Clipped {
  Region region;
  std::optional<std::string> failure;
};

Clipped run(const Region& s, const Region& c, Op op, Variant v) {
  Options o = optionsOf(v);
  try {
    return {clip(s, c, op, o), std::nullopt};
  } catch (const ClipFailure& e) {
    return {{}, std::string("ClipFailure: ") + e.what()};
  }
}

// Even-odd area of R from the exact oracle, with the slack a correct double answer may need:
// R's rounding allowance with respect to the inputs it was clipped from (each constructed vertex
// off by a few ulps of its own coordinates, tolerance.h), plus the width of the oracle's certified
// interval (which contains the exact area).
struct Area {
  double value = 0;
  double slack = 0;
};

Area areaOf(const Region& r, const Region& s, const Region& c) {
  const auto v = oracle::exactCheck(r, {}, Op::Union, {}, {false, false, false});
  return {v.expectedArea, oracle::roundingAllowance(s, c, r) + v.areaUncertainty};
}

Violation areasDiffer(const std::string& what, Area a, Area b) {
  const double slack = a.slack + b.slack + 4 * std::numeric_limits<double>::denorm_min();
  if (std::abs(a.value - b.value) <= slack) return std::nullopt;
  std::ostringstream s;
  s.precision(17);
  s << what << ": " << a.value << " vs " << b.value << " (difference " << std::abs(a.value - b.value)
    << ", allowed " << slack << ")";
  return s.str();
}

#define GH_RUN_OR_RETURN(var, s, c, op, v) \
  const Clipped var = run(s, c, op, v);    \
  if (var.failure) return *var.failure;

Violation oraclePasses(const PropertyCase& k, Variant v) {
  GH_RUN_OR_RETURN(r, k.subject, k.clip, k.op, v);
  const auto verdict = oracle::exactCheck(k.subject, k.clip, k.op, r.region, {false, false, false});
  if (verdict.pass) return std::nullopt;
  std::ostringstream s;
  s << "exact oracle: wrong faces beyond rounding, area " << verdict.beyondRoundingArea << " (error area "
    << verdict.errorArea << ", relative " << verdict.relativeError() << ")";
  return s.str();
}

Op swapped(Op op) {
  if (op == Op::Difference) return Op::ReverseDifference;
  if (op == Op::ReverseDifference) return Op::Difference;
  return op;
}

// op(S, C) and swapped(op)(C, S) describe the same set: compare the two answers exactly.
Violation commutative(const PropertyCase& k, Variant v) {
  GH_RUN_OR_RETURN(a, k.subject, k.clip, k.op, v);
  GH_RUN_OR_RETURN(b, k.clip, k.subject, swapped(k.op), v);
  const auto same = oracle::exactCheck(a.region, {}, Op::Union, b.region, {false, false, true});
  const double allowed = oracle::roundingAllowance(k.subject, k.clip, a.region) +
                         oracle::roundingAllowance(k.subject, k.clip, b.region);
  if (same.errorArea <= allowed) return std::nullopt;
  std::ostringstream s;
  s << "op(S, C) and the swapped op(C, S) differ by area " << same.errorArea << " > " << allowed;
  return s.str();
}

Violation differenceViaXor(const PropertyCase& k, Variant v) {
  GH_RUN_OR_RETURN(diff, k.subject, k.clip, Op::Difference, v);
  GH_RUN_OR_RETURN(both, k.subject, k.clip, Op::Intersection, v);
  GH_RUN_OR_RETURN(x, k.subject, both.region, Op::Xor, v);
  Area viaXor = areaOf(x.region, k.subject, both.region);
  viaXor.slack += oracle::roundingAllowance(k.subject, k.clip, both.region);
  return areasDiffer("area(S \\ C) vs area(S xor (S n C))", areaOf(diff.region, k.subject, k.clip),
                     viaXor);
}

Violation inclusionExclusion(const PropertyCase& k, Variant v) {
  GH_RUN_OR_RETURN(both, k.subject, k.clip, Op::Intersection, v);
  GH_RUN_OR_RETURN(either, k.subject, k.clip, Op::Union, v);
  const Area a = areaOf(both.region, k.subject, k.clip), b = areaOf(either.region, k.subject, k.clip);
  const Area s = areaOf(k.subject, {}, {}), c = areaOf(k.clip, {}, {});
  return areasDiffer("area(S n C) + area(S u C) vs area(S) + area(C)",
                     {a.value + b.value, a.slack + b.slack}, {s.value + c.value, s.slack + c.slack});
}

// An exact transform of the plane (or of the representation), and how it scales areas.
struct Transform {
  std::function<Region(const Region&)> apply;
  double areaFactor = 1;
};

Region mapPoints(const Region& r, const std::function<Point(Point)>& f) {
  Region out = r;
  for (Ring& ring : out) {
    for (Point& p : ring) p = f(p);
  }
  return out;
}

Property invariantUnder(Transform t) {
  return [t](const PropertyCase& k, Variant v) -> Violation {
    GH_RUN_OR_RETURN(plain, k.subject, k.clip, k.op, v);
    const Region ts = t.apply(k.subject), tc = t.apply(k.clip);
    GH_RUN_OR_RETURN(moved, ts, tc, k.op, v);
    Area a = areaOf(plain.region, k.subject, k.clip);
    a.value *= t.areaFactor, a.slack *= t.areaFactor;
    return areasDiffer("area(op(T S, T C)) vs area(T op(S, C))", areaOf(moved.region, ts, tc), a);
  };
}

Violation selfAndEmpty(const PropertyCase& k, Variant v) {
  const Region& s = k.subject;
  const Area as = areaOf(s, {}, {});
  const Area zero{0, 0};
  struct Check {
    const char* what;
    Region c;
    Op op;
    Area expect;
  };
  for (const Check& ch : {Check{"S n S = S", s, Op::Intersection, as}, Check{"S u S = S", s, Op::Union, as},
                          Check{"S \\ S = 0", s, Op::Difference, zero},
                          Check{"S n 0 = 0", {}, Op::Intersection, zero},
                          Check{"S u 0 = S", {}, Op::Union, as}}) {
    GH_RUN_OR_RETURN(r, s, ch.c, ch.op, v);
    if (auto bad = areasDiffer(ch.what, areaOf(r.region, s, ch.c), ch.expect)) return bad;
  }
  return std::nullopt;
}

const Transform kTranslate{[](const Region& r) {
                             return mapPoints(r, [](Point p) { return Point{p.x + 0.375, p.y - 1.25}; });
                           },
                           1};
const Transform kScale{[](const Region& r) {
                         return mapPoints(r, [](Point p) { return Point{std::ldexp(p.x, -9), std::ldexp(p.y, -9)}; });
                       },
                       std::ldexp(1.0, -18)};
const Transform kSwapXY{[](const Region& r) { return mapPoints(r, [](Point p) { return Point{p.y, p.x}; }); }, 1};
const Transform kReverse{[](const Region& r) {
                           Region out = r;
                           for (Ring& ring : out) std::reverse(ring.begin(), ring.end());
                           return out;
                         },
                         1};
const Transform kRotateStart{[](const Region& r) {
                               Region out = r;
                               for (Ring& ring : out) std::rotate(ring.begin(), ring.begin() + 1, ring.end());
                               return out;
                             },
                             1};
const Transform kSplitEdge{[](const Region& r) {
                             Region out = r;
                             for (Ring& ring : out) {
                               const Point a = ring[0], b = ring[1];
                               ring.insert(ring.begin() + 1, Point{a.x / 2 + b.x / 2, a.y / 2 + b.y / 2});
                             }
                             return out;
                           },
                           1};

}  // namespace

Violation bitsetExact(const BitsetCase& k, Variant v) {
  const PropertyCase c = k.asCase();
  GH_RUN_OR_RETURN(r, c.subject, c.clip, c.op, v);
  std::vector<bool> cells(k.grid.subject.size());
  for (std::size_t i = 0; i < cells.size(); ++i) cells[i] = apply(c.op, k.grid.subject[i], k.grid.clip[i]);
  const Region expected = work::cellsRegion(k.grid, cells);
  const auto verdict = oracle::exactCheck(expected, {}, Op::Union, r.region, {false, false, true});
  if (verdict.errorAreaExact == "0") return std::nullopt;
  std::ostringstream s;
  s << "error area against the bitwise answer is " << verdict.errorArea << ", not 0";
  return s.str();
}

const std::vector<PropertySpec>& suite() {
  static const std::vector<PropertySpec> specs = [] {
    std::vector<PropertySpec> s;
    for (const std::string family : {"random", "grid", "family"}) {
      s.push_back({"oracle_passes", family, oraclePasses});
      s.push_back({"commutative", family, commutative});
      s.push_back({"inclusion_exclusion", family, inclusionExclusion});
      s.push_back({"self_and_empty", family, selfAndEmpty});
    }
    for (const std::string family : {"random", "grid"}) {
      s.push_back({"difference_via_xor", family, differenceViaXor});
      s.push_back({"translate_dyadic", family, invariantUnder(kTranslate)});
      s.push_back({"scale_power_of_two", family, invariantUnder(kScale)});
      s.push_back({"swap_xy", family, invariantUnder(kSwapXY)});
      s.push_back({"reverse_orientation", family, invariantUnder(kReverse)});
      s.push_back({"rotate_start_vertex", family, invariantUnder(kRotateStart)});
      s.push_back({"split_edge_at_midpoint", family, invariantUnder(kSplitEdge)});
    }
    return s;
  }();
  return specs;
}

const PropertySpec* findSpec(const std::string& name, const std::string& family) {
  for (const PropertySpec& s : suite()) {
    if (s.name == name && s.family == family) return &s;
  }
  return nullptr;
}

}  // namespace gh::props
