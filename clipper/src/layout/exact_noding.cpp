#include "layout/exact_noding.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include "ghclip/errors.h"
#include "point_hash.h"
#include "predicates/construction.h"
#include "predicates/orientation.h"
#include "predicates/point_on_line.h"
#include "search/box_overlaps.h"

namespace gh::detail {
namespace {

// Nodes that are one exact point, merged: the root of a class is an exact node where the class has
// one (its double is the point itself), else its smallest node (a deterministic choice among
// faithful roundings of one point).
class NodeClasses {
 public:
  void add(bool exact) {
    parent_.push_back(static_cast<std::uint32_t>(parent_.size()));
    exact_.push_back(exact);
  }
  std::uint32_t find(std::uint32_t n) {
    while (parent_[n] != n) n = parent_[n] = parent_[parent_[n]];
    return n;
  }
  void unite(std::uint32_t a, std::uint32_t b) {
    a = find(a), b = find(b);
    if (a == b) return;
    const bool aFirst = exact_[a] != exact_[b] ? exact_[a] : a < b;
    if (aFirst) {
      parent_[b] = a;
    } else {
      parent_[a] = b;
    }
  }
  std::size_t size() const { return parent_.size(); }

 private:
  std::vector<std::uint32_t> parent_;
  std::vector<char> exact_;
};

// A node placed strictly inside an edge, as a point on the edge's line.
struct Split {
  std::uint32_t edge;
  std::uint32_t node;
  PointOnLine at;
};

class Noder {
 public:
  Noder(const LinedRings& rings, ExactCounters& counters) : r_(rings), counters_(counters) {}

  NodedBoundary run() {
    validateAndLink();
    for (std::uint32_t v = 0; v < r_.points.size(); ++v) {
      classes_.add(r_.exact[v] != 0);
      rounded_.push_back(r_.points[v]);
      lineA_.push_back(r_.exact[v] ? kNoLine : r_.line[prev_[v]]);
      lineB_.push_back(r_.exact[v] ? kNoLine : r_.line[v]);
    }
    uniteByIdentity();
    orientEdges();
    findMeetings();
    return pieces();
  }

 private:
  using Line = LinedRings::Line;
  const Line& lineOf(std::uint32_t l) const { return r_.lines[l]; }
  int compare(std::uint32_t l, const PointOnLine& u, const PointOnLine& v) {
    return compareOnLine(lineOf(l).from, lineOf(l).to, u, v, counters_);
  }
  bool parallel(std::uint32_t l, std::uint32_t m) {
    return crossSign(lineOf(l).from, lineOf(l).to, lineOf(m).from, lineOf(m).to, counters_) == Sign::Zero;
  }
  // Vertex v as a point on line l, which passes through it: the double, or l's crossing with one of
  // v's two lines that is not parallel to l.
  PointOnLine onLine(std::uint32_t v, std::uint32_t l) {
    if (r_.exact[v]) return PointOnLine::exact(r_.points[v]);
    std::uint32_t other = r_.line[prev_[v]];
    if (other == l || parallel(l, other)) other = r_.line[v];
    return PointOnLine::crossingWith(lineOf(other).from, lineOf(other).to);
  }

  [[noreturn]] static void invalid(const std::string& why) { throw InvalidInput("lined rings: " + why); }

