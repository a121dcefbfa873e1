#include "layout/node_rounding.h"

#include <algorithm>
#include <tuple>
#include <cmath>
#include <memory>
#include <optional>
#include <sstream>

#include "ghclip/ogc_layout.h"
#include "layout/snap_rounding.h"
#include "predicates/construction.h"
#include "predicates/orientation.h"
#include "predicates/segment_meeting.h"
#include "search/box_grid.h"
#include "search/box_overlaps.h"

namespace gh::detail {
namespace {

// For collinear directions w -> a and w -> b (neither of length 0): do they point the same way?
// Decided by comparisons along an axis on which w and a differ.
bool sameWay(Point w, Point a, Point b) {
  if (w.x != a.x) return signOfDifference(a.x, w.x) == signOfDifference(b.x, w.x);
  return signOfDifference(a.y, w.y) == signOfDifference(b.y, w.y);
}

class Rounder {
 public:
  Rounder(const NodedBoundary& noded, const LinedRings& rings, ExactCounters& counters)
      : n_(noded), rings_(rings), counters_(counters), at_(noded.rounded) {}

  // Empty when some pieces could not be kept apart: then `trouble` holds the nodes at their ends,
  // and positions() where every node is (the others kept apart from one another).
  std::optional<PlaneGraph> run(RoundingStats& stats, std::vector<std::uint32_t>& trouble) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> wrong = wrongPairs();
    if (!wrong.empty()) {
      prepareRepairs();
      for (const auto& [p, q] : wrong) {
        if (!meetWrongly(p, q)) continue;  // a repair of an earlier pair mended it too
        if (!repair(p, q)) {
          for (const std::uint32_t v : {n_.pieceFrom[p], n_.pieceTo[p], n_.pieceFrom[q], n_.pieceTo[q]}) trouble.push_back(v);
        }
      }
      if (!trouble.empty()) return std::nullopt;
      // Every repair kept the pieces near the nodes it moved apart; a last look at all of them.
      for (const auto& [p, q] : wrongPairs()) {
        for (const std::uint32_t v : {n_.pieceFrom[p], n_.pieceTo[p], n_.pieceFrom[q], n_.pieceTo[q]}) trouble.push_back(v);
      }
      if (!trouble.empty()) return std::nullopt;
    }
    for (std::uint32_t v = 0; v < at_.size(); ++v) stats.rerounded += !(at_[v] == n_.rounded[v]);
    return graph(stats);
  }
  const std::vector<Point>& positions() const { return at_; }

 private:
  std::size_t pieceCount() const { return n_.pieceFrom.size(); }
  Point from(std::uint32_t p) const { return at_[n_.pieceFrom[p]]; }
  Point to(std::uint32_t p) const { return at_[n_.pieceTo[p]]; }
  bool meetWrongly(std::uint32_t p, std::uint32_t q) { return detail::meetWrongly(from(p), to(p), from(q), to(q), counters_); }

  // A piece's box: where its ends are now, or, widened, wherever a faithful rounding may put them
  // (an ulp on each side of a crossing node's coordinates).
  Box box(std::uint32_t p, bool widened) const {
    Box b{INFINITY, -INFINITY, INFINITY, -INFINITY, p};
    for (const std::uint32_t v : {n_.pieceFrom[p], n_.pieceTo[p]}) {
      const Point q = at_[v];
      const bool wide = widened && !n_.isExact(v);
      b.minX = std::min(b.minX, wide ? std::nextafter(q.x, -INFINITY) : q.x);
      b.maxX = std::max(b.maxX, wide ? std::nextafter(q.x, INFINITY) : q.x);
      b.minY = std::min(b.minY, wide ? std::nextafter(q.y, -INFINITY) : q.y);
      b.maxY = std::max(b.maxY, wide ? std::nextafter(q.y, INFINITY) : q.y);
    }
    return b;
  }

  std::vector<std::pair<std::uint32_t, std::uint32_t>> wrongPairs() {
    std::vector<Box> boxes(pieceCount());
    for (std::uint32_t p = 0; p < pieceCount(); ++p) boxes[p] = box(p, false);
    std::vector<std::pair<std::uint32_t, std::uint32_t>> wrong;
    forEachOverlappingPair(boxes, [&](std::uint32_t p, std::uint32_t q) {
      if (meetWrongly(p, q)) wrong.emplace_back(std::min(p, q), std::max(p, q));
    });
    std::sort(wrong.begin(), wrong.end());
    return wrong;
  }

