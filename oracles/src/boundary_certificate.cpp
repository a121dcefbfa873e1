#include "ghoracle/boundary_certificate.h"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <tuple>

#include "filtered_orientation.h"
#include "judging_scale.h"
#include "line_distance.h"
#include "point_table.h"
#include "ulp.h"

namespace gh::oracle {
namespace {

struct Edge {
  Point a, b;
};

// The edges of a region ring by ring (zero-length ones left out: they bound nothing), with where
// each ring's run starts.
struct Edges {
  std::vector<Edge> edges;
  std::vector<std::size_t> ringStart;  // ring r's edges: [ringStart[r], ringStart[r + 1])
  explicit Edges(const Region& region) {
    for (const Ring& ring : region) {
      ringStart.push_back(edges.size());
      for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
        if (!(ring[i] == ring[(i + 1) % n])) edges.push_back({ring[i], ring[(i + 1) % n]});
      }
    }
    ringStart.push_back(edges.size());
  }
};

bool finite(const Region& region) {
  return std::all_of(region.begin(), region.end(), [](const Ring& ring) {
    return std::all_of(ring.begin(), ring.end(), [](const Point& p) { return std::isfinite(p.x) && std::isfinite(p.y); });
  });
}

// C is translated by delta = (eps, eps^2), eps -> 0+. Where (b - a) x (p - a) is 0, its sign is
// that of the first term of the translation's that is not: with p translated (a, b on S),
// (b - a) x delta = (b.x - a.x) eps^2 - (b.y - a.y) eps; with a and b translated, its negative.
// a != b, so one of the terms is not 0.
int pointShifted(int unshifted, Point a, Point b) {
  if (unshifted != 0) return unshifted;
  if (b.y != a.y) return b.y > a.y ? -1 : 1;
  return b.x > a.x ? 1 : -1;
}
int lineShifted(int unshifted, Point a, Point b) { return unshifted != 0 ? unshifted : -pointShifted(0, a, b); }

// The parity of C (translated) at a point p of S, which lies on none of its edges: the edges
// crossed by the ray from p towards +x (an end at p's height, raised by eps^2, lies above it).
bool parityOfShifted(const std::vector<Edge>& clip, Point p) {
  bool in = false;
  for (const Edge& f : clip) {
    const bool aAbove = f.a.y >= p.y, bAbove = f.b.y >= p.y;
    if (aAbove == bAbove || std::max(f.a.x, f.b.x) < p.x) continue;
    const Point lo = aAbove ? f.b : f.a, hi = aAbove ? f.a : f.b;
    if (lineShifted(filteredOrientation(lo, hi, p), lo, hi) > 0) in = !in;  // p left of the upward edge
  }
  return in;
}

// The parity of S at a point p of C, translated (an end of S at p's height lies below it).
bool parityAtShifted(const std::vector<Edge>& subject, Point p) {
  bool in = false;
  for (const Edge& e : subject) {
    const bool aAbove = e.a.y > p.y, bAbove = e.b.y > p.y;
    if (aAbove == bAbove || std::max(e.a.x, e.b.x) < p.x) continue;
    const Point lo = aAbove ? e.b : e.a, hi = aAbove ? e.a : e.b;
    if (pointShifted(filteredOrientation(lo, hi, p), lo, hi) > 0) in = !in;
  }
  return in;
}

// A piece's end: a double point, or (symbolic >= 0) a crossing the answers' vertices did not
// resolve, which matches no vertex of an answer.
struct Key {
  double x, y;
  std::int64_t symbolic;
  static Key at(Point p) { return {p.x, p.y, -1}; }
  bool operator==(const Key& o) const { return symbolic == o.symbolic && x == o.x && y == o.y; }
  bool operator<(const Key& o) const { return std::tie(symbolic, x, y) < std::tie(o.symbolic, o.x, o.y); }
  Point point() const { return {x, y}; }
};

// A segment with its ends in order, so that a segment and its reverse are one.
struct Piece {
  Key u, v;
  Piece(Key a, Key b) : u(std::min(a, b)), v(std::max(a, b)) {}
};

// A crossing on an edge g = (p, q) of one operand with an edge h of the other, where it lies as
// eps -> 0: a double point on g (an end of g or of h), or a point inside both, which lies on p's
// side of h's line before it and on the other side after.
struct OnEdge {
  Edge h;
  bool interior;
  Point at;              // !interior
  int startSide;         // interior: the side of h's line p lies on (1 or -1)
  std::size_t crossing;  // interior: its index among the interior crossings
  double lo = 1, hi = 0; // interior: bounds on where along the edge it lies (parameterBounds)
  mutable std::shared_ptr<mpq_class> t;  // interior: exactly, once asked for
};

// (b - a) x (p - a), exactly.
mpq_class determinant(Point a, Point b, Point p) {
  return (mpq_class(b.x) - a.x) * (mpq_class(p.y) - a.y) - (mpq_class(b.y) - a.y) * (mpq_class(p.x) - a.x);
}

// Where along g the interior crossing with h lies, t in (0, 1), as an interval that holds it, or
// an empty one (lo > hi) when doubles cannot bound it. t = |Da| / (|Da| + |Db|) for the
// determinants of g's ends against h's line, which have opposite signs; it grows with |Da| and
// falls with |Db|, so bounds on them bound it (an end of g almost on h's line gives t near 0 or 1).
std::pair<double, double> parameterBounds(Edge g, Edge h) {
  auto det = [&](Point p, double& error) {
    const double l = (h.b.x - h.a.x) * (p.y - h.a.y), r = (h.b.y - h.a.y) * (p.x - h.a.x);
    error = kOrientationErrorFactor * (std::abs(l) + std::abs(r));
    if (!(std::abs(l) + std::abs(r) > 0x1p-900)) error = std::numeric_limits<double>::infinity();
    return std::abs(l - r);
  };
  double ea, eb;
  const double a = det(g.a, ea), b = det(g.b, eb);
  if (!(std::isfinite(a) && std::isfinite(b) && std::isfinite(ea) && std::isfinite(eb))) return {1, 0};
  const double aLo = std::max(a - ea, 0.0), aHi = a + ea, bLo = std::max(b - eb, 0.0), bHi = b + eb;
  const double lo = aLo > 0 ? aLo / (aLo + bHi) * (1 - 0x1p-49) : 0.0;
  const double hi = bLo > 0 ? aHi / (aHi + bLo) * (1 + 0x1p-49) : 1.0;
  return {lo, std::min(hi, 1.0)};
}

// Where along g the interior crossing x lies, exactly (computed once).
const mpq_class& exactParameter(Edge g, const OnEdge& x) {
  if (!x.t) {
    const mpq_class da = determinant(x.h.a, x.h.b, g.a), db = determinant(x.h.a, x.h.b, g.b);
    x.t = std::make_shared<mpq_class>(da / (da - db));
  }
  return *x.t;
}

// The crossing of e and f (lines that meet inside both) when it is a double: computed along each
// in doubles, and kept when on both lines exactly.
std::optional<Point> doubleCrossing(Edge e, Edge f) {
  for (int k = 0; k < 2; ++k) {
    const Edge g = k == 0 ? e : f, h = k == 0 ? f : e;
    const double da = (h.b.x - h.a.x) * (g.a.y - h.a.y) - (h.b.y - h.a.y) * (g.a.x - h.a.x);
    const double db = (h.b.x - h.a.x) * (g.b.y - h.a.y) - (h.b.y - h.a.y) * (g.b.x - h.a.x);
    const double t = da / (da - db);
    const Point p{g.a.x + t * (g.b.x - g.a.x), g.a.y + t * (g.b.y - g.a.y)};
    if (std::isfinite(p.x) && std::isfinite(p.y) && filteredOrientation(e.a, e.b, p) == 0 && filteredOrientation(f.a, f.b, p) == 0) {
      return Point{p.x + 0.0, p.y + 0.0};
    }
  }
  return std::nullopt;
}

// The order along g of its interior crossings with h1 and h2, in 128-bit integers, when every
// coordinate is an integer times one power of two within 28 bits of the others (grids): t1 < t2
// exactly when |Da1| |Db2| < |Da2| |Db1| for the determinants of g's ends against each line
// (below 2^59 each, so the products and their difference fit).
std::optional<int> smallIntegerOrder(Edge g, Edge h1, Edge h2) {
  const double values[] = {g.a.x, g.a.y, g.b.x, g.b.y, h1.a.x, h1.a.y, h1.b.x, h1.b.y, h2.a.x, h2.a.y, h2.b.x, h2.b.y};
  int high = std::numeric_limits<int>::min(), low = std::numeric_limits<int>::max();
  for (const double v : values) {
    if (v == 0) continue;
    int e;
    const double m = std::frexp(v, &e);  // v = m 2^e, 0.5 <= |m| < 1
    auto bits = static_cast<std::int64_t>(std::ldexp(std::abs(m), 53));  // exact: 53 significant bits
    int trailing = 0;
    while (bits != 0 && (bits & 1) == 0) bits >>= 1, ++trailing;
    high = std::max(high, e), low = std::min(low, e - 53 + trailing);
  }
  if (high == std::numeric_limits<int>::min()) return 0;  // all zero: cannot happen for crossings
  if (high - low > 28) return std::nullopt;
  auto integer = [&](double v) { return static_cast<std::int64_t>(std::ldexp(v, -low)); };  // exact
  using Wide = __int128;
  auto det = [&](Edge h, Point p) {
    const std::int64_t hx = integer(h.b.x) - integer(h.a.x), hy = integer(h.b.y) - integer(h.a.y);
    const std::int64_t px = integer(p.x) - integer(h.a.x), py = integer(p.y) - integer(h.a.y);
    const Wide d = Wide(hx) * py - Wide(hy) * px;
    return d < 0 ? -d : d;
  };
  const Wide a1 = det(h1, g.a), b1 = det(h1, g.b), a2 = det(h2, g.a), b2 = det(h2, g.b);
  const Wide left = a1 * b2, right = a2 * b1;
  return left < right ? -1 : left > right ? 1 : 0;
}

// The order along g of two crossings on it: -1 (x first), 0 (one point) or 1, exactly.
int compareAlong(Edge g, const OnEdge& x, const OnEdge& y) {
  if (!x.interior && !y.interior) {
    if (x.at.x == y.at.x && x.at.y == y.at.y) return 0;
    // Both on g's line: ordered along an axis on which g's ends differ.
    const bool byX = g.a.x != g.b.x;
    const double u = byX ? x.at.x : x.at.y, w = byX ? y.at.x : y.at.y, forward = byX ? g.b.x - g.a.x : g.b.y - g.a.y;
    return (u < w) == (forward > 0) ? -1 : 1;
  }
  if (!x.interior) {  // a point on g is before y when it lies on g's start's side of y's other line
    const int side = filteredOrientation(y.h.a, y.h.b, x.at);
    return side == 0 ? 0 : (side == y.startSide ? -1 : 1);
  }
  if (!y.interior) return -compareAlong(g, y, x);
  if (x.lo <= x.hi && y.lo <= y.hi) {
    if (x.hi < y.lo) return -1;
    if (y.hi < x.lo) return 1;
  }
  // The other edges on one line (an edge doubled back, overlapping edges) cross g at one point.
  if (filteredOrientation(x.h.a, x.h.b, y.h.a) == 0 && filteredOrientation(x.h.a, x.h.b, y.h.b) == 0) return 0;
  // Other edges with an end p in common (consecutive edges of a ring), which lies off g's line:
  // the crossings are p + s (q - p) with s in (0, 1) for their other ends q, so their order along
  // g, seen from p, is that of q1 and q2: first where (q1 - p) x (q2 - p) has the sign of p's side
  // of g.
  for (const Point p : {x.h.a, x.h.b}) {
    if (!(p == y.h.a) && !(p == y.h.b)) continue;
    const Point q1 = p == x.h.a ? x.h.b : x.h.a, q2 = p == y.h.a ? y.h.b : y.h.a;
    const int turn = filteredOrientation(p, q1, q2);
    if (turn == 0) return 0;
    return turn == filteredOrientation(g.a, g.b, p) ? -1 : 1;
  }
  if (const auto order = smallIntegerOrder(g, x.h, y.h)) return *order;
  const int order = cmp(exactParameter(g, x), exactParameter(g, y));
  return order < 0 ? -1 : order > 0 ? 1 : 0;
}

double magnitude(Edge e) { return std::max({std::abs(e.a.x), std::abs(e.a.y), std::abs(e.b.x), std::abs(e.b.y)}); }
bool inBox(Edge e, Point p) {
  return p.x >= std::min(e.a.x, e.b.x) && p.x <= std::max(e.a.x, e.b.x) && p.y >= std::min(e.a.y, e.b.y) &&
         p.y <= std::max(e.a.y, e.b.y);
}

// Whether every key occurs an even number of times among ends (sorted here).
bool eachMetEvenly(std::vector<Key>& ends) {
  std::sort(ends.begin(), ends.end());
  for (std::size_t k = 0; k < ends.size();) {
    std::size_t m = k;
    while (m < ends.size() && ends[m] == ends[k]) ++m;
    if ((m - k) % 2 != 0) return false;
    k = m;
  }
  return true;
}

// The pieces left after equal ones cancelled that cancel on their lines too: on each line, every
// end met an even number of times (marked in `gone`).
void cancelOnLines(const std::vector<Piece>& rest, std::vector<char>& gone) {
  std::vector<char> grouped(rest.size(), 0);
  std::vector<std::size_t> group;
  std::vector<Key> ends;
  gone.assign(rest.size(), 0);
  for (std::size_t i = 0; i < rest.size(); ++i) {
    if (grouped[i]) continue;
    const Point a = rest[i].u.point(), b = rest[i].v.point();
    group.clear(), ends.clear();
    for (std::size_t j = i; j < rest.size(); ++j) {
      if (grouped[j] || filteredOrientation(a, b, rest[j].u.point()) != 0 || filteredOrientation(a, b, rest[j].v.point()) != 0) continue;
      grouped[j] = 1;
      group.push_back(j);
      ends.push_back(rest[j].u), ends.push_back(rest[j].v);
    }
    if (eachMetEvenly(ends)) {
      for (std::size_t j : group) gone[j] = 1;
    }
  }
}

// The certificate's work on one S and C: the crossings, the pieces with their parities, and each
// interior crossing's possible roundings among the answers' vertices.
class Certifier {
 public:
  Certifier(const Region& subject, const Region& clip, const std::vector<std::pair<Op, const Region*>>& answers)
      : s_(subject), c_(clip), answers_(answers), onS_(s_.edges.size()), onC_(c_.edges.size()) {
    findCrossings();
    nearS_.assign(s_.edges.size(), 0), nearC_.assign(c_.edges.size(), 0);
    for (const Interior& k : interiors_) {
      nearS_[k.e] = std::max(nearS_[k.e], k.near), nearC_[k.f] = std::max(nearC_[k.f], k.near);
    }
    gatherVertices();
    for (std::size_t k = 0; k < interiors_.size(); ++k) findCandidates(k);
    parent_.resize(interiors_.size());
    for (std::size_t k = 0; k < parent_.size(); ++k) parent_[k] = k;
    pointOf_.assign(interiors_.size(), std::nullopt);
    groupEnds_.resize(s_.edges.size() + c_.edges.size());
    exact_.resize(interiors_.size());
    sortAlong(s_, onS_, 0);
    sortAlong(c_, onC_, s_.edges.size());
    cut(s_, onS_, 0, true);
    cut(c_, onC_, s_.edges.size(), false);
  }

