#include "cleanup.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "point_hash.h"
#include "recycled.h"
#include "predicates/orientation.h"

namespace gh::detail {
namespace {

struct PointLess {
  bool operator()(const Point& a, const Point& b) const { return a.x < b.x || (a.x == b.x && a.y < b.y); }
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
  // back at b (decided exactly: the directions along an axis, then orientation). The axis test
  // first: it needs no arithmetic, and it clears most vertices of an answer, whose consecutive
  // points along an input edge (crossings, rounded) are so nearly collinear that their
  // orientation goes past the filter to the exact stages.
  bool isSpike(Point a, Point b, Point c) const {
    const bool alongX = a.x != b.x;
    const int in = alongX ? signOfDifference(b.x, a.x) : signOfDifference(b.y, a.y);
    const int out = alongX ? signOfDifference(c.x, b.x) : signOfDifference(c.y, b.y);
    if (!(in * out < 0 || c == a)) return false;
    return orientation(a, b, c, counters_) == Sign::Zero;
  }

  // Drops repeated points and spike tips, including ones that only appear once others are gone
  // (A B C B A: C, then B). Spikes and repeated points bound nothing: the interior is unchanged.
  // In place: the ring [first, last) becomes [first, returned end).
  Point* simplify(Point* first, Point* last) const {
    Point* out = first;  // the kept points are [first, out); never ahead of the point read
    for (const Point* i = first; i < last; ++i) {
      const Point p = *i;
      if (out > first && out[-1] == p) continue;
      bool repeated = false;
      while (out - first >= 2 && isSpike(out[-2], out[-1], p)) {
        --out;
        if (out[-1] == p) {
          repeated = true;
          break;
        }
      }
      if (!repeated) *out++ = p;
    }
    // Close the ring: the seam between the last and the first points may hide repeats and spikes.
    for (bool changed = true; changed && out - first >= 3;) {
      changed = false;
      if (out[-1] == first[0]) {
        --out, changed = true;
      } else if (isSpike(out[-2], out[-1], first[0])) {
        --out, changed = true;
      } else if (isSpike(out[-1], first[0], first[1])) {
        std::copy(first + 1, out, first);
        --out, changed = true;
      }
    }
    return out;
  }
  void simplify(Ring& ring) const { ring.resize(static_cast<std::size_t>(simplify(ring.data(), ring.data() + ring.size()) - ring.data())); }

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

  // rings (none empty) -> out, flat both.
  void dissolveSeams(const FlatRings& rings, FlatRings& out) const;

 private:
  ExactCounters& counters_;
};

// Does any point occur twice? A flat open-addressing table of indices into `points`: this runs
// over every output vertex of the exact arithmetic.
bool anyVertexRepeats(const std::vector<Point>& points) {
  std::size_t capacity = 16;
  while (capacity < 2 * points.size()) capacity *= 2;
  constexpr std::uint32_t kEmpty = 0xffffffffu;
  // Reused between calls: this runs on every answer of the exact arithmetic, and on small answers
  // the allocation would cost more than the pass.
  thread_local std::vector<std::uint32_t> slots;
  slots.assign(capacity, kEmpty);
  const PointHash hash;
  for (std::uint32_t k = 0; k < points.size(); ++k) {
    for (std::size_t i = hash(points[k]) & (capacity - 1);; i = (i + 1) & (capacity - 1)) {
      if (slots[i] == kEmpty) {
        slots[i] = k;
        break;
      }
      if (points[slots[i]] == points[k]) return true;
    }
  }
  if (slots.capacity() * sizeof(std::uint32_t) > kKeepBytes) std::vector<std::uint32_t>().swap(slots);
  return false;
}

// Distinct points numbered in order of first appearance (open addressing; equal points, -0.0 and
// 0.0 included, get one number). reset() keeps the arrays' memory for the next answer.
class PointNumbers {
 public:
  void reset(std::size_t expected) {
    std::size_t capacity = 16;
    while (capacity < 2 * expected) capacity *= 2;
    slots_.assign(capacity, kEmpty);
    points_.clear();
  }
  std::uint32_t number(Point p) {
    for (std::size_t i = PointHash()(p) & (slots_.size() - 1);; i = (i + 1) & (slots_.size() - 1)) {
      if (slots_[i] == kEmpty) {
        slots_[i] = static_cast<std::uint32_t>(points_.size());
        points_.push_back(p);
        return slots_[i];
      }
      if (points_[slots_[i]] == p) return slots_[i];
    }
  }
  std::size_t size() const { return points_.size(); }
  Point point(std::uint32_t k) const { return points_[k]; }
  std::size_t bytes() const { return slots_.capacity() * sizeof(std::uint32_t) + points_.capacity() * sizeof(Point); }