  void validateAndLink() {
    const std::size_t n = r_.points.size();
    if (r_.line.size() != n || r_.exact.size() != n || r_.ringStart.empty() || r_.ringStart.front() != 0 ||
        r_.ringStart.back() != n) {
      invalid("the per-vertex arrays and the ring starts do not match the points");
    }
    if (n >= kNoLine / 2) invalid("too many vertices");
    for (const Line& l : r_.lines) {
      if (!(std::isfinite(l.from.x) && std::isfinite(l.from.y) && std::isfinite(l.to.x) && std::isfinite(l.to.y)) ||
          l.from == l.to) {
        invalid("a line needs two distinct finite points");
      }
    }
    next_.resize(n), prev_.resize(n);
    for (std::size_t k = 0; k + 1 < r_.ringStart.size(); ++k) {
      const std::uint32_t first = r_.ringStart[k], end = r_.ringStart[k + 1];
      if (end < first) invalid("ring starts out of order");
      for (std::uint32_t v = first; v < end; ++v) {
        next_[v] = v + 1 < end ? v + 1 : first;
        prev_[v] = v > first ? v - 1 : end - 1;
      }
    }
    for (std::uint32_t v = 0; v < n; ++v) {
      if (r_.line[v] >= r_.lines.size()) invalid("a line index out of range");
      if (!std::isfinite(r_.points[v].x) || !std::isfinite(r_.points[v].y)) invalid("a non-finite vertex");
    }
    for (std::uint32_t v = 0; v < n; ++v) {
      const std::uint32_t in = r_.line[prev_[v]], out = r_.line[v];
      if (r_.exact[v]) {
        // An exact vertex lies on the lines of both its edges.
        for (const std::uint32_t l : {in, out}) {
          if (orientation(lineOf(l).from, lineOf(l).to, r_.points[v], counters_) != Sign::Zero) {
            invalid("vertex " + std::to_string(v) + " is off the line of its edge");
          }
        }
      } else if (in == out || parallel(in, out)) {
        invalid("vertex " + std::to_string(v) + " is the crossing of two parallel lines");
      }
    }
  }

  // Vertices that are one point by their definition (one double, or the crossing of the same two
  // lines: an answer's crossing where two of its rings meet, or traced twice by xor) are one node
  // from the start.
  void uniteByIdentity() {
    // By sorting (a hash map's allocations and rehashes cost more at a million vertices).
    std::vector<std::pair<std::uint64_t, std::uint32_t>> crossings;
    std::vector<std::pair<Point, std::uint32_t>> doubles;
    for (std::uint32_t v = 0; v < r_.points.size(); ++v) {
      if (r_.exact[v]) {
        doubles.emplace_back(r_.points[v], v);
        continue;
      }
      const std::uint32_t a = r_.line[prev_[v]], b = r_.line[v];
      crossings.emplace_back(std::uint64_t{std::min(a, b)} << 32 | std::max(a, b), v);
    }
    std::sort(crossings.begin(), crossings.end());
    for (std::size_t i = 1; i < crossings.size(); ++i) {
      if (crossings[i].first == crossings[i - 1].first) classes_.unite(crossings[i - 1].second, crossings[i].second);
    }
    std::stable_sort(doubles.begin(), doubles.end(), [](const auto& p, const auto& q) {
      return std::tie(p.first.x, p.first.y, p.second) < std::tie(q.first.x, q.first.y, q.second);
    });
    for (std::size_t i = 1; i < doubles.size(); ++i) {
      if (doubles[i].first == doubles[i - 1].first) classes_.unite(doubles[i - 1].second, doubles[i].second);
    }
  }

  // direction_[e]: the order along its line of edge e's start and end (-1 when the edge runs from
  // the line's `from` towards its `to`), 0 for an edge of no length, whose ends are one node.
  void orientEdges() {
    direction_.resize(r_.points.size());
    for (std::uint32_t e = 0; e < r_.points.size(); ++e) {
      const std::uint32_t l = r_.line[e];
      direction_[e] = static_cast<std::int8_t>(compare(l, onLine(e, l), onLine(next_[e], l)));
      if (direction_[e] == 0) classes_.unite(e, next_[e]);
    }
  }

  // Where point u lies on edge e (on e's line): -2 outside, -1 at its start, +1 at its end, 0
  // strictly inside.
  // `node`: u's node when it has one. Nodes known to be one point (classes_) are placed without a
  // predicate: the ties of an exact comparison are its slowest answers.
  int place(std::uint32_t e, const PointOnLine& u, std::uint32_t node = kNoLine) {
    if (node != kNoLine) {
      const std::uint32_t n = classes_.find(node);
      if (n == classes_.find(e)) return -1;
      if (n == classes_.find(next_[e])) return +1;
    }
    const std::uint32_t l = r_.line[e];
    const int a = compare(l, onLine(e, l), u);
    if (a == 0) return -1;
    const int b = compare(l, u, onLine(next_[e], l));
    if (b == 0) return +1;
    return a == b ? 0 : -2;
  }
  std::uint32_t endNode(std::uint32_t e, int where) const { return where < 0 ? e : next_[e]; }

