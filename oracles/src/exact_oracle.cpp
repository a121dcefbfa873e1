// The only translation unit that includes CGAL's arrangements (they are slow to compile).
#include "ghoracle/exact_oracle.h"

#include <CGAL/Arr_curve_data_traits_2.h>
#include <CGAL/Arr_extended_dcel.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <set>
#include <sstream>
#include <unordered_map>
#include <vector>

#include "ghclip/validate.h"
#include "ghoracle/tolerance.h"
#include "judging_scale.h"

namespace gh::oracle {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using FT = Kernel::FT;
using KPoint = Kernel::Point_2;
using EFT = Kernel::Exact_kernel::FT;  // exact rationals
using SegmentTraits = CGAL::Arr_segment_traits_2<Kernel>;

// How many segments of S, C and R run along a piece of curve.
struct Counts {
  int s = 0, c = 0, r = 0;
  bool operator==(const Counts& o) const { return s == o.s && c == o.c && r == o.r; }
  int parityBits() const { return (s & 1) | (c & 1) << 1 | (r & 1) << 2; }
};
// Overlapping segments add up their counts.
struct AddCounts {
  Counts operator()(const Counts& a, const Counts& b) const {
    return {a.s + b.s, a.c + b.c, a.r + b.r};
  }
};

using Traits = CGAL::Arr_curve_data_traits_2<SegmentTraits, Counts, AddCounts>;
// Face data: parity bits of S (1), C (2), R (4), and kVisited during propagation.
using Dcel = CGAL::Arr_face_extended_dcel<Traits, int>;
using Arrangement = CGAL::Arrangement_2<Traits, Dcel>;
using Face = Arrangement::Face_const_handle;
using Halfedge = Arrangement::Halfedge_const_handle;

constexpr int kS = 1, kC = 2, kR = 4, kVisited = 8;

void addSegments(const Region& region, Counts counts, std::vector<Traits::Curve_2>& out) {
  for (const Ring& ring : region) {
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
      const Point a = ring[i], b = ring[(i + 1) % n];
      if (a == b) continue;
      out.emplace_back(SegmentTraits::Curve_2(KPoint(a.x, a.y), KPoint(b.x, b.y)), counts);
    }
  }
}

// Parities from the unbounded face outward, across every edge (breadth first).
void propagateParities(Arrangement& arr) {
  for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f) f->set_data(0);
  std::vector<Arrangement::Face_handle> queue{arr.unbounded_face()};
  arr.unbounded_face()->set_data(kVisited);
  for (std::size_t k = 0; k < queue.size(); ++k) {
    const auto f = queue[k];
    auto visit = [&](Arrangement::Ccb_halfedge_circulator first) {
      auto h = first;
      do {
        auto g = h->twin()->face();
        if (!(g->data() & kVisited)) {
          g->set_data(((f->data() ^ h->curve().data().parityBits()) & 7) | kVisited);
          queue.push_back(g);
        }
      } while (++h != first);
    };
    for (auto ccb = f->outer_ccbs_begin(); ccb != f->outer_ccbs_end(); ++ccb) visit(*ccb);
    for (auto ccb = f->inner_ccbs_begin(); ccb != f->inner_ccbs_end(); ++ccb) visit(*ccb);
  }
}

bool expectedInside(Op op, int bits) { return apply(op, bits & kS, bits & kC); }
bool resultInside(int bits) { return bits & kR; }

using Interval = CGAL::Interval_nt<false>;

// Certified interval enclosure of a bounded face's area from the vertices' interval
// approximations, taken relative to one of its vertices: a sliver face then gets an interval
// as small as itself, so its verdict rarely needs exact arithmetic.
Interval faceAreaInterval(Face f) {
  Interval twice = 0;
  const auto& origin = CGAL::approx((*f->outer_ccbs_begin())->source()->point());
  auto add = [&](Arrangement::Ccb_halfedge_const_circulator first) {
    auto h = first;
    do {
      const auto& p = CGAL::approx(h->source()->point());
      const auto& q = CGAL::approx(h->target()->point());
      const Interval px = p.x() - origin.x(), py = p.y() - origin.y();
      const Interval qx = q.x() - origin.x(), qy = q.y() - origin.y();
      twice += px * qy - qx * py;
    } while (++h != first);
  };
  for (auto ccb = f->outer_ccbs_begin(); ccb != f->outer_ccbs_end(); ++ccb) add(*ccb);
  for (auto ccb = f->inner_ccbs_begin(); ccb != f->inner_ccbs_end(); ++ccb) add(*ccb);
  return twice / 2;
}