 private:
  static constexpr std::uint32_t kEmpty = 0xffffffffu;
  std::vector<std::uint32_t> slots_;
  std::vector<Point> points_;
};

// Lists in compressed rows: row r holds items[start[r] .. start[r + 1]) in the order added.
struct Rows {
  std::vector<std::uint32_t> start, items;
  template <class ForEach>  // forEach(add) calls add(row, item) for every item, twice the same way
  void fill(std::size_t rows, ForEach forEach) {
    start.assign(rows + 1, 0);
    forEach([this](std::uint32_t row, std::uint32_t) { ++start[row + 1]; });
    for (std::size_t r = 0; r < rows; ++r) start[r + 1] += start[r];
    items.resize(start[rows]);
    // start[r] serves as row r's write position, which ends at row r + 1's start: shifted back
    // after.
    forEach([&](std::uint32_t row, std::uint32_t item) { items[start[row]++] = item; });
    for (std::size_t r = rows; r > 0; --r) start[r] = start[r - 1];
    start[0] = 0;
  }
  const std::uint32_t* begin(std::uint32_t r) const { return items.data() + start[r]; }
  const std::uint32_t* end(std::uint32_t r) const { return items.data() + start[r + 1]; }
  std::size_t bytes() const { return (start.capacity() + items.capacity()) * sizeof(std::uint32_t); }
};

// The edges of flat rings: edge e runs from points[e] to points[next[e]].
struct FlatEdges {
  const Point* points = nullptr;
  const std::uint32_t* next = nullptr;
  std::uint32_t count = 0;
  std::uint32_t size() const { return count; }
  Point from(std::uint32_t e) const { return points[e]; }
  Point to(std::uint32_t e) const { return points[next[e]]; }
};

// An edge's box: its x-range and y-range.
struct EdgeBox {
  double x0, x1, y0, y1;
};

// A uniform grid over the edges' bounding boxes: each edge is listed in every cell its closed box
// meets, so the edges whose box holds a point are among those of the point's cell. The cell size
// follows the edges' mean extent, coarsened until no edge is listed in too many cells in all.
class EdgeGrid {
 public:
  // boxes[e]: edge e's box; spans: scratch for each edge's cells.
  EdgeGrid(const FlatEdges& op, const std::vector<EdgeBox>& boxes, Rows& rows, std::vector<std::uint32_t>& spans)
      : rows_(rows) {
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    for (std::uint32_t e = 0; e < op.size(); ++e) {
      const Point p = op.from(e);
      x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
    }
    x0_ = x0, y0_ = y0;
    // Each edge's first and last column and row, computed once for the grid chosen: the fill
    // below walks them twice, and computing them in its loops' conditions (a division each) was
    // most of the grid's time (perf).
    spans.resize(4 * std::size_t{op.size()});
    auto span = [&](std::uint32_t e) {
      const EdgeBox& b = boxes[e];
      spans[4 * e] = cellX(b.x0), spans[4 * e + 1] = cellX(b.x1), spans[4 * e + 2] = cellY(b.y0), spans[4 * e + 3] = cellY(b.y1);
    };
    const double n = static_cast<double>(std::max<std::size_t>(op.size(), 1));
    for (int side = static_cast<int>(std::min(2048.0, std::ceil(std::sqrt(n / 2)))); side >= 1; side /= 2) {
      side_ = static_cast<std::uint32_t>(side);
      cellW_ = (x1 - x0) / side, cellH_ = (y1 - y0) / side;
      if (!(cellW_ > 0) || !(cellH_ > 0) || !std::isfinite(cellW_) || !std::isfinite(cellH_)) {
        side_ = 1, cellW_ = cellH_ = INFINITY;
        for (std::uint32_t e = 0; e < op.size(); ++e) span(e);
        break;
      }
      std::size_t listed = 0;
      for (std::uint32_t e = 0; e < op.size(); ++e) {
        span(e);
        listed += std::size_t{spans[4 * e + 1] - spans[4 * e] + 1} * (spans[4 * e + 3] - spans[4 * e + 2] + 1);
        if (listed > 16 * std::size_t{op.size()}) break;
      }
      if (listed <= 16 * std::size_t{op.size()}) break;  // every edge's span is in place
    }
    rows_.fill(std::size_t{side_} * side_, [&](auto&& add) {
      for (std::uint32_t e = 0; e < op.size(); ++e) {
        const std::uint32_t* c = &spans[4 * e];
        for (std::uint32_t cy = c[2]; cy <= c[3]; ++cy) {
          for (std::uint32_t cx = c[0]; cx <= c[1]; ++cx) add(cy * side_ + cx, e);
        }
      }
    });
  }
  // The edges listed in the cell of p.
  std::pair<const std::uint32_t*, const std::uint32_t*> near(Point p) const {
    const std::uint32_t c = cellY(p.y) * side_ + cellX(p.x);
    return {rows_.begin(c), rows_.end(c)};
  }

