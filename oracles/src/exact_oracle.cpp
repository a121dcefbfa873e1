// The only translation unit that includes CGAL's arrangements (they are slow to compile).
#include "ghoracle/exact_oracle.h"

#include <CGAL/Arr_curve_data_traits_2.h>
#include <CGAL/Arr_extended_dcel.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/convex_hull_2.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <cmath>
#include <limits>
#include <map>
#include <new>
#include <set>
#include <sstream>
#include <tuple>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "ghclip/errors.h"
#include "ghclip/validate.h"
#include "difference_bound.h"
#include "filtered_orientation.h"
#include "judging_scale.h"
#include "point_hash.h"
#include "rational_orientation.h"
#include "robust_segment_traits.h"

namespace gh::oracle {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using FT = Kernel::FT;
using KPoint = Kernel::Point_2;
using EFT = Kernel::Exact_kernel::FT;  // exact rationals
using SegmentTraits = RobustSegmentTraits<Kernel>;

// How many segments of S and C run along a piece of curve, the parities of the answers' segments
// along it (bit j: answer j, for the several answers judged in one arrangement), and the signed
// number of rounding zone edges (+1 when the zone lies to the left of the piece directed left to
// right, -1 when to its right).
// Beside the counts, the segment of doubles the piece was cut from (its line: lineA != lineB), so
// that which pieces lie on one line is decided on doubles (OperandLines), not on the pieces'
// ends, crossings in the kernel's rationals. Not part of the data's equality.
struct Counts {
  int s = 0, c = 0;
  unsigned r = 0;
  int z = 0;
  Point lineA{}, lineB{};
  bool operator==(const Counts& o) const { return s == o.s && c == o.c && r == o.r && z == o.z; }
  unsigned parityBits() const { return (s & 1u) | (c & 1u) << 1 | r << 2; }
  bool onOperands() const { return s + c > 0; }
  bool hasLine() const { return lineA != lineB; }
};
// Overlapping segments add up their counts (and their parities); they lie on one line, either's.
struct AddCounts {
  Counts operator()(const Counts& a, const Counts& b) const {
    const Counts& line = a.hasLine() ? a : b;
    return {a.s + b.s, a.c + b.c, a.r ^ b.r, a.z + b.z, line.lineA, line.lineB};
  }
};

using Traits = CGAL::Arr_curve_data_traits_2<SegmentTraits, Counts, AddCounts>;
constexpr unsigned kS = 1, kC = 2;
constexpr std::size_t kMostAnswers = 30;  // parity bits of S, C and the answers in one unsigned
constexpr double kSymmetricDifferenceTightness = 1e-9;  // symmetricDifferenceAreas' relative accuracy
// Parity bits of S (kS), C (kC) and answer j (answerBit(j)), and how many rounding zones hold
// the face.
constexpr unsigned answerBit(std::size_t j) { return 4u << j; }
struct FaceData {
  unsigned bits = 0;
  int zones = 0;
  bool visited = false;
};
using Dcel = CGAL::Arr_face_extended_dcel<Traits, FaceData>;
using Arrangement = CGAL::Arrangement_2<Traits, Dcel>;
using Face = Arrangement::Face_const_handle;
using Halfedge = Arrangement::Halfedge_const_handle;
using Vertex = Arrangement::Vertex_const_handle;
using Interval = CGAL::Interval_nt<true>;  // protected: every interval contains the truth

// A segment of S, C or an answer, its ends in lexicographic order, with its counts.
struct CountedSegment {
  Point a, b;
  Counts counts;
};

void addSegments(const Region& region, Counts counts, std::vector<CountedSegment>& out) {
  for (const Ring& ring : region) {
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
      Point a = ring[i], b = ring[(i + 1) % n];
      if (a == b) continue;
      if (std::tie(b.x, b.y) < std::tie(a.x, a.y)) std::swap(a, b);
      out.push_back({a, b, counts});
    }
  }
}

// One curve per distinct segment, carrying the sum of the counts of its copies: what the
// arrangement makes of overlapping copies anyway (AddCounts), without computing each overlap in
// exact arithmetic. The answers share most of their edges with S, C and one another.
std::vector<Traits::Curve_2> mergedCurves(std::vector<CountedSegment> segments) {
  const auto key = [](const CountedSegment& g) { return std::tie(g.a.x, g.a.y, g.b.x, g.b.y); };
  std::sort(segments.begin(), segments.end(),
            [&](const CountedSegment& l, const CountedSegment& r) { return key(l) < key(r); });
  std::vector<Traits::Curve_2> curves;
  for (std::size_t i = 0; i < segments.size();) {
    Counts counts = segments[i].counts;
    std::size_t next = i + 1;
    for (; next < segments.size() && key(segments[next]) == key(segments[i]); ++next) {
      counts = AddCounts()(counts, segments[next].counts);
    }
    const Point a = segments[i].a, b = segments[i].b;
    counts.lineA = a, counts.lineB = b;
    curves.emplace_back(SegmentTraits::Curve_2(KPoint(a.x, a.y), KPoint(b.x, b.y)), counts);
    i = next;
  }
  return curves;
}

// Parities and zone depths from the unbounded face outward, across every edge (breadth first).
// A face lies to the left of each of its halfedges.
void propagate(Arrangement& arr) {
  for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f) f->set_data({});
  std::vector<Arrangement::Face_handle> queue{arr.unbounded_face()};
  arr.unbounded_face()->set_data({0, 0, true});
  for (std::size_t k = 0; k < queue.size(); ++k) {
    const auto f = queue[k];
    auto visit = [&](Arrangement::Ccb_halfedge_circulator first) {
      auto h = first;
      do {
        auto g = h->twin()->face();
        if (!g->data().visited) {
          const Counts& counts = h->curve().data();
          const bool leftToRight = h->direction() == CGAL::ARR_LEFT_TO_RIGHT;
          g->set_data({f->data().bits ^ counts.parityBits(),
                       f->data().zones + (leftToRight ? -counts.z : counts.z), true});
          queue.push_back(g);
        }
      } while (++h != first);
    };
    for (auto ccb = f->outer_ccbs_begin(); ccb != f->outer_ccbs_end(); ++ccb) visit(*ccb);
    for (auto ccb = f->inner_ccbs_begin(); ccb != f->inner_ccbs_end(); ++ccb) visit(*ccb);
  }
}

bool expectedInside(Op op, unsigned bits) { return apply(op, bits & kS, bits & kC); }
bool resultInside(unsigned bits, std::size_t j) { return bits & answerBit(j); }
bool isWrong(Op op, std::size_t j, Face f) { return expectedInside(op, f->data().bits) != resultInside(f->data().bits, j); }

template <class F>
void forEachCcb(Face f, F&& visit) {
  for (auto ccb = f->outer_ccbs_begin(); ccb != f->outer_ccbs_end(); ++ccb) visit(*ccb);
  for (auto ccb = f->inner_ccbs_begin(); ccb != f->inner_ccbs_end(); ++ccb) visit(*ccb);
}