  // Per answer, whether certified: first with each crossing's end chosen among every answer's
  // vertices; an answer that fails where some crossing had several is tried again with the
  // choice among its own vertices (each answer is its own proof: any rounding that satisfies the
  // bounds may stand for a crossing in it).
  std::vector<bool> certify() {
    std::vector<bool> certified(answers_.size(), false);
    constexpr std::size_t kMostAnswers = 64;
    if (answers_.size() > kMostAnswers) return certified;
    const std::vector<Key> keys = chooseKeys(nullptr);
    const std::vector<bool> first = compare(keys, answers_.size() == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << answers_.size()) - 1);
    for (std::size_t k = 0; k < answers_.size(); ++k) {
      certified[k] = first[k];
      if (certified[k] || !ambiguous_) continue;
      std::vector<Point> own;
      for (const Ring& ring : *answers_[k].second) own.insert(own.end(), ring.begin(), ring.end());
      std::sort(own.begin(), own.end(), byXY);
      certified[k] = compare(chooseKeys(&own), std::uint64_t{1} << k)[k];
    }
    return certified;
  }

 private:
  struct Interior {
    std::size_t e, f;        // its edges of S and C
    double lo, hi;           // where along e it lies (parameterBounds)
    double near;             // 2 ulps of its magnitude (bounded by both edges')
    double boundE, boundF;   // near times each edge's length: lineDistanceAtMost's bounds
  };
  // A piece's end: an end of its edge, or a crossing on it.
  struct End {
    bool interior;
    Point at;              // !interior: a double point
    std::size_t crossing;  // interior: its index
  };
  struct Side {
    End from, to;
    bool otherParity;  // C's along a piece of S, S's along a piece of C
    bool ofSubject;
  };