 private:
  // Monotone in the coordinate, so a box [lo, hi] meets every cell of a point inside it.
  std::uint32_t cellX(double x) const { return cell((x - x0_) / cellW_); }
  std::uint32_t cellY(double y) const { return cell((y - y0_) / cellH_); }
  std::uint32_t cell(double t) const {
    if (!(t > 0)) return 0;  // also NaN: 0 / infinity
    // min(floor(t), side - 1) without a call to floor: below side - 1, t > 0 truncates to it.
    return t < static_cast<double>(side_ - 1) ? static_cast<std::uint32_t>(t) : side_ - 1;
  }
  double x0_ = 0, y0_ = 0, cellW_ = 1, cellH_ = 1;
  std::uint32_t side_ = 1;
  Rows& rows_;
};

// dissolveSeams' working arrays, kept per thread between answers: the exact arithmetic's answers
// have seams to look for whenever a vertex repeats, and on the fuzz targets' small answers two
// dozen fresh arrays a call cost more than the work (perf: allocation was a fifth of the pass).
// Let go when larger than kKeepBytes, like the clip's other spares (recycled.h).
struct SeamScratch {
  std::vector<std::uint32_t> next, fromNumber, toNumber, pieceFrom, pieceTo, forwardOf, backwardOf, kept, left, spans;
  PointNumbers numbers;
  Rows edgesAt, cells, around;
  std::vector<EdgeBox> boxes;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> cuts;
  std::vector<std::pair<Point, Point>> pieces;
  std::vector<std::uint32_t> pairSlots;  // dissolveSeams' (from, to) table: a piece index each, or kNoPiece
  std::vector<int> count;
  std::vector<std::pair<std::uint64_t, std::uint32_t>> byPair;
  std::vector<char> dropped, used;

