#include "cleanup.h"

#include <algorithm>
#include <cstring>
#include <map>

#include "operand.h"
#include "predicates/orientation.h"
#include "search/sweep_search.h"

namespace gh::detail {
namespace {

struct PointLess {
  bool operator()(const Point& a, const Point& b) const { return a.x < b.x || (a.x == b.x && a.y < b.y); }
};
struct PointHash {
  std::size_t operator()(const Point& p) const {
    std::uint64_t x, y;
    std::memcpy(&x, &p.x, 8), std::memcpy(&y, &p.y, 8);
    std::uint64_t h = (x ^ (y * 0x9E3779B97F4A7C15ull)) * 0xBF58476D1CE4E5B9ull;
    return static_cast<std::size_t>(h ^ (h >> 31));
  }
};

// For collinear directions a -> b and c -> d (both non-zero): do they point the same way?
// Decided by comparisons along an axis on which a and b differ: nothing is computed.
bool sameDirection(Point a, Point b, Point c, Point d) {
  if (a.x != b.x) return signOfDifference(b.x, a.x) == signOfDifference(d.x, c.x);
  return signOfDifference(b.y, a.y) == signOfDifference(d.y, c.y);
}

class CleanUp {
 public:
  explicit CleanUp(ExactCounters& counters) : counters_(counters) {}

  // b is the tip of a zero-width spike a -> b -> c: the three are collinear and the path turns
  // back at b (decided exactly: orientation, then the directions along an axis).
  bool isSpike(Point a, Point b, Point c) const {
    if (orientation(a, b, c, counters_) != Sign::Zero) return false;
    const bool alongX = a.x != b.x;
    const int in = alongX ? signOfDifference(b.x, a.x) : signOfDifference(b.y, a.y);
    const int out = alongX ? signOfDifference(c.x, b.x) : signOfDifference(c.y, b.y);
    return in * out < 0 || c == a;
  }

  // Drops repeated points and spike tips, including ones that only appear once others are gone
  // (A B C B A: C, then B). Spikes and repeated points bound nothing: the interior is unchanged.
  void simplify(Ring& ring) const {
    Ring out;
    out.reserve(ring.size());
    auto push = [&](Point p) {
      if (!out.empty() && out.back() == p) return;
      while (out.size() >= 2 && isSpike(out[out.size() - 2], out.back(), p)) {
        out.pop_back();
        if (out.back() == p) return;
      }
      out.push_back(p);
    };
    for (const Point& p : ring) push(p);
    // Close the ring: the seam between the last and the first points may hide repeats and spikes.
    for (bool changed = true; changed && out.size() >= 3;) {
      changed = false;
      if (out.back() == out.front()) {
        out.pop_back(), changed = true;
      } else if (isSpike(out[out.size() - 2], out.back(), out.front())) {
        out.pop_back(), changed = true;
      } else if (isSpike(out.back(), out[0], out[1])) {
        out.erase(out.begin()), changed = true;
      }
    }
    ring.swap(out);
  }

  bool allCollinear(const Ring& ring) const {
    // ring[0] != ring[1] after simplify, so they span a line.
    for (std::size_t i = 2; i < ring.size(); ++i) {
      if (orientation(ring[0], ring[1], ring[i], counters_) != Sign::Zero) return false;
    }
    return true;
  }

  // Drops vertices where the ring goes straight on (collinear, not folding back).
  void dropStraightVertices(Ring& ring) const {
    for (bool changed = true; changed && ring.size() > 3;) {
      changed = false;
      for (std::size_t i = 0; i < ring.size() && ring.size() > 3; ++i) {
        const Point a = ring[(i + ring.size() - 1) % ring.size()], b = ring[i], c = ring[(i + 1) % ring.size()];
        if (orientation(a, b, c, counters_) == Sign::Zero && !isSpike(a, b, c)) {
          ring.erase(ring.begin() + static_cast<long>(i));
          changed = true;
        }
      }
    }
  }

  // The turn from the direction from -> at into the direction at -> to, as a class in increasing
  // angle over (-pi, pi]: 0 right turns, 1 straight on, 2 left turns, 3 straight back.
  int turnClass(Point from, Point at, Point to) const {
    const Sign s = crossSign(from, at, at, to, counters_);
    if (s != Sign::Zero) return s == Sign::Negative ? 0 : 2;
    return sameDirection(from, at, at, to) ? 1 : 3;
  }

  // Is the turn from -> at -> a sharper to the right (a smaller angle) than from -> at -> b?
  // Exact: within the open right or left half-plane, a is sharper iff b lies counter-clockwise
  // of a.
  bool sharperRight(Point from, Point at, Point a, Point b) const {
    const int ca = turnClass(from, at, a), cb = turnClass(from, at, b);
    if (ca != cb) return ca < cb;
    if (ca == 1 || ca == 3) return false;  // the same direction: a tie
    return crossSign(at, a, at, b, counters_) == Sign::Positive;
  }

  Region dissolveSeams(const Region& region) const;