  static bool byXY(Point p, Point q) { return p.x < q.x || (p.x == q.x && p.y < q.y); }

  void findCrossings() {
    for (std::size_t i = 0; i < s_.edges.size(); ++i) {
      const Edge e = s_.edges[i];
      for (std::size_t j = 0; j < c_.edges.size(); ++j) {
        const Edge f = c_.edges[j];
        if (std::max(e.a.x, e.b.x) < std::min(f.a.x, f.b.x) || std::max(f.a.x, f.b.x) < std::min(e.a.x, e.b.x) ||
            std::max(e.a.y, e.b.y) < std::min(f.a.y, f.b.y) || std::max(f.a.y, f.b.y) < std::min(e.a.y, e.b.y)) {
          continue;
        }
        const int dc = filteredOrientation(e.a, e.b, f.a), dd = filteredOrientation(e.a, e.b, f.b);
        if (pointShifted(dc, e.a, e.b) == pointShifted(dd, e.a, e.b)) continue;
        const int da = filteredOrientation(f.a, f.b, e.a), db = filteredOrientation(f.a, f.b, e.b);
        if (lineShifted(da, f.a, f.b) == lineShifted(db, f.a, f.b)) continue;
        // They cross; not parallel (parallel edges, translated, never do), so where the lines
        // meet is the limit: an end of either when it lies on the other's line.
        std::optional<Point> exactly;  // where the crossing is a double (grids: often)
        if (da == 0 || db == 0 || dc == 0 || dd == 0) {
          exactly = da == 0 ? e.a : db == 0 ? e.b : dc == 0 ? f.a : f.b;
        } else {
          exactly = doubleCrossing(e, f);
        }
        if (exactly) {
          const Point at = *exactly;
          onS_[i].push_back({f, false, at, 0, 0, 1, 0, nullptr});
          onC_[j].push_back({e, false, at, 0, 0, 1, 0, nullptr});
        } else {
          const auto [elo, ehi] = parameterBounds(e, f);
          const auto [flo, fhi] = parameterBounds(f, e);
          onS_[i].push_back({f, true, {}, da, interiors_.size(), elo, ehi, nullptr});
          onC_[j].push_back({e, true, {}, dc, interiors_.size(), flo, fhi, nullptr});
          const double near = 2 * ulpOf(std::min(magnitude(e), magnitude(f)));
          interiors_.push_back({i, j, elo, ehi, near, near * std::hypot(e.b.x - e.a.x, e.b.y - e.a.y),
                                near * std::hypot(f.b.x - f.a.x, f.b.y - f.a.y)});
        }
      }
    }
  }