// Certified enclosure of a bounded face's area from the vertices' interval approximations,
// taken relative to one of its vertices: a sliver face then gets an interval as small as itself.
// In one upward rounding mode for the whole face (CGAL's unprotected intervals under one
// Protect_FPU_rounding give the protected ones' bounds without setting and restoring the mode at
// each operation, which made this a twentieth of the exact-oracle target's corpus replay).
Interval faceAreaInterval(Face f) {
  CGAL::Protect_FPU_rounding<true> upward;
  using Fast = CGAL::Interval_nt<false>;
  Fast twice = 0;
  const auto& origin = CGAL::approx((*f->outer_ccbs_begin())->source()->point());
  forEachCcb(f, [&](Arrangement::Ccb_halfedge_const_circulator first) {
    auto h = first;
    do {
      const auto& p = CGAL::approx(h->source()->point());
      const auto& q = CGAL::approx(h->target()->point());
      const Fast px = p.x() - origin.x(), py = p.y() - origin.y();
      const Fast qx = q.x() - origin.x(), qy = q.y() - origin.y();
      twice += px * qy - qx * py;
    } while (++h != first);
  });
  const Fast area = twice / 2;
  return Interval(area.inf(), area.sup());
}

// Exact area of a bounded face: outer boundary counter-clockwise, holes clockwise. Summed in the
// exact number type: lazy sums would build one large expression tree per face (5x slower).
EFT faceArea(Face f) {
  EFT twice = 0;
  forEachCcb(f, [&](Arrangement::Ccb_halfedge_const_circulator first) {
    auto h = first;
    do {
      const auto& p = CGAL::exact(h->source()->point());
      const auto& q = CGAL::exact(h->target()->point());
      twice += p.x() * q.y() - q.x() * p.y();
    } while (++h != first);
  });
  return twice / 2;
}

CGAL::Bbox_2 faceBox(Face f) {
  CGAL::Bbox_2 box;
  bool first = true;
  forEachCcb(f, [&](Arrangement::Ccb_halfedge_const_circulator start) {
    auto h = start;
    do {
      const CGAL::Bbox_2 b = h->source()->point().bbox();
      box = first ? b : box + b;
      first = false;
    } while (++h != start);
  });
  return box;
}

// A point strictly inside face f: on a vertical line between two vertex abscissae (so it meets
// no vertex), the face's boundary edges cut the line into alternating in/out intervals; take
// the middle of the longest inside interval. Edges with f on both sides are skipped.
KPoint pointInside(Face f) {
  std::vector<Halfedge> edges;
  std::vector<FT> xs;
  forEachCcb(f, [&](Arrangement::Ccb_halfedge_const_circulator first) {
    auto h = first;
    do {
      xs.push_back(h->source()->point().x());
      if (h->twin()->face() != f) edges.push_back(h);
    } while (++h != first);
  });
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  std::size_t widest = 0;
  for (std::size_t i = 1; i + 1 < xs.size(); ++i) {
    if (xs[i + 1] - xs[i] > xs[widest + 1] - xs[widest]) widest = i;
  }
  const FT x0 = (xs[widest] + xs[widest + 1]) / 2;
  std::vector<FT> ys;
  for (const Halfedge& h : edges) {
    const KPoint& a = h->source()->point();
    const KPoint& b = h->target()->point();
    if ((a.x() < x0 && x0 < b.x()) || (b.x() < x0 && x0 < a.x())) {
      ys.push_back(a.y() + (b.y() - a.y()) * (x0 - a.x()) / (b.x() - a.x()));
    }
  }
  std::sort(ys.begin(), ys.end());
  std::size_t best = 0;
  for (std::size_t i = 2; i + 1 < ys.size(); i += 2) {
    if (ys[i + 1] - ys[i] > ys[best + 1] - ys[best]) best = i;
  }
  return KPoint(x0, (ys[best] + ys[best + 1]) / 2);
}

// The largest double <= v and the smallest >= v (equal when v is a double).
std::pair<double, double> doublesAround(const EFT& v) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  double lo = CGAL::to_double(v);
  while (EFT(lo) > v) lo = std::nextafter(lo, -inf);
  while (EFT(std::nextafter(lo, inf)) <= v) lo = std::nextafter(lo, inf);
  return {lo, EFT(lo) == v ? lo : std::nextafter(lo, inf)};
}

// The double nearest to an exact rational (ties to the lower): a faithful rounding, and what the
// tools print of an area (CGAL::to_double of a rational truncates; of a lazy number it is an
// interval's midpoint, which need not be either double around the value).
double nearestOf(const EFT& v) {
  const auto [lo, hi] = doublesAround(v);
  return lo == hi || v - EFT(lo) <= EFT(hi) - v ? lo : hi;
}
double nearestDouble(const FT& v) {
  const auto& a = CGAL::approx(v);
  return a.is_point() ? a.inf() : nearestOf(CGAL::exact(v));
}

// The boundary of the union of faces where `in` holds, as rings with the region on the left:
// from each boundary halfedge, turn around its target through inside faces to the next one.
template <class In>
Region boundaryRings(const Arrangement& arr, In in) {
  auto isBoundary = [&](Halfedge h) { return in(h->face()) && !in(h->twin()->face()); };
  Region rings;
  std::vector<Halfedge> all;
  for (auto h = arr.halfedges_begin(); h != arr.halfedges_end(); ++h) all.push_back(h);
  std::unordered_map<const void*, std::size_t> index;
  for (std::size_t i = 0; i < all.size(); ++i) index[&*all[i]] = i;
  std::vector<char> used(all.size(), 0);
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (used[i] || !isBoundary(all[i])) continue;
    Ring ring;
    Halfedge h = all[i];
    do {
      used[index[&*h]] = 1;
      const Point p{nearestDouble(h->source()->point().x()), nearestDouble(h->source()->point().y())};
      if (ring.empty() || ring.back() != p) ring.push_back(p);
      Halfedge next = h->next();
      while (!isBoundary(next)) next = next->twin()->next();
      h = next;
    } while (h != all[i]);
    while (ring.size() > 1 && ring.back() == ring.front()) ring.pop_back();
    if (ring.size() >= 3) rings.push_back(std::move(ring));
  }
  return rings;
}

void build(const std::vector<Traits::Curve_2>& curves, Arrangement& arr) {
  CGAL::insert(arr, curves.begin(), curves.end());
  propagate(arr);
}

std::vector<Traits::Curve_2> operandCurves(const Region& s, const Region& c, const std::vector<const Region*>& answers) {
  std::vector<CountedSegment> segments;
  addSegments(normalized(s, OnBadRing::Drop), {1, 0, 0, 0}, segments);
  addSegments(normalized(c, OnBadRing::Drop), {0, 1, 0, 0}, segments);
  for (std::size_t j = 0; j < answers.size(); ++j) {
    addSegments(normalized(*answers[j], OnBadRing::Drop), {0, 0, 1u << j, 0}, segments);
  }
  return mergedCurves(std::move(segments));
}