  std::size_t bytes() const {
    std::size_t b = numbers.bytes() + edgesAt.bytes() + cells.bytes() + around.bytes();
    for (const auto* v : {&next, &fromNumber, &toNumber, &pieceFrom, &pieceTo, &forwardOf, &backwardOf, &kept, &left, &spans}) {
      b += v->capacity() * sizeof(std::uint32_t);
    }
    b += boxes.capacity() * sizeof(EdgeBox) + cuts.capacity() * sizeof(cuts[0]) + pieces.capacity() * sizeof(pieces[0]);
    b += pairSlots.capacity() * sizeof(std::uint32_t) + count.capacity() * sizeof(int) + byPair.capacity() * sizeof(byPair[0]);
    return b + dropped.capacity() + used.capacity();
  }
};

constexpr std::uint32_t kNoPiece = 0xffffffffu;

// Up to this many edges every edge's box is screened against every point: cheaper than building
// a grid for the few edges of most answers (the fuzz targets' answers have a few dozen).
constexpr std::uint32_t kScreenAllEdgesUpTo = 64;

// Zero-width seams: two rings of the answer running along the same segment in opposite
// directions (the exact arithmetic's limit leaves them between regions that only touch, like two
// squares sharing an edge). Each pair bounds nothing: split collinear overlaps at each other's
// endpoints, cancel opposite pairs, and chain what is left into rings again, so that the union of
// two squares sharing an edge is one rectangle.
void CleanUp::dissolveSeams(const FlatRings& rings, FlatRings& out) const {
  thread_local SeamScratch scratch;
  SeamScratch& s = scratch;
  const auto edgeCount = static_cast<std::uint32_t>(rings.points.size());
  s.next.resize(edgeCount);
  for (std::size_t k = 0; k + 1 < rings.start.size(); ++k) {
    for (std::uint32_t v = rings.start[k]; v < rings.start[k + 1]; ++v) s.next[v] = v + 1 < rings.start[k + 1] ? v + 1 : rings.start[k];
  }
  const FlatEdges op{rings.points.data(), s.next.data(), edgeCount};
  // The endpoints of every edge, numbered, and the edges at each.
  PointNumbers& numbers = s.numbers;
  numbers.reset(op.size());
  std::vector<std::uint32_t>&fromNumber = s.fromNumber, &toNumber = s.toNumber;
  fromNumber.resize(op.size()), toNumber.resize(op.size());
  for (std::uint32_t e = 0; e < op.size(); ++e) fromNumber[e] = numbers.number(op.from(e));
  for (std::uint32_t e = 0; e < op.size(); ++e) toNumber[e] = numbers.number(op.to(e));
  Rows& edgesAt = s.edgesAt;
  edgesAt.fill(numbers.size(), [&](auto&& add) {
    for (std::uint32_t e = 0; e < op.size(); ++e) add(fromNumber[e], e), add(toNumber[e], e);
  });
  // Cut every edge e at each point x strictly inside it that is an endpoint of an edge f collinear
  // with e (a collinear overlap, split at the other's endpoints). A point collinear with e lies
  // strictly inside it iff it is in e's closed box and is neither end: the boxes, in one array,
  // screen the edges (all of them, or those of x's grid cell) before any orientation is decided.
  std::vector<EdgeBox>& boxes = s.boxes;
  boxes.resize(op.size());
  for (std::uint32_t e = 0; e < op.size(); ++e) {
    const Point a = op.from(e), b = op.to(e);
    boxes[e] = {std::min(a.x, b.x), std::max(a.x, b.x), std::min(a.y, b.y), std::max(a.y, b.y)};
  }
  auto& cuts = s.cuts;  // (edge, number of a point cutting it)
  cuts.clear();
  // The screen, inline in the loops below: on the exact fuzz target's grown corpus it turns away
  // 76 % of the (point, edge) pairs met there (1,265,177 of 5,367,103 held), and a call for each
  // pair was a sixth of the exact clip's time (perf, release build).
  auto boxHolds = [&](std::uint32_t e, Point x) {
    const EdgeBox& box = boxes[e];
    return (x.x >= box.x0) & (x.x <= box.x1) & (x.y >= box.y0) & (x.y <= box.y1);
  };
  // e, whose box holds x (point k): cut at x if x is not an end of e and is collinear with e and
  // with another edge at x.
  auto tryCut = [&](std::uint32_t k, Point x, std::uint32_t e) {
    if (fromNumber[e] == k || toNumber[e] == k) return;  // an end of e
    const Point a = op.from(e), b = op.to(e);
    if (orientation(a, b, x, counters_) != Sign::Zero) return;
    for (const std::uint32_t* f = edgesAt.begin(k); f != edgesAt.end(k); ++f) {
      const Point other = fromNumber[*f] == k ? op.to(*f) : op.from(*f);
      if (orientation(a, b, other, counters_) == Sign::Zero) {
        cuts.push_back({e, k});
        return;
      }
    }
  };
  if (op.size() <= kScreenAllEdgesUpTo) {
    for (std::uint32_t k = 0; k < numbers.size(); ++k) {
      const Point x = numbers.point(k);
      for (std::uint32_t e = 0; e < op.size(); ++e) {
        if (boxHolds(e, x)) tryCut(k, x, e);
      }
    }
  } else {
    const EdgeGrid grid(op, boxes, s.cells, s.spans);
    for (std::uint32_t k = 0; k < numbers.size(); ++k) {
      const Point x = numbers.point(k);
      for (auto [it, end] = grid.near(x); it != end; ++it) {
        if (boxHolds(*it, x)) tryCut(k, x, *it);
      }
    }
  }
  // Directed pieces (each edge's cuts in order from its start), numbered by their ends' numbers
  // (every end is a vertex), then cancellation of opposite pairs: a piece cancels while both it
  // and an opposite copy are still counted, in the order of the pieces.
  std::sort(cuts.begin(), cuts.end(), [&](const auto& u, const auto& v) {
    return u.first != v.first ? u.first < v.first : PointLess()(numbers.point(u.second), numbers.point(v.second));
  });
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());  // distinct numbers, distinct points
  auto& pieces = s.pieces;
  std::vector<std::uint32_t>&pieceFrom = s.pieceFrom, &pieceTo = s.pieceTo;
  pieces.clear(), pieceFrom.clear(), pieceTo.clear();
  pieces.reserve(op.size() + cuts.size()), pieceFrom.reserve(pieces.capacity()), pieceTo.reserve(pieces.capacity());
  auto addPiece = [&](Point from, std::uint32_t u, Point to, std::uint32_t v) {
    pieces.push_back({from, to}), pieceFrom.push_back(u), pieceTo.push_back(v);
  };
  for (std::size_t c = 0, e = 0; e < op.size(); ++e) {
    std::size_t last = c;  // this edge's cuts are cuts[c, last)
    while (last < cuts.size() && cuts[last].first == e) ++last;
    const Point a = op.from(static_cast<std::uint32_t>(e)), b = op.to(static_cast<std::uint32_t>(e));
    const bool backwards = PointLess()(b, a);
    Point from = a;
    std::uint32_t u = fromNumber[e];
    for (std::size_t i = 0; i < last - c; ++i) {
      const std::uint32_t k = cuts[backwards ? last - 1 - i : c + i].second;
      addPiece(from, u, numbers.point(k), k), from = numbers.point(k), u = k;
    }
    addPiece(from, u, b, toNumber[e]);
    c = last;
  }
  // Counts of directed pieces, keyed by their (from, to) numbers: each piece is counted under the
  // first piece with its ends, found in a table open-addressed by the pair, and its reverse under
  // the first piece running the other way, if any (kNoPiece when none). (The pairs were sorted,
  // and a binary search for every piece and for its reverse was this pass's hottest loop, perf.)
  auto key = [](std::uint32_t u, std::uint32_t v) { return (std::uint64_t{u} << 32) | v; };
  int bits = 4;
  while ((std::size_t{1} << bits) < 2 * pieces.size()) ++bits;
  const std::size_t mask = (std::size_t{1} << bits) - 1;
  std::vector<std::uint32_t>& slots = s.pairSlots;
  slots.assign(mask + 1, kNoPiece);
  auto slotOf = [&](std::uint64_t k) {  // the slot that holds pair k, or the empty one where it would go
    std::size_t i = static_cast<std::size_t>((k * 0x9E3779B97F4A7C15ull) >> (64 - bits));
    while (slots[i] != kNoPiece && key(pieceFrom[slots[i]], pieceTo[slots[i]]) != k) i = (i + 1) & mask;
    return i;
  };
  std::vector<int>& count = s.count;
  count.assign(pieces.size(), 0);  // by first piece
  std::vector<std::uint32_t>&forwardOf = s.forwardOf, &backwardOf = s.backwardOf;
  forwardOf.resize(pieces.size()), backwardOf.resize(pieces.size());
  for (std::uint32_t i = 0; i < pieces.size(); ++i) {
    const std::size_t slot = slotOf(key(pieceFrom[i], pieceTo[i]));
    if (slots[slot] == kNoPiece) slots[slot] = i;
    forwardOf[i] = slots[slot];
    ++count[forwardOf[i]];
  }
  for (std::uint32_t i = 0; i < pieces.size(); ++i) {
    backwardOf[i] = slots[slotOf(key(pieceTo[i], pieceFrom[i]))];
  }
  std::vector<std::uint32_t>& kept = s.kept;
  kept.clear();
  for (std::uint32_t i = 0; i < pieces.size(); ++i) {
    const std::uint32_t u = pieceFrom[i], v = pieceTo[i];
    int& forward = count[forwardOf[i]];
    int* backward = backwardOf[i] != kNoPiece ? &count[backwardOf[i]] : nullptr;
    if (forward > 0 && backward && *backward > 0 && u != v) {
      --forward, --*backward;  // this piece and one opposite copy cancel
      continue;
    }
    if (forward > 0) --forward, kept.push_back(i);
  }
  // Under the even-odd rule two copies of a piece in the same direction cancel as well (crossing
  // both changes nothing): a loop traced twice, as borders shared with T-junctions leave in
  // S \ S. The pieces kept between two points all run one way (opposite ones cancelled above);
  // where two or more remain, their count modulo 2 is kept, and the pieces are chained without
  // regard to direction: every point still ends an even number of pieces, so every walk closes.
  bool directed = true;
  {
    auto& byPair = s.byPair;
    byPair.resize(kept.size());
    for (std::uint32_t j = 0; j < kept.size(); ++j) {
      const std::uint32_t u = pieceFrom[kept[j]], v = pieceTo[kept[j]];
      byPair[j] = {key(std::min(u, v), std::max(u, v)), j};
    }
    std::sort(byPair.begin(), byPair.end());
    std::vector<char>& dropped = s.dropped;
    dropped.assign(kept.size(), 0);
    for (std::size_t a = 0, b; a < byPair.size(); a = b) {
      for (b = a + 1; b < byPair.size() && byPair[b].first == byPair[a].first; ++b) {
      }
      // Drop all but (b - a) mod 2 of the run, keeping its first in order of the pieces.
      for (std::size_t k = a + (b - a) % 2; k < b; ++k) dropped[byPair[k].second] = 1, directed = false;
    }
    if (!directed) {
      std::vector<std::uint32_t>& left = s.left;
      left.clear();
      for (std::uint32_t j = 0; j < kept.size(); ++j) {
        if (!dropped[j]) left.push_back(kept[j]);
      }
      kept.swap(left);
    }
  }
  // Chain the remaining pieces; at a vertex with several ways on, take the sharpest right turn,
  // decided exactly. Any choice bounds the same even-odd interior; this one is deterministic
  // (counter-clockwise rings touching at a vertex become one ring through it).
  Rows& around = s.around;
  around.fill(numbers.size(), [&](auto&& add) {
    for (std::uint32_t j = 0; j < kept.size(); ++j) {
      add(pieceFrom[kept[j]], j);
      if (!directed) add(pieceTo[kept[j]], j);
    }
  });
  std::vector<char>& used = s.used;
  used.assign(kept.size(), 0);
  out.points.clear(), out.start.assign(1, 0);
  out.points.reserve(kept.size());
  for (std::size_t start = 0; start < kept.size(); ++start) {
    if (used[start]) continue;
    std::size_t cur = start;
    bool reversed = false;  // the current piece is walked from its end to its start
    for (std::size_t guard = 0; guard <= kept.size(); ++guard) {
      used[cur] = 1;
      const auto& piece = pieces[kept[cur]];
      const Point from = reversed ? piece.second : piece.first, at = reversed ? piece.first : piece.second;
      out.points.push_back(from);
      const std::uint32_t atNumber = reversed ? pieceFrom[kept[cur]] : pieceTo[kept[cur]];
      std::size_t best = kept.size();
      bool bestReversed = false;
      Point bestFar{};
      for (const std::uint32_t* j = around.begin(atNumber); j != around.end(atNumber); ++j) {
        if (used[*j]) continue;
        const bool backwards = pieceFrom[kept[*j]] != atNumber;  // only when undirected
        const Point far = backwards ? pieces[kept[*j]].first : pieces[kept[*j]].second;
        if (best == kept.size() || sharperRight(from, at, far, bestFar)) best = *j, bestReversed = backwards, bestFar = far;
      }
      if (best == kept.size()) break;  // back at the start (its piece is used)
      cur = best, reversed = bestReversed;
    }
    out.closeRing();
  }
  if (s.bytes() > kKeepBytes) s = SeamScratch();
}

}  // namespace