  void gatherVertices() {
    for (const Edges* own : {&s_, &c_}) {
      for (const Edge& e : own->edges) claimed_.push_back(e.a);
    }
    std::sort(claimed_.begin(), claimed_.end(), byXY);
    PointTable<char> seen;  // the answers share most vertices
    for (const auto& [op, answer] : answers_) {
      for (const Ring& ring : *answer) {
        for (const Point& p : ring) {
          if (seen.findOrAdd(p).second) vertices_.push_back(p);
        }
      }
    }
    std::sort(vertices_.begin(), vertices_.end(), byXY);
  }

  // Whether p may stand for interior crossing k: in both edges' boxes, within 2 ulps (of the
  // crossing's magnitude, which both edges' bound) of both lines.
  bool rounds(std::size_t k, Point p) const {
    const Interior& x = interiors_[k];
    const Edge e = s_.edges[x.e], f = c_.edges[x.f];
    return std::isfinite(x.boundE) && std::isfinite(x.boundF) && inBox(e, p) && inBox(f, p) &&
           lineDistanceAtMost(e.a, e.b, p, x.boundE) && lineDistanceAtMost(f.a, f.b, p, x.boundF);
  }

  // The answers' vertices that may stand for interior crossing k (at most kMostCandidates), found
  // among those whose x lies where the crossing's can (sorted by x).
  void findCandidates(std::size_t k) {
    constexpr std::size_t kMostCandidates = 8;
    const Edge e = s_.edges[interiors_[k].e], f = c_.edges[interiors_[k].f];
    double x0 = std::max(std::min(e.a.x, e.b.x), std::min(f.a.x, f.b.x));
    double x1 = std::min(std::max(e.a.x, e.b.x), std::max(f.a.x, f.b.x));
    // Narrowed to where along e the crossing lies, widened by far more than its rounding (a
    // rounding within 2 ulps of both lines lies near the crossing unless the lines are almost
    // parallel, and then the bounds on where it lies are wide too).
    const double lo = interiors_[k].lo, hi = interiors_[k].hi;
    if (lo <= hi) {
      const double u = e.a.x + lo * (e.b.x - e.a.x), w = e.a.x + hi * (e.b.x - e.a.x);
      const double slack = 64 * ulpOf(magnitude(e)) + 64 * std::abs(hi - lo) * std::abs(e.b.x - e.a.x);
      if (std::isfinite(slack)) x0 = std::max(x0, std::min(u, w) - slack), x1 = std::min(x1, std::max(u, w) + slack);
    }
    candidateStart_.push_back(candidates_.size());
    auto it = std::lower_bound(vertices_.begin(), vertices_.end(), x0, [](Point p, double x) { return p.x < x; });
    for (std::size_t n = 0; it != vertices_.end() && it->x <= x1 && n < kMostCandidates; ++it) {
      if (rounds(k, *it)) candidates_.push_back(*it), ++n;
    }
    ambiguous_ |= candidates_.size() - candidateStart_.back() > 1;
  }