std::string rationalText(const EFT& v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// ---------------------------------------------------------------------------------------------
// Rounding zones (see exact_oracle.h).

// 2^e exactly, from doubles (exact powers of two) in steps of at most 2^+-1000: a few products,
// not |e| of them (the judging exponent reaches 2200).
EFT powerOfTwo(int e) {
  EFT p = 1;
  for (; e > 1000; e -= 1000) p *= EFT(std::ldexp(1.0, 1000));
  for (; e < -1000; e += 1000) p *= EFT(std::ldexp(1.0, -1000));
  return p * EFT(std::ldexp(1.0, e));
}

// The doubles in order as integers (both zeros 0, -denorm_min -1): n doubles away from x is
// n away here, whatever binades or the sign it crosses. NaN never comes here.
std::int64_t doubleIndex(double x) {
  std::int64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  return bits >= 0 ? bits : std::numeric_limits<std::int64_t>::min() - bits;
}
double doubleAtIndex(std::int64_t i) {
  const std::int64_t bits = i >= 0 ? i : std::numeric_limits<std::int64_t>::min() - i;
  double x;
  std::memcpy(&x, &bits, sizeof x);
  return x;
}
// x moved by n doubles (n may be negative), stopping at the largest finite ones: O(1) for any n
// (`--ulps 1048576` took a million nextafter calls per coordinate).
double stepDoubles(double x, std::int64_t n) {
  const std::int64_t most = doubleIndex(std::numeric_limits<double>::max());
  return doubleAtIndex(std::clamp(doubleIndex(x) + n, -most, most));
}

// The doubles a coordinate may round to: [lo, hi] with lo the largest double <= v and hi the
// smallest >= v (equal when v is a double), widened by ulps - 1 doubles on each side. Computed
// at the original scale (v * 2^-k: the judge works on a copy scaled by 2^k), returned scaled.
std::pair<double, double> roundingInterval(const FT& v, int k, int ulps) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  const auto& approx = CGAL::approx(v);
  double lo, hi;
  if (approx.is_point() && k == 0) {
    lo = hi = approx.inf();
  } else {
    EFT exact = CGAL::exact(v);
    if (k != 0) exact *= powerOfTwo(-k);
    std::tie(lo, hi) = doublesAround(exact);
  }
  lo = stepDoubles(lo, -(ulps - 1)), hi = stepDoubles(hi, ulps - 1);
  if (k == 0) return {lo, hi};
  // Back to the judging scale, rounded outward (exact unless the scaled value is subnormal).
  double slo = std::ldexp(lo, k), shi = std::ldexp(hi, k);
  if (std::ldexp(slo, -k) > lo) slo = std::nextafter(slo, -inf);
  if (std::ldexp(shi, -k) < hi) shi = std::nextafter(shi, inf);
  return {slo, shi};
}

struct RoundingBox {
  double x0, x1, y0, y1;
  bool isPoint() const { return x0 == x1 && y0 == y1; }
};

RoundingBox roundingBox(const KPoint& p, int k, int ulps) {
  const auto [x0, x1] = roundingInterval(p.x(), k, ulps);
  const auto [y0, y1] = roundingInterval(p.y(), k, ulps);
  return {x0, x1, y0, y1};
}

// The straight lines of S and C: maximal chains of arrangement edges on S or C that go on along
// one line through each vertex. A candidate's edges run along these lines between (rounded)
// vertices of the arrangement of S and C, and may skip any of them (a ring passing straight
// through a crossing, as Greiner-Hormann's rings pass through the operands' self-crossings, or a
// peer dropping a collinear vertex), so a line's zone is the convex hull of the rounding boxes of
// all vertices on it. Every line counts, not only the exact answer's boundary: where two rings of
// a candidate run along one operand edge in opposite directions, one through a rounded crossing
// and one straight past it, the sliver between them is rounding although the exact answer has no
// boundary there. Vertices that only R or R's crossings make are not vertices of S and C: they
// add nothing.
class OperandLines {
 public:
  explicit OperandLines(const Arrangement& arr, const std::unordered_set<Point, PointHash>& inputVertices)
      : inputVertices_(inputVertices) {
    std::unordered_set<const void*> done;
    for (auto e = arr.edges_begin(); e != arr.edges_end(); ++e) {
      const Halfedge h = e;
      if (!onOperands(h) || done.count(&*h)) continue;
      std::vector<Vertex> run;
      std::vector<const void*> passed;
      done.insert(&*h), done.insert(&*h->twin());
      follow(h, run, passed, done);
      follow(h->twin(), run, passed, done);
      std::sort(passed.begin(), passed.end());
      runs_.push_back(std::move(run));
      passed_.push_back(std::move(passed));
    }
  }
  // Each run: the vertices of the arrangement of S and C on it (at least its two ends).
  const std::vector<std::vector<Vertex>>& runs() const { return runs_; }
  // Every vertex of the arrangement on run i (crossings with the answers' edges too), sorted by
  // address: all on the segment between its two ends.
  const std::vector<const void*>& passed(std::size_t i) const { return passed_[i]; }

 private:
  static bool onOperands(Halfedge h) { return h->curve().data().onOperands(); }
  // A vertex of the arrangement of S and C: an input vertex, or where operand segments cross
  // (anything but exactly two operand pieces, which then continue one segment straight on).
  bool isOperandVertex(Vertex v) {
    const auto found = operandVertex_.find(&*v);
    if (found != operandVertex_.end()) return found->second;
    bool result;
    const auto& a = CGAL::approx(v->point());
    if (a.x().is_point() && a.y().is_point() && inputVertices_.count(Point{a.x().inf(), a.y().inf()})) {
      result = true;
    } else {
      int pieces = 0;
      auto h = v->incident_halfedges();
      const auto first = h;
      do pieces += h->curve().data().onOperands();
      while (++h != first);
      result = pieces != 2;
    }
    operandVertex_.emplace(&*v, result);
    return result;
  }
  // Does out, leaving h's target, go on along h's line beyond it? Two pieces that meet lie on
  // one line iff the segments of doubles they were cut from do (exact orientations of doubles);
  // then out goes on, not back along h, iff both run the same way in lexicographic order.
  // Pieces without their segment (none in the arrangement of S, C and the answers) are decided
  // on their ends, in the kernel's rationals.
  static bool continues(Halfedge h, Halfedge out) {
    const Counts &a = h->curve().data(), &b = out->curve().data();
    if (a.hasLine() && b.hasLine()) {
      return filteredOrientation(a.lineA, a.lineB, b.lineA) == 0 && filteredOrientation(a.lineA, a.lineB, b.lineB) == 0 &&
             h->direction() == out->direction();
    }
    const KPoint &p = h->source()->point(), &v = h->target()->point(), &q = out->target()->point();
    // (The second predicate's precondition: the three points are collinear.)
    return Kernel().collinear_2_object()(p, v, q) && Kernel().collinear_are_strictly_ordered_along_line_2_object()(p, v, q);
  }
  // From h's target on: every boundary edge that continues h's line, collecting the operand
  // vertices passed.
  void follow(Halfedge h, std::vector<Vertex>& run, std::vector<const void*>& passed, std::unordered_set<const void*>& done) {
    for (;;) {
      const Vertex v = h->target();
      if (isOperandVertex(v)) run.push_back(v);
      passed.push_back(&*v);
      auto around = v->incident_halfedges();
      const auto first = around;
      std::optional<Halfedge> next;
      do {
        const Halfedge out = around->twin();  // leaves v
        if (around != h && onOperands(out) && !done.count(&*out) && continues(h, out)) next = out;
      } while (++around != first);
      if (!next) return;
      h = *next;
      done.insert(&*h), done.insert(&*h->twin());
    }
  }