  void prepareRepairs() {
    widened_.resize(pieceCount());
    for (std::uint32_t p = 0; p < pieceCount(); ++p) widened_[p] = box(p, true);
    grid_ = std::make_unique<BoxGrid>(widened_);
    piecesAt_.assign(at_.size(), {});
    for (std::uint32_t p = 0; p < pieceCount(); ++p) {
      piecesAt_[n_.pieceFrom[p]].push_back(p);
      piecesAt_[n_.pieceTo[p]].push_back(p);
    }
  }

  // Every faithful rounding of node v: its first one first.
  std::vector<Point> choices(std::uint32_t v) const {
    std::vector<Point> out{n_.rounded[v]};
    if (n_.isExact(v)) return out;
    const LinedRings::Line &a = rings_.lines[n_.lineA[v]], &b = rings_.lines[n_.lineB[v]];
    const CrossingRoundings r = crossingRoundings(a.from, a.to, b.from, b.to);
    for (const double x : {r.x0, r.x1}) {
      for (const double y : {r.y0, r.y1}) {
        const Point c{x, y};
        if (std::find(out.begin(), out.end(), c) == out.end()) out.push_back(c);
      }
    }
    return out;
  }

  // Does any piece at the given nodes meet another wrongly, where they are now? Pieces whose boxes
  // (where their ends are now) do not overlap are not asked.
  bool wrongNear(const std::vector<std::uint32_t>& nodes) {
    for (const std::uint32_t v : nodes) {
      for (const std::uint32_t p : piecesAt_[v]) {
        const Box bp = box(p, false);
        bool wrong = false;
        grid_->near(widened_[p], [&](std::uint32_t q) {
          if (!wrong && q != p && overlap(bp, box(q, false)) && meetWrongly(p, q)) wrong = true;
        });
        if (wrong) return true;
      }
    }
    return false;
  }

  // Other faithful roundings for the crossing nodes at the ends of pieces p and q, fewest changes
  // first, until no piece at those nodes meets another wrongly. False when none does it.
  bool repair(std::uint32_t p, std::uint32_t q) {
    std::vector<std::uint32_t> nodes;
    for (const std::uint32_t v : {n_.pieceFrom[p], n_.pieceTo[p], n_.pieceFrom[q], n_.pieceTo[q]}) {
      if (!n_.isExact(v) && std::find(nodes.begin(), nodes.end(), v) == nodes.end()) nodes.push_back(v);
    }
    std::vector<std::vector<Point>> options;
    for (const std::uint32_t v : nodes) options.push_back(choices(v));
    const std::vector<Point> original = [&] {
      std::vector<Point> o;
      for (const std::uint32_t v : nodes) o.push_back(at_[v]);
      return o;
    }();
    // Assignments as one index per node into its options (0: where it is now), tried by the
    // number of nodes they move.
    const std::size_t k = nodes.size();
    for (std::size_t moves = 1; moves <= k; ++moves) {
      std::vector<std::size_t> pick(k, 0);
      for (;;) {
        // The next assignment of indices (odometer) with exactly `moves` nodes not at option 0.
        std::size_t i = 0;
        for (; i < k; ++i) {
          if (++pick[i] < options[i].size()) break;
          pick[i] = 0;
        }
        if (i == k) break;
        std::size_t moved = 0;
        for (std::size_t j = 0; j < k; ++j) moved += pick[j] != 0;
        if (moved != moves) continue;
        for (std::size_t j = 0; j < k; ++j) at_[nodes[j]] = pick[j] == 0 ? original[j] : options[j][pick[j]];
        // The pair itself first: most assignments fail there, at the cost of one test.
        if (!meetWrongly(p, q) && !wrongNear(nodes)) return true;
      }
    }
    for (std::size_t j = 0; j < k; ++j) at_[nodes[j]] = original[j];
    return false;
  }

  PlaneGraph graph(RoundingStats& stats) const {
    std::vector<std::pair<Point, Point>> segments(pieceCount());
    for (std::uint32_t p = 0; p < pieceCount(); ++p) segments[p] = {from(p), to(p)};
    stats.merged = mergedNodes(at_);
    return planeGraph(segments);
  }

  const NodedBoundary& n_;
  const LinedRings& rings_;
  ExactCounters& counters_;
  std::vector<Point> at_;  // each node's rounding now
  std::vector<Box> widened_;
  std::unique_ptr<BoxGrid> grid_;
  std::vector<std::vector<std::uint32_t>> piecesAt_;
};

}  // namespace

bool meetWrongly(Point a, Point b, Point c, Point d, ExactCounters& counters) {
  if (a == b || c == d) return false;
  if ((a == c && b == d) || (a == d && b == c)) return false;
  if (a == c || a == d || b == c || b == d) {
    const Point w = a == c || a == d ? a : b;
    const Point x = w == a ? b : a, y = w == c ? d : c;
    return orientation(w, x, y, counters) == Sign::Zero && sameWay(w, x, y);
  }
  return meeting(a, b, c, d, counters) != Meeting::Disjoint;
}