  // Interior crossing k, exactly (computed once).
  const std::pair<mpq_class, mpq_class>& exactPoint(std::size_t k) {
    if (!exact_[k]) {
      const Edge e = s_.edges[interiors_[k].e], f = c_.edges[interiors_[k].f];
      const mpq_class da = determinant(f.a, f.b, e.a), db = determinant(f.a, f.b, e.b), t = da / (da - db);
      exact_[k] = std::make_unique<std::pair<mpq_class, mpq_class>>(mpq_class(e.a.x) + t * (mpq_class(e.b.x) - e.a.x),
                                                                   mpq_class(e.a.y) + t * (mpq_class(e.b.y) - e.a.y));
    }
    return *exact_[k];
  }

  std::pair<const Point*, const Point*> candidatesOf(std::size_t k) const {
    return {candidates_.data() + candidateStart_[k],
            candidates_.data() + (k + 1 < interiors_.size() ? candidateStart_[k + 1] : candidates_.size())};
  }

  // Of the candidates, the nearest to interior crossing k as computed in doubles (from the nearer
  // end of its edge of S): any candidate is as sound, and one that is not the answers' rounding of
  // k leaves slivers that thin() accepts or a sampling that judges.
  Point nearest(std::size_t k, const std::vector<Point>& candidates) const {
    if (candidates.size() == 1) return candidates.front();
    const Edge e = s_.edges[interiors_[k].e], f = c_.edges[interiors_[k].f];
    const double da = std::abs((f.b.x - f.a.x) * (e.a.y - f.a.y) - (f.b.y - f.a.y) * (e.a.x - f.a.x));
    const double db = std::abs((f.b.x - f.a.x) * (e.b.y - f.a.y) - (f.b.y - f.a.y) * (e.b.x - f.a.x));
    const double t = da / (da + db), u = db / (da + db);
    const Point x = t <= 0.5 ? Point{e.a.x + t * (e.b.x - e.a.x), e.a.y + t * (e.b.y - e.a.y)}
                             : Point{e.b.x + u * (e.a.x - e.b.x), e.b.y + u * (e.a.y - e.b.y)};
    Point chosen = candidates.front();
    double best = std::numeric_limits<double>::infinity();
    for (const Point& c : candidates) {
      const double d = std::max(std::abs(c.x - x.x), std::abs(c.y - x.y));
      if (d < best) best = d, chosen = c;
    }
    return chosen;
  }

  // Sorts each edge's crossings along it, and joins crossings tied at one point into one class
  // (union-find), noting a double point one of them is.
  void sortAlong(const Edges& own, std::vector<std::vector<OnEdge>>& on, std::size_t offset) {
    for (std::size_t i = 0; i < own.edges.size(); ++i) {
      const Edge g = own.edges[i];
      std::vector<OnEdge>& crossings = on[i];
      std::sort(crossings.begin(), crossings.end(), [&](const OnEdge& x, const OnEdge& y) { return compareAlong(g, x, y) < 0; });
      for (std::size_t k = 0; k < crossings.size();) {
        std::size_t m = k + 1;
        while (m < crossings.size() && compareAlong(g, crossings[k], crossings[m]) == 0) ++m;
        groupEnds_[offset + i].push_back(m);
        std::optional<Point> point;
        std::optional<std::size_t> first;
        for (std::size_t n = k; n < m; ++n) {
          if (!crossings[n].interior) point = crossings[n].at;
        }
        for (std::size_t n = k; n < m; ++n) {
          if (!crossings[n].interior) continue;
          const std::size_t x = crossings[n].crossing;
          if (point) pointOf_[x] = point;
          if (first) parent_[root(x)] = root(*first);
          first = x;
        }
        k = m;
      }
    }
  }
  std::size_t root(std::size_t k) {
    while (parent_[k] != k) k = parent_[k] = parent_[parent_[k]];
    return k;
  }