  const std::unordered_set<Point, PointHash>& inputVertices_;
  std::unordered_map<const void*, bool> operandVertex_;
  std::vector<std::vector<Vertex>> runs_;
  std::vector<std::vector<const void*>> passed_;
};

using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 2, std::size_t>;

// The rounding zones that meet some wrong face: for each straight line of S and C with a vertex
// that is not a double, the convex hull of its vertices' rounding boxes, as edges for the
// arrangement. Returns how many zones.
// Which runs of the lines of S and C (lines.runs()) lie near a wrong face: their rounding zones
// could hold part of it. The others' zones cannot (a zone lies within its run's box, widened
// by far more than a rounding box).
std::vector<char> runsNear(const OperandLines& lines, const std::vector<Face>& wrongFaces, int k, int ulps) {
  std::vector<Box> wrongBoxes, pieceBoxes;
  for (std::size_t i = 0; i < wrongFaces.size(); ++i) wrongBoxes.emplace_back(faceBox(wrongFaces[i]), i);
  for (std::size_t i = 0; i < lines.runs().size(); ++i) {
    const auto& run = lines.runs()[i];
    CGAL::Bbox_2 box = run.front()->point().bbox();
    for (const Vertex& v : run) box += v->point().bbox();
    // Room for the rounding boxes, generously (the exact boxes are computed for the survivors).
    const double margin = std::ldexp(std::max({std::abs(box.xmin()), std::abs(box.xmax()),
                                               std::abs(box.ymin()), std::abs(box.ymax())}),
                                     -48 + ulps) +
                          std::ldexp(std::numeric_limits<double>::denorm_min(), ulps + 2 + std::max(k, 0));
    box = CGAL::Bbox_2(box.xmin() - margin, box.ymin() - margin, box.xmax() + margin, box.ymax() + margin);
    pieceBoxes.emplace_back(box, i);
  }
  std::vector<char> near(lines.runs().size(), 0);
  CGAL::box_intersection_d(wrongBoxes.begin(), wrongBoxes.end(), pieceBoxes.begin(), pieceBoxes.end(),
                           [&](const Box&, const Box& piece) { near[piece.info()] = 1; });
  return near;
}

// The rounding zone of run i (the hull of its crossings' rounding boxes, counter-clockwise, in
// `hull`), as curves whose zone count says on which side the zone lies; false when it has none
// (no crossing is rounded).
bool addRoundingZone(const OperandLines& lines, std::size_t i, int k, int ulps, std::vector<Traits::Curve_2>& curves,
                     std::vector<Point>& zoneHull) {
  using HullKernel = CGAL::Exact_predicates_inexact_constructions_kernel;  // exact predicates
  std::vector<HullKernel::Point_2> corners;
  bool anyBox = false;
  for (const Vertex& v : lines.runs()[i]) {
    const RoundingBox r = roundingBox(v->point(), k, ulps);
    anyBox |= !r.isPoint();
    for (double x : {r.x0, r.x1}) {
      for (double y : {r.y0, r.y1}) corners.emplace_back(x, y);
    }
  }
  if (!anyBox) return false;
  std::sort(corners.begin(), corners.end());
  corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
  std::vector<HullKernel::Point_2> hull;
  CGAL::convex_hull_2(corners.begin(), corners.end(), std::back_inserter(hull));  // counter-clockwise
  if (hull.size() < 3) return false;
  zoneHull.clear();
  for (const auto& corner : hull) zoneHull.push_back({corner.x(), corner.y()});
  for (std::size_t j = 0; j < hull.size(); ++j) {
    const auto& p = hull[j];
    const auto& q = hull[(j + 1) % hull.size()];
    const int side = p < q ? 1 : -1;  // the zone lies to the left of p -> q
    curves.emplace_back(SegmentTraits::Curve_2(KPoint(p.x(), p.y()), KPoint(q.x(), q.y())), Counts{0, 0, 0, side});
  }
  return true;
}

// ---------------------------------------------------------------------------------------------

// errorArea relative to the problem's size (see exact_oracle.h); scale-free, so it is computed
// on the scaled problem, where no area underflows.
double problemScale(const ExactVerdict& v) {
  double scale = std::max({v.subjectArea, v.clipArea, v.expectedArea, v.resultArea});
  // Operands of zero area (collinear rings) leave no area to compare with: then the size of the
  // problem is its bounding box.
  if (scale <= v.boxArea * 0x1p-40) scale = v.boxArea;
  return scale;
}
double relativeTo(double scale, double area) { return scale > 0 ? area / scale : (area > 0 ? 1.0 : 0.0); }

double boxAreaOf(const Region& subject, const Region& clip) {
  double minX = 0, minY = 0, maxX = 0, maxY = 0;
  bool any = false;
  for (const Region* r : {&subject, &clip}) {
    for (const Ring& ring : *r) {
      for (const Point& p : ring) {
        if (!any) minX = maxX = p.x, minY = maxY = p.y, any = true;
        minX = std::min(minX, p.x), maxX = std::max(maxX, p.x), minY = std::min(minY, p.y), maxY = std::max(maxY, p.y);
      }
    }
  }
  return (maxX / 2 - minX / 2) * (maxY / 2 - minY / 2) * 4;  // halves: no overflow near 1e308
}