namespace {
bool lexLess(Point a, Point b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }
}  // namespace

PlaneGraph planeGraph(const std::vector<std::pair<Point, Point>>& segments) {
  // The distinct ends by sorting (numbered in order of first appearance), not by a hash map:
  // with a million segments the map's allocations and rehashes were a tenth of the layout.
  PlaneGraph g;
  std::vector<std::pair<Point, std::uint32_t>> ends;  // (end, 2k or 2k + 1)
  ends.reserve(2 * segments.size());
  for (std::uint32_t k = 0; k < segments.size(); ++k) {
    ends.emplace_back(segments[k].first, 2 * k);
    ends.emplace_back(segments[k].second, 2 * k + 1);
  }
  std::stable_sort(ends.begin(), ends.end(), [](const auto& p, const auto& q) {
    return std::tie(p.first.x, p.first.y, p.second) < std::tie(q.first.x, q.first.y, q.second);
  });
  std::vector<std::uint32_t> firstOf(ends.size());  // each end's first appearance among equal ends
  for (std::size_t i = 0; i < ends.size(); ++i) {
    firstOf[ends[i].second] = i > 0 && ends[i].first == ends[i - 1].first ? firstOf[ends[i - 1].second] : ends[i].second;
  }
  std::vector<std::uint32_t> vertexOf(ends.size(), 0xffffffffu);
  for (std::uint32_t i = 0; i < vertexOf.size(); ++i) {
    if (firstOf[i] == i) {
      vertexOf[i] = static_cast<std::uint32_t>(g.vertices.size());
      g.vertices.push_back(i % 2 == 0 ? segments[i / 2].first : segments[i / 2].second);
    } else {
      vertexOf[i] = vertexOf[firstOf[i]];
    }
  }
  std::vector<std::uint64_t> keys;
  keys.reserve(segments.size());
  for (std::uint32_t k = 0; k < segments.size(); ++k) {
    const std::uint32_t u = vertexOf[2 * k], v = vertexOf[2 * k + 1];
    if (u != v) keys.push_back(std::uint64_t{std::min(u, v)} << 32 | std::max(u, v));
  }
  std::stable_sort(keys.begin(), keys.end());
  for (std::size_t i = 0, j; i < keys.size(); i = j) {
    for (j = i + 1; j < keys.size() && keys[j] == keys[i]; ++j) {
    }
    if ((j - i) % 2 == 1) g.edges.emplace_back(static_cast<std::uint32_t>(keys[i] >> 32), static_cast<std::uint32_t>(keys[i]));
  }
  return g;
}

std::uint64_t mergedNodes(const std::vector<Point>& positions) {
  std::vector<Point> sorted = positions;
  std::stable_sort(sorted.begin(), sorted.end(), lexLess);
  std::uint64_t merged = 0;
  for (std::size_t i = 1; i < sorted.size(); ++i) merged += sorted[i] == sorted[i - 1];
  return merged;
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> wrongEdges(const PlaneGraph& g, ExactCounters& counters) {
  std::vector<Box> boxes(g.edges.size());
  for (std::uint32_t e = 0; e < g.edges.size(); ++e) {
    const Point a = g.vertices[g.edges[e].first], b = g.vertices[g.edges[e].second];
    boxes[e] = {std::min(a.x, b.x), std::max(a.x, b.x), std::min(a.y, b.y), std::max(a.y, b.y), e};
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> wrong;
  forEachOverlappingPair(boxes, [&](std::uint32_t e, std::uint32_t f) {
    const Point a = g.vertices[g.edges[e].first], b = g.vertices[g.edges[e].second];
    const Point c = g.vertices[g.edges[f].first], d = g.vertices[g.edges[f].second];
    if (meetWrongly(a, b, c, d, counters)) wrong.emplace_back(std::min(e, f), std::max(e, f));
  });
  std::sort(wrong.begin(), wrong.end());
  return wrong;
}

std::string pointText(Point p) {
  std::ostringstream s;
  s.precision(17);
  s << "(" << p.x << " " << p.y << ")";
  return s.str();
}

PlaneGraph roundNodes(const NodedBoundary& noded, const LinedRings& rings, ExactCounters& counters, RoundingStats& stats) {
  Rounder rounder(noded, rings, counters);
  std::vector<std::uint32_t> trouble;
  if (std::optional<PlaneGraph> g = rounder.run(stats, trouble)) return std::move(*g);
  stats = {};
  stats.snapRounded = true;
  return snapRoundAround(noded, rings, rounder.positions(), trouble, counters, stats);
}


}  // namespace gh::detail