  // The pieces of every edge, each with the other operand's parity along it: one ray test at each
  // ring's first vertex, a flip at every crossing (the edges of a ring join end to start).
  void cut(const Edges& own, const std::vector<std::vector<OnEdge>>& on, std::size_t offset, bool ofSubject) {
    for (std::size_t r = 0; r + 1 < own.ringStart.size(); ++r) {
      if (own.ringStart[r] == own.ringStart[r + 1]) continue;
      const Point start = own.edges[own.ringStart[r]].a;
      bool parity = ofSubject ? parityOfShifted(c_.edges, start) : parityAtShifted(s_.edges, start);
      for (std::size_t i = own.ringStart[r]; i < own.ringStart[r + 1]; ++i) {
        const Edge g = own.edges[i];
        const std::vector<OnEdge>& crossings = on[i];
        End from{false, g.a, 0};
        std::size_t k = 0;
        for (const std::size_t m : groupEnds_[offset + i]) {
          // An even number of crossings at a point no answer has a vertex near (edges of the other
          // operand through it in pairs, like an edge doubled back): the pieces on either side
          // are one (op is the same on both), and the answers run straight through.
          bool unseen = (m - k) % 2 == 0;
          for (std::size_t n = k; n < m && unseen; ++n) {
            unseen = crossings[n].interior && candidatesOf(crossings[n].crossing).first == candidatesOf(crossings[n].crossing).second;
          }
          if (unseen) {
            k = m;
            continue;
          }
          const End at{crossings[k].interior, crossings[k].at, crossings[k].crossing};
          pieces_.push_back({from, at, parity, ofSubject});
          parity ^= ((m - k) % 2 != 0);
          from = at, k = m;
        }
        pieces_.push_back({from, End{false, g.b, 0}, parity, ofSubject});
      }
    }
  }

  // Each interior crossing's end: the double point it is, where it is one; else one rounding for
  // its whole class (a candidate of one of them, among `among` when given, the nearest to it
  // where several, which is also a rounding of each other member: checked as for its own), else one
  // symbolic end for the class.
  std::vector<Key> chooseKeys(const std::vector<Point>* among) {
    const std::size_t n = interiors_.size();
    std::vector<Key> own(n);
    // Each crossing's candidates (among `among`): one that no vertex of S or C claims is taken;
    // several such are settled below, by clusters; only claimed ones, the nearest of them.
    std::vector<std::vector<Point>> open(n);
    for (std::size_t k = 0; k < n; ++k) {
      own[k] = Key{0, 0, static_cast<std::int64_t>(root(k))};
      if (pointOf_[k]) {
        own[k] = Key::at(*pointOf_[k]);
        continue;
      }
      const auto [first, last] = candidatesOf(k);
      std::vector<Point> claimed;
      for (const Point* p = first; p != last; ++p) {
        if (among && !std::binary_search(among->begin(), among->end(), *p, byXY)) continue;
        (std::binary_search(claimed_.begin(), claimed_.end(), *p, byXY) ? claimed : open[k]).push_back(*p);
      }
      if (open[k].size() == 1) {
        own[k] = Key::at(open[k].front());
        open[k].clear();
      } else if (open[k].empty() && !claimed.empty()) {
        own[k] = Key::at(nearest(k, claimed));
      }
    }
    // Crossings a few ulps apart (of nearly coincident edges) share candidates: a cluster of
    // crossings (one per point) that have, together, as many candidates takes them in the same
    // order (by x, then y: the answers' roundings keep the crossings' order), where each is one of
    // its own; otherwise each takes its nearest.
    std::vector<char> settled(n, 0);
    for (std::size_t k = 0; k < n; ++k) {
      if (open[k].empty() || settled[k]) continue;
      std::vector<std::size_t> cluster{k};
      std::vector<Point> points(open[k]);
      settled[k] = 1;
      for (bool grown = true; grown;) {
        grown = false;
        for (std::size_t j = 0; j < n; ++j) {
          if (open[j].empty() || settled[j]) continue;
          const bool shares = std::any_of(open[j].begin(), open[j].end(), [&](Point p) {
            return std::find(points.begin(), points.end(), p) != points.end();
          });
          if (!shares) continue;
          settled[j] = 1, grown = true;
          if (std::none_of(cluster.begin(), cluster.end(), [&](std::size_t i) { return root(i) == root(j); })) cluster.push_back(j);
          for (Point p : open[j]) {
            if (std::find(points.begin(), points.end(), p) == points.end()) points.push_back(p);
          }
        }
      }
      // Each its nearest, unless two of them take one point.
      std::vector<Point> near;
      for (std::size_t i : cluster) near.push_back(nearest(i, open[i]));
      std::sort(near.begin(), near.end(), byXY);
      const bool collide = std::adjacent_find(near.begin(), near.end(), [](Point p, Point q) { return p.x == q.x && p.y == q.y; }) != near.end();
      bool inOrder = collide && cluster.size() == points.size();
      if (inOrder) {
        std::sort(points.begin(), points.end(), byXY);
        std::sort(cluster.begin(), cluster.end(), [&](std::size_t a, std::size_t b) {
          const auto& [ax, ay] = exactPoint(a);
          const auto& [bx, by] = exactPoint(b);
          return ax < bx || (ax == bx && ay < by);
        });
        for (std::size_t i = 0; i < cluster.size() && inOrder; ++i) {
          inOrder = std::find(open[cluster[i]].begin(), open[cluster[i]].end(), points[i]) != open[cluster[i]].end();
        }
      }
      for (std::size_t i = 0; i < cluster.size(); ++i) {
        own[cluster[i]] = Key::at(inOrder ? points[i] : nearest(cluster[i], open[cluster[i]]));
      }
      // The other members of a class (the same point) follow through classKey below.
    }
    std::vector<Key> classKey(n, Key{0, 0, -2});  // -2: none yet
    for (std::size_t k = 0; k < n; ++k) {
      if (own[k].symbolic < 0 && classKey[root(k)].symbolic == -2) classKey[root(k)] = own[k];
    }
    std::vector<Key> keys(n);
    for (std::size_t k = 0; k < n; ++k) {
      const Key shared = classKey[root(k)];
      if (pointOf_[k] || shared.symbolic == -2 || shared == own[k]) {
        keys[k] = own[k];
      } else {
        keys[k] = rounds(k, shared.point()) ? shared : own[k];
      }
    }
    return keys;
  }