// The areas of op(S, C), of answer j and of S and C over the bounded faces, in number type N
// (certified intervals, or exact rationals), each face's area computed once; `each` sees every
// face that lies in any of them, with whether op(S, C) and the answer hold it.
template <class N>
struct AreaSums {
  N expected = 0, result = 0, subject = 0, clip = 0;
};
template <class N, class AreaOf, class Each>
AreaSums<N> sumAreas(const Arrangement& arr, Op op, std::size_t j, AreaOf areaOf, Each each) {
  AreaSums<N> sums;
  for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f) {
    if (f->is_unbounded()) continue;  // outside everything: op(0, 0) = 0 for every op
    const unsigned bits = f->data().bits;
    const bool want = expectedInside(op, bits), have = resultInside(bits, j);
    if (!want && !have && !(bits & (kS | kC))) continue;
    const N area = areaOf(f);
    if (bits & kS) sums.subject += area;
    if (bits & kC) sums.clip += area;
    if (want) sums.expected += area;
    if (have) sums.result += area;
    each(Face(f), want, have);
  }
  return sums;
}

// The judgement of answer j of an arrangement of S, C and the answers, on a problem already at
// a comfortable scale (coordinates multiplied by 2^k, areas by 4^k), in two steps around the
// rounding zones that every answer's wrong faces share: its areas and wrong faces first, then
// (finish) the wrong region split by the zones into faces excused by rounding and faces beyond.
struct AnswerJudgement {
  ExactVerdict v;
  std::vector<Face> wrongFaces;
  std::vector<Face> rounding, beyond;  // the wrong region's faces in the zoned arrangement
  std::chrono::steady_clock::time_point start;
};

AnswerJudgement judgeFaces(const Arrangement& arr, const Region& subject, const Region& clip, Op op, std::size_t j) {
  AnswerJudgement a;
  a.start = std::chrono::steady_clock::now();
  ExactVerdict& v = a.v;
  const AreaSums<Interval> sums = sumAreas<Interval>(arr, op, j, faceAreaInterval, [&](Face f, bool want, bool have) {
    if (want != have) a.wrongFaces.push_back(f);
  });
  const Interval &expected = sums.expected, &got = sums.result;
  v.expectedArea = CGAL::to_double(expected);
  v.resultArea = CGAL::to_double(got);
  v.subjectArea = CGAL::to_double(sums.subject);
  v.clipArea = CGAL::to_double(sums.clip);
  v.boxArea = boxAreaOf(subject, clip);
  v.areaUncertainty = std::max(expected.sup() - expected.inf(), got.sup() - got.inf());
  v.faces = arr.number_of_faces();
  v.vertices = arr.number_of_vertices();
  v.edges = arr.number_of_edges();
  return a;
}

void finish(AnswerJudgement& a, const Arrangement& arr, Op op, std::size_t j, const ExactOptions& options, int k) {
  ExactVerdict& v = a.v;
  const std::vector<Face>& beyond = a.wrongFaces.empty() || v.zones > 0 ? a.beyond : a.wrongFaces;
  const std::vector<Face>& rounding = a.rounding;
  v.pass = beyond.empty();
  Interval error = 0, beyondError = 0;
  double largest = -1;
  std::optional<Face> witnessFace;
  for (const auto* faces : {&beyond, &rounding}) {
    for (Face f : *faces) {
      const Interval area = faceAreaInterval(f);
      error += area;
      if (faces == &beyond) beyondError += area;
      // The witness lies in the largest face beyond rounding, or in the largest rounding face.
      if ((faces == &beyond || beyond.empty()) && CGAL::to_double(area) > largest) {
        largest = CGAL::to_double(area), witnessFace = f;
      }
    }
  }
  v.errorArea = CGAL::to_double(error);
  v.beyondRoundingArea = CGAL::to_double(beyondError);
  if (options.exactErrorArea) {
    const EFT toOriginal = powerOfTwo(-2 * k);
    EFT beyondExact = 0, roundingExact = 0;
    for (Face f : beyond) beyondExact += faceArea(f);
    for (Face f : rounding) roundingExact += faceArea(f);
    v.errorArea = nearestOf(beyondExact + roundingExact);
    v.beyondRoundingArea = nearestOf(beyondExact);
    v.errorAreaExact = rationalText((beyondExact + roundingExact) * toOriginal);
    v.beyondRoundingAreaExact = rationalText(beyondExact * toOriginal);
  }
  if (options.exactAreas) {
    // Each area the exact rational rounded once (a midpoint of an interval can be off by far
    // more than an ulp where slivers widen it).
    const AreaSums<EFT> sums = sumAreas<EFT>(arr, op, j, faceArea, [](Face, bool, bool) {});
    v.expectedArea = nearestOf(sums.expected);
    v.resultArea = nearestOf(sums.result);
    v.subjectArea = nearestOf(sums.subject);
    v.clipArea = nearestOf(sums.clip);
  }
  if (witnessFace) {
    const KPoint w = pointInside(*witnessFace);
    v.witness = Point{CGAL::to_double(w.x()), CGAL::to_double(w.y())};
  }
  if (options.wantExpectedRings) {
    v.expected = boundaryRings(arr, [op](Face f) { return expectedInside(op, f->data().bits); });
  }
  if (options.wantWrongRings && !a.wrongFaces.empty()) {
    v.wrong = boundaryRings(arr, [op, j](Face f) { return isWrong(op, j, f); });
  }
  const double scale = problemScale(v);
  v.relative = relativeTo(scale, v.errorArea);
  v.relativeBeyond = relativeTo(scale, v.beyondRoundingArea);
  v.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - a.start).count();
}