Region cleanedUp(FlatRings& rings, bool dissolve, ExactCounters& counters) {
  const CleanUp cleanUp(counters);
  // Every ring simplified where it is, then moved down over what earlier rings gave up.
  std::vector<Point>& points = rings.points;
  std::uint32_t write = 0;
  std::vector<std::uint32_t> start{0};
  start.reserve(rings.start.size());
  for (std::size_t r = 0; r < rings.size(); ++r) {
    Point* first = points.data() + rings.start[r];
    Point* last = cleanUp.simplify(first, points.data() + rings.start[r + 1]);
    // A ring on one line always folds back at its extreme points, so spike removal has left it
    // with fewer than 3 points: no separate collinearity test is needed.
    if (last - first < 3) continue;
    std::copy(first, last, points.data() + write);
    write += static_cast<std::uint32_t>(last - first);
    start.push_back(write);
  }
  points.resize(write);
  rings.start.swap(start);
  // Seams are looked for only where a vertex repeats (rings touching at a shared vertex: the usual
  // shape of the exact arithmetic's seams), which costs one hash pass otherwise. Rings that touch
  // only along a T-junction keep their seam; their even-odd interior is right either way.
  if (!dissolve || !anyVertexRepeats(points)) return rings.toRegion();
  FlatRings walked;
  cleanUp.dissolveSeams(rings, walked);
  Region dissolved;
  dissolved.reserve(walked.size());
  for (std::size_t r = 0; r < walked.size(); ++r) {
    Point* first = walked.points.data() + walked.start[r];
    Ring ring(first, cleanUp.simplify(first, walked.points.data() + walked.start[r + 1]));
    cleanUp.dropStraightVertices(ring);
    if (ring.size() >= 3) dissolved.push_back(std::move(ring));
  }
  return dissolved;
}

Region cleanedUp(const Region& region, bool dissolve, ExactCounters& counters) {
  FlatRings rings = FlatRings::from(region);
  return cleanedUp(rings, dissolve, counters);
}

}  // namespace gh::detail