  // Every pair of edges whose boxes overlap, decided exactly. The boxes are widened by an ulp on
  // each side of every rounded vertex: the exact vertex lies within it.
  void findMeetings() {
    std::vector<Box> boxes;
    boxes.reserve(r_.points.size());
    for (std::uint32_t e = 0; e < r_.points.size(); ++e) {
      if (direction_[e] == 0) continue;
      Box b{INFINITY, -INFINITY, INFINITY, -INFINITY, e};
      for (const std::uint32_t v : {e, next_[e]}) {
        const Point p = r_.points[v];
        const double wide = r_.exact[v] ? 0 : INFINITY;
        b.minX = std::min(b.minX, wide > 0 ? std::nextafter(p.x, -wide) : p.x);
        b.maxX = std::max(b.maxX, wide > 0 ? std::nextafter(p.x, wide) : p.x);
        b.minY = std::min(b.minY, wide > 0 ? std::nextafter(p.y, -wide) : p.y);
        b.maxY = std::max(b.maxY, wide > 0 ? std::nextafter(p.y, wide) : p.y);
      }
      boxes.push_back(b);
    }
    forEachOverlappingPair(boxes, [this](std::uint32_t e, std::uint32_t f) { meet(e, f); });
  }

  void meet(std::uint32_t e, std::uint32_t f) {
    const std::uint32_t le = r_.line[e], lf = r_.line[f];
    const bool parallelLines = le == lf || parallel(le, lf);
    // Consecutive edges share a vertex; they meet elsewhere only when they fold back on one line.
    if ((next_[e] == f || next_[f] == e) && !parallelLines) return;
    if (!parallelLines) {
      if (clearlyAside(e, f) || clearlyAside(f, e)) return;
      meetAtCrossing(e, f);
    } else if (le == lf || orientation(lineOf(le).from, lineOf(le).to, lineOf(lf).from, counters_) == Sign::Zero) {
      overlap(e, f), overlap(f, e);  // one line: each edge's ends that lie inside the other
    }
  }

  // Do both ends of edge f lie strictly on one side of edge e's line, by a margin that covers the
  // rounding of f's ends (each exact vertex within an ulp of its double in each coordinate) and of
  // the arithmetic (Shewchuk's stage A)? Then e and f do not meet, and no exact predicate is asked:
  // on inputs whose edges all overlap in their boxes (the paper's random polygons, the fuzz
  // targets' raw doubles) most candidate pairs end here.
  bool clearlyAside(std::uint32_t e, std::uint32_t f) const {
    const Line& l = lineOf(r_.line[e]);
    const double dx = std::abs(l.to.x - l.from.x), dy = std::abs(l.to.y - l.from.y);
    int side = 0;
    for (const std::uint32_t v : {f, next_[f]}) {
      const Point p = r_.points[v];
      const FilteredDeterminant d = orientationDeterminant(l.from, l.to, p);
      // |exact - p| <= 2^-52 |p| + 2^-1074 in each coordinate moves the determinant by at most that
      // times the line's extent in the other coordinate; 2^-50 and 2^-1072 leave room for the
      // rounding of this bound itself.
      const double moved = r_.exact[v] ? 0 : (std::abs(p.x) * 0x1p-50 + 0x1p-1072) * dy + (std::abs(p.y) * 0x1p-50 + 0x1p-1072) * dx;
      const double margin = (d.bound + moved) * (1 + 0x1p-20);
      if (!(std::abs(d.value) > margin)) return false;  // also infinite bounds and NaN
      const int s = d.value > 0 ? 1 : -1;
      if (side != 0 && s != side) return false;
      side = s;
    }
    return true;
  }