// Every answer judged against S and C in one arrangement, on a problem already at a comfortable
// scale. The wrong regions of all the answers (bit j: answer j's) and the rounding zones near any
// of them go into one second arrangement, far smaller than S, C and R again: a zone near one
// answer's wrong faces only can hold nothing of another's, so each answer's faces there are
// split and excused as in an arrangement of its own (built once instead of once per answer: 68 %
// of the exact-oracle fuzz target's time went into those), and an answer whose wrong faces each
// lie in one zone needs none. Each verdict's seconds: its own judging and an equal share of
// building the arrangements.
std::vector<ExactVerdict> judge(const Region& subject, const Region& clip, const std::vector<Answer>& answers,
                                const ExactOptions& options, int k) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<const Region*> regions;
  for (const Answer& a : answers) regions.push_back(&a.result);
  Arrangement arr;
  build(operandCurves(subject, clip, regions), arr);
  std::vector<AnswerJudgement> judged;
  for (std::size_t j = 0; j < answers.size(); ++j) judged.push_back(judgeFaces(arr, subject, clip, answers[j].op, j));
  std::vector<Face> anyWrong;
  for (const AnswerJudgement& a : judged) anyWrong.insert(anyWrong.end(), a.wrongFaces.begin(), a.wrongFaces.end());
  Arrangement zoned;
  if (!anyWrong.empty()) {
    std::unordered_set<Point, PointHash> inputVertices;
    for (const Region* r : {&subject, &clip}) {
      for (const Ring& ring : *r) inputVertices.insert(ring.begin(), ring.end());
    }
    const OperandLines lines(arr, inputVertices);
    std::vector<Traits::Curve_2> curves;
    const std::vector<char> near = runsNear(lines, anyWrong, k, options.constructionUlps);
    std::vector<Traits::Curve_2> zoneCurves;
    std::vector<std::size_t> zoneStart(near.size() + 1, 0);  // run i's curves: [start[i], start[i + 1])
    std::vector<std::vector<Point>> hulls(near.size());
    std::vector<char> zone(near.size(), 0);
    for (std::size_t i = 0; i < near.size(); ++i) {
      zone[i] = near[i] && addRoundingZone(lines, i, k, options.constructionUlps, zoneCurves, hulls[i]);
      zoneStart[i + 1] = zoneCurves.size();
    }
    // A wrong face whose outer boundary lies in one zone (convex: decided at its vertices,
    // exactly) is rounding as a whole; an answer whose wrong faces all are needs no arrangement
    // of its own (most of the exact variant's: slivers along an edge, within one zone).
    // The zones' corners are doubles: a vertex's side of a zone edge is decided by intervals
    // where they suffice, else exactly in integers (rational_orientation.h), not in the kernel's
    // rationals, which divide out common factors after every operation.
    // A face's outer boundary is read once (its vertices' intervals and their box), not once per
    // zone: a vertex whose interval lies wholly beyond a zone's box lies outside the zone, with
    // no interval product. (Tested against every zone near it, vertex by vertex, this loop was
    // the exact-oracle target's largest item in perf: 12 % of a fork-mode run.)
    using Fast = CGAL::Interval_nt<false>;  // the kernel's own approximations: used under Protect_FPU_rounding
    struct Corner {
      const void* vertex;
      const KPoint* p;
      Fast x, y;
    };
    struct Outline {
      std::vector<Corner> corners;
      double maxInfX = -HUGE_VAL, minSupX = HUGE_VAL, maxInfY = -HUGE_VAL, minSupY = HUGE_VAL;
    };
    auto outlineOf = [](Face f) {
      Outline o;
      auto h = *f->outer_ccbs_begin(), first = h;
      do {
        const KPoint& p = h->source()->point();
        const Corner c{&*h->source(), &p, CGAL::approx(p).x(), CGAL::approx(p).y()};
        o.maxInfX = std::max(o.maxInfX, c.x.inf()), o.minSupX = std::min(o.minSupX, c.x.sup());
        o.maxInfY = std::max(o.maxInfY, c.y.inf()), o.minSupY = std::min(o.minSupY, c.y.sup());
        o.corners.push_back(c);
      } while (++h != first);
      return o;
    };
    std::vector<CGAL::Bbox_2> hullBoxes(hulls.size());
    for (std::size_t i = 0; i < hulls.size(); ++i) {
      for (const Point& a : hulls[i]) hullBoxes[i] += CGAL::Bbox_2(a.x, a.y, a.x, a.y);
    }
    // A face corner on a zone's run (lines.passed) lies in the zone, with nothing to decide: on
    // the segment between the run's ends, whose rounding boxes the zone (convex) holds. Such
    // corners lie within an ulp of the zone's edges (a run's vertex on its box's, the answers'
    // crossings with the run beside them), where the intervals cannot tell the side: on the
    // oracle target's corpus they made most of the exact tests (1.9 million for 724 inputs).
    auto inZone = [&](const Outline& o, std::size_t i) {
      const std::vector<Point>& hull = hulls[i];
      const CGAL::Bbox_2& box = hullBoxes[i];
      if (!hull.empty() && (o.maxInfX > box.xmax() || o.minSupX < box.xmin() || o.maxInfY > box.ymax() || o.minSupY < box.ymin())) {
        return false;
      }
      // Every corner's side of every zone edge by intervals, in one upward rounding mode for all
      // (CGAL's unprotected intervals under one Protect_FPU_rounding: a protected interval sets
      // and restores the mode at each operation), then exactly where an interval holds 0.
      thread_local std::vector<std::pair<const Corner*, std::size_t>> undecided;
      undecided.clear();
      {
        CGAL::Protect_FPU_rounding<true> upward;
        for (const Corner& c : o.corners) {
          if (std::binary_search(lines.passed(i).begin(), lines.passed(i).end(), c.vertex)) continue;
          for (std::size_t m = 0; m < hull.size(); ++m) {
            const Point& a = hull[m];
            const Point& b = hull[(m + 1) % hull.size()];
            const Fast det = (Fast(b.x) - a.x) * (c.y - a.y) - (Fast(b.y) - a.y) * (c.x - a.x);
            if (det.inf() > 0) continue;
            if (det.sup() < 0) return false;
            undecided.push_back({&c, m});
          }
        }
      }
      for (const auto& [c, m] : undecided) {
        const Point& a = hull[m];
        const Point& b = hull[(m + 1) % hull.size()];
        if (c->x.is_point() && c->y.is_point()) {  // a double: its side in doubles, exactly
          if (filteredOrientation(a, b, Point{c->x.inf(), c->y.inf()}) < 0) return false;
          continue;
        }
        const auto& exact = CGAL::exact(*c->p);
        if (orientationOfRational(a, b, exact.x().get_mpq_t(), exact.y().get_mpq_t()) < 0) return false;
      }
      return true;
    };
    // Whether a wrong face lies in some zone, asked once: the answers share most of their wrong
    // faces. The same for every answer it is wrong for, as a zone that holds the face lies near
    // it, so among the zones near that answer's wrong faces (runsNear: the zone lies within its
    // run's box widened as there).
    std::unordered_map<const void*, bool> inSomeZone;
    bool anyZone = false;
    std::vector<char> excused(judged.size(), 0), zoneNeeded(near.size(), 0);
    for (std::size_t j = 0; j < judged.size(); ++j) {
      if (judged[j].wrongFaces.empty()) continue;
      const std::vector<char> nearJ = runsNear(lines, judged[j].wrongFaces, k, options.constructionUlps);
      std::size_t zones = 0;
      for (std::size_t i = 0; i < nearJ.size(); ++i) zones += nearJ[i] && zone[i];
      judged[j].v.zones = zones;
      if (zones == 0) continue;
      excused[j] = std::all_of(judged[j].wrongFaces.begin(), judged[j].wrongFaces.end(), [&](Face f) {
        const auto [known, fresh] = inSomeZone.try_emplace(&*f, false);
        if (!fresh) return known->second;
        const Outline o = outlineOf(f);
        for (std::size_t i = 0; i < nearJ.size(); ++i) {
          if (nearJ[i] && zone[i] && inZone(o, i)) return known->second = true;
        }
        return false;
      });
      if (excused[j]) {
        judged[j].rounding = judged[j].wrongFaces;
        continue;
      }
      anyZone = true;
      for (std::size_t i = 0; i < nearJ.size(); ++i) zoneNeeded[i] |= nearJ[i] && zone[i];
    }
    if (anyZone) {
      // The answers not excused so: their wrong regions' boundaries and the zones, each edge once
      // with the answers whose wrong region it bounds (bit j: answer j; an edge shared by several
      // answers' boundaries would otherwise be overlapped in exact arithmetic).
      for (auto e = arr.edges_begin(); e != arr.edges_end(); ++e) {
        unsigned bounds = 0;
        for (std::size_t j = 0; j < judged.size(); ++j) {
          if (judged[j].wrongFaces.empty() || judged[j].v.zones == 0 || excused[j]) continue;
          if (isWrong(answers[j].op, j, e->face()) != isWrong(answers[j].op, j, e->twin()->face())) bounds |= 1u << j;
        }
        if (bounds) curves.emplace_back(e->curve(), Counts{0, 0, bounds, 0});
      }
      for (std::size_t i = 0; i < near.size(); ++i) {  // the zones near an answer not excused whole
        if (zoneNeeded[i]) curves.insert(curves.end(), zoneCurves.begin() + zoneStart[i], zoneCurves.begin() + zoneStart[i + 1]);
      }
      build(curves, zoned);
      for (auto f = zoned.faces_begin(); f != zoned.faces_end(); ++f) {
        if (f->is_unbounded()) continue;
        for (std::size_t j = 0; j < judged.size(); ++j) {
          if (judged[j].v.zones == 0 || excused[j] || !resultInside(f->data().bits, j)) continue;
          (f->data().zones > 0 ? judged[j].rounding : judged[j].beyond).push_back(f);
        }
      }
    }
  }
  const auto end = std::chrono::steady_clock::now();
  const double shared = std::chrono::duration<double>(end - start).count() /
                        static_cast<double>(std::max<std::size_t>(answers.size(), 1));
  std::vector<ExactVerdict> verdicts;
  for (std::size_t j = 0; j < answers.size(); ++j) {
    judged[j].start = end;
    finish(judged[j], arr, answers[j].op, j, options, k);
    verdicts.push_back(judged[j].v);
    verdicts.back().seconds += shared;
  }
  return verdicts;
}