 private:
  ExactCounters& counters_;
};

// Does any point occur twice in the region? A flat open-addressing table: this runs over every
// output vertex of the exact arithmetic.
bool anyVertexRepeats(const Region& region) {
  std::size_t n = 0;
  for (const Ring& ring : region) n += ring.size();
  std::size_t capacity = 16;
  while (capacity < 2 * n) capacity *= 2;
  // Reused between calls: this runs on every answer of the exact arithmetic, and on small answers
  // the allocation would cost more than the pass.
  thread_local std::vector<Point> slots;
  thread_local std::vector<char> used;
  if (slots.size() < capacity) slots.resize(capacity);
  used.assign(capacity, 0);
  const PointHash hash;
  for (const Ring& ring : region) {
    for (const Point& p : ring) {
      for (std::size_t i = hash(p) & (capacity - 1);; i = (i + 1) & (capacity - 1)) {
        if (!used[i]) {
          used[i] = 1, slots[i] = p;
          break;
        }
        if (slots[i] == p) return true;
      }
    }
  }
  return false;
}

// Zero-width seams: two rings of the answer running along the same segment in opposite
// directions (the exact arithmetic's limit leaves them between regions that only touch, like two
// squares sharing an edge). Each pair bounds nothing: split collinear overlaps at each other's
// endpoints, cancel opposite pairs, and chain what is left into rings again, so that the union of
// two squares sharing an edge is one rectangle.
Region CleanUp::dissolveSeams(const Region& region) const {
  const Operand op(region);
  std::vector<std::vector<Point>> cuts(op.size());
  SweepSearch{}.forEachCandidate(op, op, [&](std::uint32_t e, std::uint32_t f) {
    if (e >= f) return;
    const Point a = op.from(e), b = op.to(e), c = op.from(f), d = op.to(f);
    if (orientation(a, b, c, counters_) != Sign::Zero || orientation(a, b, d, counters_) != Sign::Zero) return;
    auto strictlyInside = [](Point p, Point q, Point r) {  // r strictly between p and q (collinear)
      return PointLess()(std::min(p, q, PointLess()), r) && PointLess()(r, std::max(p, q, PointLess()));
    };
    for (Point x : {c, d}) {
      if (strictlyInside(a, b, x)) cuts[e].push_back(x);
    }
    for (Point x : {a, b}) {
      if (strictlyInside(c, d, x)) cuts[f].push_back(x);
    }
  });
  // Directed pieces, then cancellation of opposite pairs.
  std::map<std::pair<std::pair<double, double>, std::pair<double, double>>, int> count;
  std::vector<std::pair<Point, Point>> pieces;
  for (std::uint32_t e = 0; e < op.size(); ++e) {
    std::vector<Point> pts = cuts[e];
    const Point a = op.from(e), b = op.to(e);
    std::sort(pts.begin(), pts.end(), PointLess());
    pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
    if (PointLess()(b, a)) std::reverse(pts.begin(), pts.end());
    Point from = a;
    for (const Point& x : pts) pieces.push_back({from, x}), from = x;
    pieces.push_back({from, b});
  }
  auto key = [](Point u, Point v) { return std::make_pair(std::make_pair(u.x, u.y), std::make_pair(v.x, v.y)); };
  for (const auto& [u, v] : pieces) ++count[key(u, v)];
  std::vector<std::pair<Point, Point>> kept;
  for (const auto& [u, v] : pieces) {
    int& forward = count[key(u, v)];
    int& backward = count[key(v, u)];
    if (forward > 0 && backward > 0 && !(u == v)) {
      --forward, --backward;  // this piece and one opposite copy cancel
      continue;
    }
    if (forward > 0) --forward, kept.push_back({u, v});
  }
  // Chain the remaining pieces; at a vertex with several ways on, take the sharpest right turn,
  // decided exactly. Any choice bounds the same even-odd interior; this one is deterministic
  // (counter-clockwise rings touching at a vertex become one ring through it).
  std::map<Point, std::vector<std::size_t>, PointLess> outgoing;
  for (std::size_t i = 0; i < kept.size(); ++i) outgoing[kept[i].first].push_back(i);
  std::vector<char> used(kept.size(), 0);
  Region out;
  for (std::size_t start = 0; start < kept.size(); ++start) {
    if (used[start]) continue;
    Ring ring;
    std::size_t cur = start;
    for (std::size_t guard = 0; guard <= kept.size(); ++guard) {
      used[cur] = 1;
      ring.push_back(kept[cur].first);
      const Point from = kept[cur].first, at = kept[cur].second;
      std::size_t best = kept.size();
      for (std::size_t j : outgoing[at]) {
        if (used[j]) continue;
        if (best == kept.size() || sharperRight(from, at, kept[j].second, kept[best].second)) best = j;
      }
      if (best == kept.size()) break;  // back at the start (its piece is used)
      cur = best;
    }
    out.push_back(std::move(ring));
  }
  return out;
}

}  // namespace

Region cleanedUp(Region region, bool dissolve, ExactCounters& counters) {
  const CleanUp cleanUp(counters);
  Region out;
  out.reserve(region.size());
  for (Ring& ring : region) {
    cleanUp.simplify(ring);
    if (ring.size() >= 3 && !cleanUp.allCollinear(ring)) out.push_back(std::move(ring));
  }
  // Seams are looked for only where a vertex repeats (rings touching at a shared vertex: the usual
  // shape of the exact arithmetic's seams), which costs one hash pass otherwise. Rings that touch
  // only along a T-junction keep their seam; their even-odd interior is right either way.
  if (!dissolve || !anyVertexRepeats(out)) return out;
  Region dissolved;
  for (Ring& ring : cleanUp.dissolveSeams(out)) {
    cleanUp.simplify(ring);
    cleanUp.dropStraightVertices(ring);
    if (ring.size() >= 3 && !cleanUp.allCollinear(ring)) dissolved.push_back(std::move(ring));
  }
  return dissolved;
}

}  // namespace gh::detail