  // Edges on lines that cross: they meet, if at all, at the crossing X of their lines. Where an end
  // of one line lies on the other, X is that double (degenerate inputs: edges through one input
  // vertex), and every comparison with it is an orientation of doubles instead of an order of
  // crossings, whose ties would need exact arithmetic to show.
  void meetAtCrossing(std::uint32_t e, std::uint32_t f) {
    const Line &le = lineOf(r_.line[e]), &lf = lineOf(r_.line[f]);
    std::optional<Point> atDouble;
    for (const auto& [on, end] : {std::pair{&le, lf.from}, std::pair{&le, lf.to}, std::pair{&lf, le.from}, std::pair{&lf, le.to}}) {
      if (orientation(on->from, on->to, end, counters_) == Sign::Zero) {
        atDouble = end;
        break;
      }
    }
    const PointOnLine onLe = atDouble ? PointOnLine::exact(*atDouble) : PointOnLine::crossingWith(lf.from, lf.to);
    const int onE = place(e, onLe);
    if (onE == -2) return;
    const PointOnLine onLf = atDouble ? PointOnLine::exact(*atDouble) : PointOnLine::crossingWith(le.from, le.to);
    const int onF = place(f, onLf);
    if (onF == -2) return;
    std::uint32_t node;
    if (onE != 0 && onF != 0) {
      classes_.unite(endNode(e, onE), endNode(f, onF));  // an end of each: one point
      return;
    }
    if (onE != 0) {
      node = endNode(e, onE);
    } else if (onF != 0) {
      node = endNode(f, onF);
    } else if (atDouble) {
      node = exactNode(*atDouble);
    } else {
      node = newNode(r_.line[e], r_.line[f]);
    }
    if (onE == 0) splits_.push_back({e, node, onLe});
    if (onF == 0) splits_.push_back({f, node, onLf});
  }

  // Edges e and f on one line: f's ends that lie on e.
  void overlap(std::uint32_t e, std::uint32_t f) {
    const std::uint32_t l = r_.line[e];
    for (const std::uint32_t v : {f, next_[f]}) {
      const PointOnLine at = onLine(v, l);
      const int where = place(e, at, v);
      if (where == 0) {
        splits_.push_back({e, v, at});
      } else if (where != -2) {
        classes_.unite(v, endNode(e, where));
      }
    }
  }

  // A node at a double that is no vertex of the rings (an input vertex another edge passes through).
  std::uint32_t exactNode(Point p) {
    classes_.add(true);
    rounded_.push_back(p);
    lineA_.push_back(kNoLine), lineB_.push_back(kNoLine);
    return static_cast<std::uint32_t>(classes_.size() - 1);
  }

  std::uint32_t newNode(std::uint32_t a, std::uint32_t b) {
    const Line &la = lineOf(a), &lb = lineOf(b);
    classes_.add(false);
    rounded_.push_back(constructCrossing(la.from, la.to, lb.from, lb.to, counters_));
    lineA_.push_back(a), lineB_.push_back(b);
    ++newNodes_;
    return static_cast<std::uint32_t>(classes_.size() - 1);
  }

  // Each edge cut at its splits in order along it; the pieces counted modulo 2.
  NodedBoundary pieces() {
    std::sort(splits_.begin(), splits_.end(), [this](const Split& s, const Split& t) {
      if (s.edge != t.edge) return s.edge < t.edge;
      // Along the edge from its start: the line's order, reversed for an edge that runs backwards.
      return compare(r_.line[s.edge], s.at, t.at) * -direction_[s.edge] < 0;
    });
    for (std::size_t i = 1; i < splits_.size(); ++i) {
      const Split &s = splits_[i - 1], &t = splits_[i];
      if (s.edge != t.edge || classes_.find(s.node) == classes_.find(t.node)) continue;
      if (compare(r_.line[s.edge], s.at, t.at) == 0) classes_.unite(s.node, t.node);
    }
    std::vector<Piece> raw;
    raw.reserve(r_.points.size() + splits_.size());
    for (std::size_t i = 0, e = 0; e < r_.points.size(); ++e) {
      std::size_t end = i;
      while (end < splits_.size() && splits_[end].edge == e) ++end;
      if (direction_[e] != 0) {
        std::uint32_t from = classes_.find(static_cast<std::uint32_t>(e));
        auto cut = [&](std::uint32_t node) {
          const std::uint32_t to = classes_.find(node);
          if (to != from) raw.push_back({from, to, r_.line[e]});
          from = to;
        };
        for (std::size_t s = i; s < end; ++s) cut(splits_[s].node);
        cut(next_[e]);
      }
      i = end;
    }
    return evenOdd(std::move(raw));
  }

  struct Piece {
    std::uint32_t from, to, line;
    std::uint64_t key() const { return std::uint64_t{std::min(from, to)} << 32 | std::max(from, to); }
  };