// Everything the arrangement code may throw becomes CannotJudge (with CGAL's checks compiled in,
// see CMakeLists.txt, a violated precondition throws instead of crashing later).
template <class F>
auto judging(F&& f) {
  try {
    return f();
  } catch (const InvalidInput&) {
    throw;
  } catch (const CannotJudge&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw CannotJudge("out of memory building the arrangement");
  } catch (const std::exception& e) {
    throw CannotJudge(std::string("the arrangement failed: ") + e.what());
  }
}

}  // namespace

double ExactVerdict::relativeError() const { return relative; }

double ExactVerdict::relativeBeyondRounding() const { return relativeBeyond; }

std::vector<ExactVerdict> exactCheckAll(const Region& subject, const Region& clip, const std::vector<Answer>& answers,
                                        const ExactOptions& options) {
  if (options.constructionUlps < 1) throw std::invalid_argument("constructionUlps must be at least 1");
  if (answers.size() > kMostAnswers) {
    throw std::invalid_argument("exactCheckAll judges at most " + std::to_string(kMostAnswers) + " answers at once");
  }
  return judging([&] {
    std::vector<const Region*> all{&subject, &clip};
    for (const Answer& a : answers) all.push_back(&a.result);
    const int k = judgingExponent(all);
    if (k == 0) return judge(subject, clip, answers, options, 0);
    std::vector<Answer> scaled;
    for (const Answer& a : answers) scaled.push_back({a.op, scaledBy(a.result, k)});
    std::vector<ExactVerdict> verdicts = judge(scaledBy(subject, k), scaledBy(clip, k), scaled, options, k);
    // Back to the original scale (areas may underflow to 0 or overflow there; the relative error
    // and the verdict were decided at the comfortable scale).
    for (ExactVerdict& v : verdicts) {
      for (double* area : {&v.expectedArea, &v.resultArea, &v.subjectArea, &v.clipArea, &v.boxArea,
                           &v.areaUncertainty, &v.errorArea, &v.beyondRoundingArea}) {
        *area = std::ldexp(*area, -2 * k);
      }
      if (v.witness) v.witness = scaledBy(*v.witness, -k);
      v.expected = scaledBy(v.expected, -k);
      v.wrong = scaledBy(v.wrong, -k);
    }
    return verdicts;
  });
}

ExactVerdict exactCheck(const Region& subject, const Region& clip, Op op, const Region& result,
                        const ExactOptions& options) {
  return exactCheckAll(subject, clip, {{op, result}}, options).front();
}

namespace {

// The symmetric differences of several pairs of regions in one arrangement, at the judging scale
// 2^k: a face's bit i is its parity in pair i's symmetric difference. Both regions of pair i
// carry parity bit i, so a segment that a and b (or one of them twice) share cancels its own bit,
// and a curve left with no bit separates no faces: it is dropped before the sweep. Two answers
// that differ only near a few vertices leave only the slivers there to arrange, and two that
// share every segment none at all.
class SymmetricDifferences {
 public:
  // Asked before the arrangement is tried (judging() turns what it throws into CannotJudge).
  static void requireFewPairs(std::size_t pairs, const char* caller) {
    if (2 * pairs > kMostAnswers) {
      throw std::invalid_argument(std::string(caller) + " compares at most " + std::to_string(kMostAnswers / 2) + " pairs at once");
    }
  }

  explicit SymmetricDifferences(const std::vector<std::pair<Region, Region>>& pairs) : areas_(pairs.size(), Interval(0)) {
    std::vector<const Region*> all;
    for (const auto& [a, b] : pairs) all.push_back(&a), all.push_back(&b);
    k_ = judgingExponent(all);
    std::vector<CountedSegment> segments;
    for (std::size_t i = 0; i < all.size(); ++i) {
      const Region r = normalized(k_ == 0 ? *all[i] : scaledBy(*all[i], k_), OnBadRing::Drop);
      addSegments(r, {0, 0, 1u << (i / 2), 0}, segments);
    }
    std::vector<Traits::Curve_2> curves = mergedCurves(std::move(segments));
    curves.erase(std::remove_if(curves.begin(), curves.end(), [](const Traits::Curve_2& g) { return g.data().r == 0; }),
                 curves.end());
    if (curves.empty()) return;
    build(curves, arr_);
    for (auto f = arr_.faces_begin(); f != arr_.faces_end(); ++f) {
      if (f->is_unbounded()) continue;
      std::optional<Interval> area;
      for (std::size_t i = 0; i < areas_.size(); ++i) {
        if (!resultInside(f->data().bits, i)) continue;
        if (!area) area = faceAreaInterval(f);
        areas_[i] += *area;
      }
    }
  }

  // Pair i's area at the judging scale: certified, and exact.
  const Interval& interval(std::size_t i) const { return areas_[i]; }
  EFT exact(std::size_t i) const {
    EFT sum = 0;
    for (auto f = arr_.faces_begin(); f != arr_.faces_end(); ++f) {
      if (!f->is_unbounded() && resultInside(f->data().bits, i)) sum += faceArea(f);
    }
    return sum;
  }
  int exponent() const { return k_; }