  // The answers (bits) whose op a piece bounds: a piece of S where op tells "in S" from "not in S"
  // at C's parity along it (and so for C).
  std::uint64_t boundedBy(const Side& side) const {
    std::uint64_t bounded = 0;
    for (std::size_t k = 0; k < answers_.size(); ++k) {
      const Op op = answers_[k].first;
      const bool p = side.otherParity;
      if (side.ofSubject ? apply(op, false, p) != apply(op, true, p) : apply(op, p, false) != apply(op, p, true)) {
        bounded |= std::uint64_t{1} << k;
      }
    }
    return bounded;
  }

  // Per answer in mask, whether its edges and op's pieces (with these ends) cover every point
  // equally mod 2, up to slivers within the rounding (thin()): equal segments cancel in pairs, all
  // answers in one sort, each segment with the answers it counts for. Segments are pairs of
  // numbers (one per distinct end), so that equal ones sort together cheaply.
  std::vector<bool> compare(const std::vector<Key>& keys, std::uint64_t mask) {
    auto keyOf = [&](const End& end) { return end.interior ? keys[end.crossing] : Key::at(end.at); };
    constexpr std::uint32_t kSymbolic = 0x80000000u;
    auto idOf = [&](const Key& k) -> std::uint32_t {
      if (k.symbolic >= 0) return kSymbolic | static_cast<std::uint32_t>(k.symbolic);
      auto [id, fresh] = ids_.findOrAdd(k.point());
      if (fresh) id = static_cast<std::uint32_t>(keyOfId_.size()), keyOfId_.push_back(k);
      return id;
    };
    auto segment = [](std::uint32_t u, std::uint32_t v) {
      return u < v ? std::uint64_t{u} << 32 | v : std::uint64_t{v} << 32 | u;
    };
    std::vector<std::pair<std::uint64_t, std::uint64_t>>& all = all_;
    all.clear();
    for (const Side& side : pieces_) {
      const std::uint32_t u = idOf(keyOf(side.from)), v = idOf(keyOf(side.to));
      if (u == v) continue;
      const std::uint64_t bounded = boundedBy(side) & mask;
      if (bounded) all.push_back({segment(u, v), bounded});
    }
    for (std::size_t k = 0; k < answers_.size(); ++k) {
      if (!(mask >> k & 1)) continue;
      for (const Ring& ring : *answers_[k].second) {
        for (std::size_t i = 0, m = ring.size(); i < m; ++i) {
          const std::uint32_t u = idOf(Key::at(ring[i])), v = idOf(Key::at(ring[(i + 1) % m]));
          if (u != v) all.push_back({segment(u, v), std::uint64_t{1} << k});
        }
      }
    }
    std::sort(all.begin(), all.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    auto keyOfId = [&](std::uint32_t id) { return id & kSymbolic ? Key{0, 0, id & ~kSymbolic} : keyOfId_[id]; };
    std::vector<std::vector<Piece>> rest(answers_.size());
    for (std::size_t i = 0; i < all.size();) {
      std::uint64_t odd = 0;
      std::size_t m = i;
      for (; m < all.size() && all[m].first == all[i].first; ++m) odd ^= all[m].second;
      for (std::size_t k = 0; odd != 0; ++k, odd >>= 1) {
        if (odd & 1) rest[k].push_back(Piece(keyOfId(static_cast<std::uint32_t>(all[i].first >> 32)), keyOfId(static_cast<std::uint32_t>(all[i].first))));
      }
      i = m;
    }
    std::vector<bool> certified(answers_.size(), false);
    for (std::size_t k = 0; k < answers_.size(); ++k) {
      if (mask >> k & 1) certified[k] = rest[k].empty() || thin(rest[k]);
    }
    return certified;
  }

  // Whether the segments left over (of the answer and of the pieces, those that did not cancel)
  // bound only what lies within the rounding of edges of S or C. They must form a cycle (every end
  // met an even number of times: then the answer's interior differs from the pieces' exactly by
  // the parity of this cycle). Those that cancel on their lines go; each connected part left has
  // the parity of the fan of triangles from one of its vertices over its segments, and each
  // triangle that is not flat must lie in one edge's box within its rounding distance of its line
  // (a convex set). Rounded crossings a few ulps apart leave such slivers where the answers
  // rounded them otherwise than chooseKeys guessed; segments the answers join across a point
  // where the pieces meet, cancel on their lines.
  bool thin(const std::vector<Piece>& rest) const {
    constexpr std::size_t kMostLeft = 512;  // beyond that, let the sampling oracle judge
    if (rest.size() > kMostLeft) return false;
    std::vector<Key> ends;
    for (const Piece& piece : rest) {
      if (piece.u.symbolic >= 0 || piece.v.symbolic >= 0) return false;
      ends.push_back(piece.u), ends.push_back(piece.v);
    }
    if (!eachMetEvenly(ends)) return false;  // not a cycle: the pieces are not a boundary
    std::vector<char> gone;
    cancelOnLines(rest, gone);
    std::vector<Key> part;
    std::vector<std::size_t> segments;
    for (std::size_t i = 0; i < rest.size(); ++i) {
      if (gone[i]) continue;
      // The connected part of rest[i]: its segments marked gone as they join.
      part.assign({rest[i].u, rest[i].v});
      segments.assign({i});
      gone[i] = 1;
      for (bool grown = true; grown;) {
        grown = false;
        for (std::size_t j = i + 1; j < rest.size(); ++j) {
          if (gone[j]) continue;
          const bool u = std::find(part.begin(), part.end(), rest[j].u) != part.end();
          const bool v = std::find(part.begin(), part.end(), rest[j].v) != part.end();
          if (!u && !v) continue;
          if (!u) part.push_back(rest[j].u);
          if (!v) part.push_back(rest[j].v);
          segments.push_back(j);
          gone[j] = 1, grown = true;
        }
      }
      auto along = [&](const Edge& g, double d, std::initializer_list<Point> points) {
        const double bound = d * std::hypot(g.b.x - g.a.x, g.b.y - g.a.y);
        return std::isfinite(bound) && std::all_of(points.begin(), points.end(), [&](Point q) {
          return inBox(g, q) && lineDistanceAtMost(g.a, g.b, q, bound);
        });
      };
      auto thinTriangle = [&](Point o, Point p, Point q) {
        if (o == p || o == q || filteredOrientation(o, p, q) == 0) return true;
        for (std::size_t e = 0; e < s_.edges.size(); ++e) {
          if (along(s_.edges[e], nearS_[e], {o, p, q})) return true;
        }
        for (std::size_t f = 0; f < c_.edges.size(); ++f) {
          if (along(c_.edges[f], nearC_[f], {o, p, q})) return true;
        }
        return false;
      };
      constexpr std::size_t kMostTried = 16;
      bool found = false;
      for (std::size_t t = 0; t < part.size() && t < kMostTried && !found; ++t) {
        const Point o = part[t].point();
        found = std::all_of(segments.begin(), segments.end(), [&](std::size_t j) { return thinTriangle(o, rest[j].u.point(), rest[j].v.point()); });
      }
      if (!found) return false;
    }
    return true;
  }

  const Edges s_, c_;
  const std::vector<std::pair<Op, const Region*>>& answers_;
  // Per edge of S (of C), 2 ulps of the largest magnitude its interior crossings can have (0
  // without any): a quarter of the sampling oracle's delta along it, at most.
  std::vector<double> nearS_, nearC_;
  std::vector<std::vector<OnEdge>> onS_, onC_;  // each edge's crossings
  std::vector<Interior> interiors_;
  std::vector<Point> vertices_;  // the answers', sorted by x, each once
  std::vector<Point> claimed_;   // the vertices of S and C, sorted
  std::vector<Point> candidates_;
  std::vector<std::size_t> candidateStart_;  // interior crossing k's: [start[k], start[k + 1])
  bool ambiguous_ = false;                   // some interior crossing has several
  std::vector<std::unique_ptr<std::pair<mpq_class, mpq_class>>> exact_;
  std::vector<std::size_t> parent_;                 // union-find over the interior crossings
  std::vector<std::optional<Point>> pointOf_;       // the double point a crossing is tied with
  std::vector<std::vector<std::size_t>> groupEnds_; // per edge (S's, then C's), where each tie group ends
  std::vector<Side> pieces_;
  PointTable<std::uint32_t> ids_;  // compare()'s numbers of the double points
  std::vector<Key> keyOfId_;
  std::vector<std::pair<std::uint64_t, std::uint64_t>> all_;  // compare()'s segments, with their answers
};

}  // namespace

std::vector<bool> certifiedAnswers(const Region& subject, const Region& clip,
                                   const std::vector<std::pair<Op, const Region*>>& answers) {
  if (!finite(subject) || !finite(clip)) return std::vector<bool>(answers.size(), false);
  for (const auto& [op, answer] : answers) {
    if (!finite(*answer)) return std::vector<bool>(answers.size(), false);
  }
  // At a comfortable scale (judging_scale.h): 2 ulps times an edge's length would underflow at
  // 1e-300. Every coordinate scales exactly, and so do the roundings and the proof.
  std::vector<const Region*> all{&subject, &clip};
  for (const auto& [op, answer] : answers) all.push_back(answer);
  const int k = judgingExponent(all);
  if (k == 0) return Certifier(subject, clip, answers).certify();
  const Region s = scaledBy(subject, k), c = scaledBy(clip, k);
  std::vector<Region> scaled;
  scaled.reserve(answers.size());
  std::vector<std::pair<Op, const Region*>> scaledAnswers;
  for (const auto& [op, answer] : answers) scaled.push_back(scaledBy(*answer, k)), scaledAnswers.emplace_back(op, &scaled.back());
  return Certifier(s, c, scaledAnswers).certify();
}

}  // namespace gh::oracle