  NodedBoundary evenOdd(std::vector<Piece> raw) {
    // Copies of one piece (the same two nodes: the same segment) cancel in pairs.
    std::stable_sort(raw.begin(), raw.end(), [](const Piece& a, const Piece& b) { return a.key() < b.key(); });
    std::vector<Piece> kept;
    for (std::size_t i = 0, j; i < raw.size(); i = j) {
      for (j = i + 1; j < raw.size() && raw[j].key() == raw[i].key(); ++j) {
      }
      if ((j - i) % 2 == 1) kept.push_back(raw[i]);
    }
    joinStraightRuns(kept);
    // The nodes the pieces use, numbered in order of first use.
    NodedBoundary out;
    std::vector<std::uint32_t> number(classes_.size(), kNoLine);
    auto use = [&](std::uint32_t n) {
      if (number[n] == kNoLine) {
        number[n] = static_cast<std::uint32_t>(out.rounded.size());
        out.rounded.push_back(rounded_[n]);
        out.lineA.push_back(lineA_[n]), out.lineB.push_back(lineB_[n]);
      }
      return number[n];
    };
    for (const Piece& p : kept) {
      out.pieceFrom.push_back(use(p.from));
      out.pieceTo.push_back(use(p.to));
      out.pieceLine.push_back(p.line);
    }
    out.newNodes = 0;
    for (std::size_t n = r_.points.size(); n < classes_.size(); ++n) out.newNodes += number[n] != kNoLine;
    return out;
  }

  // A node with two pieces left on one line, one on each side, is where the boundary goes straight
  // on: the two become one piece (any number of such nodes in a row).
  void joinStraightRuns(std::vector<Piece>& pieces) {
    std::vector<std::uint32_t> degree(classes_.size(), 0), firstAt(classes_.size(), kNoLine), secondAt(classes_.size(), kNoLine);
    for (std::uint32_t i = 0; i < pieces.size(); ++i) {
      for (const std::uint32_t n : {pieces[i].from, pieces[i].to}) {
        ++degree[n];
        (firstAt[n] == kNoLine ? firstAt[n] : secondAt[n]) = i;
      }
    }
    std::vector<char> straight(classes_.size(), 0);
    bool any = false;
    for (std::uint32_t n = 0; n < classes_.size(); ++n) {
      if (degree[n] != 2) continue;
      const std::uint32_t a = pieces[firstAt[n]].line, b = pieces[secondAt[n]].line;
      straight[n] = a == b || parallel(a, b);  // both through n: one line, and no two pieces overlap
      any |= straight[n] != 0;
    }
    if (!any) return;
    std::vector<char> used(pieces.size(), 0);
    std::vector<Piece> joined;
    auto other = [&](std::uint32_t n, std::uint32_t piece) { return firstAt[n] == piece ? secondAt[n] : firstAt[n]; };
    for (std::uint32_t i = 0; i < pieces.size(); ++i) {
      if (used[i]) continue;
      // Start from a piece end that is a real vertex; pieces of a closed run of straight nodes
      // cannot exist (a ring on one line has no area and cancelled).
      std::uint32_t start = pieces[i].from, cur = i, at = pieces[i].to;
      if (straight[start] && !straight[at]) std::swap(start, at);
      if (straight[start]) continue;  // in the middle of a run: reached from one of its ends
      used[cur] = 1;
      while (straight[at]) {
        cur = other(at, cur);
        used[cur] = 1;
        at = pieces[cur].from == at ? pieces[cur].to : pieces[cur].from;
      }
      joined.push_back({start, at, pieces[i].line});
    }
    pieces.swap(joined);
  }

  const LinedRings& r_;
  ExactCounters& counters_;
  std::vector<std::uint32_t> next_, prev_;
  std::vector<std::int8_t> direction_;
  NodeClasses classes_;
  std::vector<Point> rounded_;  // per node: its own rounding; the class takes its root's
  std::vector<std::uint32_t> lineA_, lineB_;
  std::vector<Split> splits_;
  std::uint64_t newNodes_ = 0;
};

}  // namespace

NodedBoundary nodeExactly(const LinedRings& rings, ExactCounters& counters) { return Noder(rings, counters).run(); }

}  // namespace gh::detail