 private:
  int k_ = 0;
  Arrangement arr_;
  std::vector<Interval> areas_;
};

}  // namespace

std::vector<double> symmetricDifferenceAreas(const std::vector<std::pair<Region, Region>>& pairs) {
  SymmetricDifferences::requireFewPairs(pairs.size(), "symmetricDifferenceAreas");
  return judging([&] {
    const SymmetricDifferences d(pairs);
    std::vector<double> out;
    for (std::size_t i = 0; i < pairs.size(); ++i) {
      // A sliver's certified interval can be wider than the sliver (its vertices' products round
      // at the scale of the coordinates): such a pair's area is summed exactly instead.
      const Interval& a = d.interval(i);
      const double area = a.sup() - a.inf() <= kSymmetricDifferenceTightness * a.inf() ? CGAL::to_double(a)
                                                                                        : CGAL::to_double(d.exact(i));
      out.push_back(std::ldexp(area, -2 * d.exponent()));
    }
    return out;
  });
}

std::vector<bool> symmetricDifferencesWithin(const std::vector<std::pair<Region, Region>>& pairs,
                                             const std::vector<double>& limits) {
  if (limits.size() != pairs.size()) throw std::invalid_argument("symmetricDifferencesWithin: one limit per pair");
  for (double limit : limits) {
    if (std::isnan(limit)) throw std::invalid_argument("symmetricDifferencesWithin: a limit is NaN");
  }
  SymmetricDifferences::requireFewPairs(pairs.size(), "symmetricDifferencesWithin");
  // Pairs that differ by slivers within their limits are decided in doubles
  // (difference_bound.h); the arrangement is built for the others only.
  std::vector<bool> within(pairs.size(), true);
  std::vector<std::pair<Region, Region>> undecided;
  std::vector<std::size_t> at;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const std::optional<double> bound = symmetricDifferenceBound(pairs[i].first, pairs[i].second);
    if (bound && *bound <= limits[i]) continue;
    undecided.push_back(pairs[i]);
    at.push_back(i);
  }
  if (undecided.empty()) return within;
  return judging([&] {
    const SymmetricDifferences d(undecided);
    const int k = d.exponent();
    for (std::size_t u = 0; u < undecided.size(); ++u) {
      const std::size_t i = at[u];
      // The interval's ends back at the original scale, when that loses nothing: most pairs are
      // decided there; one whose interval holds the limit is decided in exact arithmetic.
      const Interval& a = d.interval(u);
      const double lo = std::ldexp(a.inf(), -2 * k), hi = std::ldexp(a.sup(), -2 * k);
      const bool exactEnds = std::ldexp(lo, 2 * k) == a.inf() && std::ldexp(hi, 2 * k) == a.sup();
      if (exactEnds && hi <= limits[i]) {
        within[i] = true;
      } else if (exactEnds && lo > limits[i]) {
        within[i] = false;
      } else if (std::isinf(limits[i])) {
        within[i] = limits[i] > 0;
      } else {
        within[i] = d.exact(u) <= EFT(limits[i]) * powerOfTwo(2 * k);
      }
    }
    return within;
  });
}

Region exactAnswer(const Region& subject, const Region& clip, Op op) {
  return judging([&] {
    Arrangement arr;
    build(operandCurves(subject, clip, {}), arr);
    return boundaryRings(arr, [op](Face f) { return expectedInside(op, f->data().bits); });
  });
}

LinedRings exactAnswerLines(const Region& subject, const Region& clip, Op op) {
  return judging([&] {
    Arrangement arr;
    build(operandCurves(subject, clip, {}), arr);
    auto in = [op](Face f) { return expectedInside(op, f->data().bits); };
    auto isBoundary = [&](Halfedge h) { return in(h->face()) && !in(h->twin()->face()); };
    LinedRings out;
    std::map<std::tuple<double, double, double, double>, std::uint32_t> lineIds;
    auto lineOf = [&](Halfedge h) {
      const Counts& c = h->curve().data();
      const auto key = std::make_tuple(c.lineA.x, c.lineA.y, c.lineB.x, c.lineB.y);
      const auto [it, added] = lineIds.emplace(key, static_cast<std::uint32_t>(out.lines.size()));
      if (added) out.lines.push_back({c.lineA, c.lineB});
      return it->second;
    };
    auto collinear = [&](std::uint32_t a, std::uint32_t b) {
      const LinedRings::Line &p = out.lines[a], &q = out.lines[b];
      return a == b || (filteredOrientation(p.from, p.to, q.from) == 0 && filteredOrientation(p.from, p.to, q.to) == 0);
    };
    std::unordered_set<const void*> used;
    for (auto e = arr.halfedges_begin(); e != arr.halfedges_end(); ++e) {
      const Halfedge first = e;
      if (used.count(&*first) || !isBoundary(first)) continue;
      // The ring's halfedges in order, each with its line; then its corners: a vertex where the
      // boundary goes straight on along one line is no corner.
      std::vector<Halfedge> walk;
      Halfedge h = first;
      do {
        used.insert(&*h);
        walk.push_back(h);
        Halfedge next = h->next();
        while (!isBoundary(next)) next = next->twin()->next();
        h = next;
      } while (h != first);
      std::vector<std::uint32_t> lines;
      for (const Halfedge& w : walk) lines.push_back(lineOf(w));
      const std::size_t n = walk.size(), start = out.points.size();
      for (std::size_t k = 0; k < n; ++k) {
        const std::uint32_t in = lines[(k + n - 1) % n], here = lines[k];
        if (collinear(in, here)) continue;
        const KPoint& p = walk[k]->source()->point();
        const Point rounded{nearestDouble(p.x()), nearestDouble(p.y())};
        const bool exact = CGAL::exact(p.x()) == EFT(rounded.x) && CGAL::exact(p.y()) == EFT(rounded.y);
        out.points.push_back(rounded);
        out.exact.push_back(exact);
        out.line.push_back(here);
      }
      if (out.points.size() - start < 3) {
        out.points.resize(start), out.exact.resize(start), out.line.resize(start);
        continue;
      }
      out.ringStart.push_back(static_cast<std::uint32_t>(out.points.size()));
    }
    return out;
  });
}

ExactArea exactArea(const Region& region) {
  return judging([&] {
    Arrangement arr;
    build(operandCurves(region, {}, {}), arr);
    EFT total = 0;
    for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f) {
      if (!f->is_unbounded() && (f->data().bits & kS)) total += faceArea(f);
    }
    return ExactArea{rationalText(total), CGAL::to_double(total)};
  });
}

bool sameExactArea(const Region& a, const Region& b) { return exactArea(a).rational == exactArea(b).rational; }

}  // namespace gh::oracle