// Exact area of a bounded face: outer boundary counter-clockwise, holes clockwise. Summed in the
// exact number type: lazy sums would build one large expression tree per face (5x slower).
EFT faceArea(Face f) {
  EFT twice = 0;
  auto add = [&](Arrangement::Ccb_halfedge_const_circulator first) {
    auto h = first;
    do {
      const auto& p = CGAL::exact(h->source()->point());
      const auto& q = CGAL::exact(h->target()->point());
      twice += p.x() * q.y() - q.x() * p.y();
    } while (++h != first);
  };
  for (auto ccb = f->outer_ccbs_begin(); ccb != f->outer_ccbs_end(); ++ccb) add(*ccb);
  for (auto ccb = f->inner_ccbs_begin(); ccb != f->inner_ccbs_end(); ++ccb) add(*ccb);
  return twice / 2;
}

// A point strictly inside face f: on a vertical line between two vertex abscissae (so it meets
// no vertex), the face's boundary edges cut the line into alternating in/out intervals; take
// the middle of the longest inside interval. Edges with f on both sides are skipped.
KPoint pointInside(Face f) {
  std::vector<Halfedge> edges;
  std::vector<FT> xs;
  auto collect = [&](Arrangement::Ccb_halfedge_const_circulator first) {
    auto h = first;
    do {
      xs.push_back(h->source()->point().x());
      if (h->twin()->face() != f) edges.push_back(h);
    } while (++h != first);
  };
  for (auto ccb = f->outer_ccbs_begin(); ccb != f->outer_ccbs_end(); ++ccb) collect(*ccb);
  for (auto ccb = f->inner_ccbs_begin(); ccb != f->inner_ccbs_end(); ++ccb) collect(*ccb);
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

// The boundary of the union of faces where `in` holds, as rings with the region on the left:
// from each boundary halfedge, turn around its target through inside faces to the next one.
template <class In>
Region boundaryRings(const Arrangement& arr, In in) {
  auto isBoundary = [&](Halfedge h) { return in(h->face()) && !in(h->twin()->face()); };
  Region rings;
  std::vector<char> used;
  std::vector<Halfedge> all;
  for (auto h = arr.halfedges_begin(); h != arr.halfedges_end(); ++h) all.push_back(h);
  std::unordered_map<const void*, std::size_t> index;
  for (std::size_t i = 0; i < all.size(); ++i) index[&*all[i]] = i;
  used.assign(all.size(), 0);
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (used[i] || !isBoundary(all[i])) continue;
    Ring ring;
    Halfedge h = all[i];
    do {
      used[index[&*h]] = 1;
      const Point p{CGAL::to_double(h->source()->point().x()),
                    CGAL::to_double(h->source()->point().y())};
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

void build(const Region& s, const Region& c, const Region& r, Arrangement& arr) {
  std::vector<Traits::Curve_2> curves;
  addSegments(normalized(s, OnBadRing::Drop), {1, 0, 0}, curves);
  addSegments(normalized(c, OnBadRing::Drop), {0, 1, 0}, curves);
  addSegments(normalized(r, OnBadRing::Drop), {0, 0, 1}, curves);
  CGAL::insert(arr, curves.begin(), curves.end());
  propagateParities(arr);
}

std::string rationalText(const EFT& v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

namespace {

// errorArea relative to the problem's size (see exact_oracle.h); scale-free, so it is computed
// on the scaled problem, where no area underflows.
double relativeErrorOf(const ExactVerdict& v) {
  double scale = std::max({v.subjectArea, v.clipArea, v.expectedArea, v.resultArea});
  // Operands of zero area (collinear rings) leave no area to compare with: then the size of the
  // problem is its bounding box.
  if (scale <= v.boxArea * 0x1p-40) scale = v.boxArea;
  return scale > 0 ? v.errorArea / scale : (v.errorArea > 0 ? 1.0 : 0.0);
}

// The tolerance for the exact answer's own constructed vertices: each end of a boundary edge of
// op(S, C) that is not an input vertex may move by `displacement` when rounded.
double answerTolerance(const Arrangement& arr, Op op, const Region& subject, const Region& clip, double displacement) {
  std::set<std::pair<double, double>> inputVertices;
  for (const Region* r : {&subject, &clip}) {
    for (const Ring& ring : *r) {
      for (const Point& p : ring) inputVertices.insert({p.x, p.y});
    }
  }
  auto constructed = [&](Arrangement::Vertex_const_handle v) {
    const auto& a = CGAL::approx(v->point());
    if (!a.x().is_point() || !a.y().is_point()) return true;
    return !inputVertices.count({a.x().inf(), a.y().inf()});
  };
  double tolerance = 0;
  for (auto e = arr.edges_begin(); e != arr.edges_end(); ++e) {
    if (expectedInside(op, e->face()->data()) == expectedInside(op, e->twin()->face()->data())) continue;
    const int ends = constructed(e->source()) + constructed(e->target());
    if (ends == 0) continue;
    const auto& a = CGAL::approx(e->source()->point());
    const auto& b = CGAL::approx(e->target()->point());
    const double length = std::hypot(CGAL::to_double(b.x() - a.x()), CGAL::to_double(b.y() - a.y()));
    tolerance += displacement * length / 2 * ends;
  }
  return tolerance;
}

// The judgement proper, on a problem already at a comfortable scale: coordinates were multiplied
// by 2^k (areas by 4^k) and `displacement` is the original's, scaled alike.
ExactVerdict judge(const Region& subject, const Region& clip, Op op, const Region& result,
                   const ExactOptions& options, double displacement, int k) {
  const auto start = std::chrono::steady_clock::now();
  Arrangement arr;
  build(subject, clip, result, arr);

  ExactVerdict v;
  // Expected and result areas: interval sums (exact evaluation of every intersection vertex
  // costs 5-10x more). The error area, which decides the verdict, is summed exactly.
  Interval expected = 0, got = 0, error = 0, areaS = 0, areaC = 0;
  double worst = -1;
  Face worstFace;
  std::vector<Face> wrongFaces;
  for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f) {
    if (f->is_unbounded()) continue;  // outside everything: op(0, 0) = 0 for every op
    const int bits = f->data();
    const bool want = expectedInside(op, bits), have = resultInside(bits);
    if (!want && !have && !(bits & (kS | kC))) continue;
    const auto approxArea = faceAreaInterval(f);
    if (bits & kS) areaS += approxArea;
    if (bits & kC) areaC += approxArea;
    if (want) expected += approxArea;
    if (have) got += approxArea;
    if (want != have) {
      error += approxArea;
      wrongFaces.push_back(f);
      if (CGAL::to_double(approxArea) > worst) worst = CGAL::to_double(approxArea), worstFace = f;
    }
  }
  const bool anyWrong = !wrongFaces.empty();
  v.expectedArea = CGAL::to_double(expected);
  v.resultArea = CGAL::to_double(got);
  v.subjectArea = CGAL::to_double(areaS);
  v.clipArea = CGAL::to_double(areaC);
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
  v.boxArea = (maxX / 2 - minX / 2) * (maxY / 2 - minY / 2) * 4;
  v.areaUncertainty = std::max(expected.sup() - expected.inf(), got.sup() - got.inf());
  v.errorArea = CGAL::to_double(error);
  v.tolerance = roundingTolerance(subject, clip, result, displacement) +
                answerTolerance(arr, op, subject, clip, displacement);
  // The verdict is certified: by the interval when it lies on one side of the tolerance,
  // else by the exact sum.
  const bool undecided = error.inf() <= v.tolerance && v.tolerance < error.sup();
  if (undecided || options.exactErrorArea) {
    EFT exact = 0;
    for (Face f : wrongFaces) exact += faceArea(f);
    v.errorArea = CGAL::to_double(exact);
    EFT original = exact;
    const EFT factor = k > 0 ? EFT(0.5) : EFT(2);
    for (int i = 0; i < 2 * std::abs(k); ++i) original *= factor;
    v.errorAreaExact = rationalText(original);
    v.pass = exact <= EFT(v.tolerance);
  } else {
    v.pass = error.sup() <= v.tolerance;
  }
  if (anyWrong) {
    const KPoint w = pointInside(worstFace);
    v.witness = Point{CGAL::to_double(w.x()), CGAL::to_double(w.y())};
  }
  if (options.wantExpectedRings) {
    v.expected = boundaryRings(arr, [op](Face f) { return expectedInside(op, f->data()); });
  }
  if (options.wantWrongRings && anyWrong) {
    v.wrong = boundaryRings(arr, [op](Face f) {
      return expectedInside(op, f->data()) != resultInside(f->data());
    });
  }
  v.faces = arr.number_of_faces();
  v.vertices = arr.number_of_vertices();
  v.edges = arr.number_of_edges();
  v.relative = relativeErrorOf(v);
  v.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return v;
}

}  // namespace

double ExactVerdict::relativeError() const { return relative; }

ExactVerdict exactCheck(const Region& subject, const Region& clip, Op op, const Region& result,
                        const ExactOptions& options) {
  const double displacement = constructionDisplacement(subject, clip, result);
  const int k = judgingExponent(subject, clip, result);
  if (k == 0) return judge(subject, clip, op, result, options, displacement, 0);
  ExactVerdict v = judge(scaledBy(subject, k), scaledBy(clip, k), op, scaledBy(result, k), options,
                         std::ldexp(displacement, k), k);
  // Back to the original scale (areas may underflow to 0 or overflow there; the relative error
  // and the verdict were decided at the comfortable scale).
  for (double* area : {&v.expectedArea, &v.resultArea, &v.subjectArea, &v.clipArea, &v.boxArea,
                       &v.areaUncertainty, &v.errorArea, &v.tolerance}) {
    *area = std::ldexp(*area, -2 * k);
  }
  if (v.witness) v.witness = scaledBy(*v.witness, -k);
  v.expected = scaledBy(v.expected, -k);
  v.wrong = scaledBy(v.wrong, -k);
  return v;
}

Region exactAnswer(const Region& subject, const Region& clip, Op op) {
  Arrangement arr;
  build(subject, clip, {}, arr);
  return boundaryRings(arr, [op](Face f) { return expectedInside(op, f->data()); });
}

}  // namespace gh::oracle
