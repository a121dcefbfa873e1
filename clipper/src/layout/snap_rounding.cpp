#include "layout/snap_rounding.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <unordered_map>

#include "ghclip/ogc_layout.h"
#include "point_hash.h"
#include "predicates/exact_point.h"
#include "predicates/orientation.h"
#include "search/box_grid.h"

namespace gh::detail {
namespace {

// The cell of a double d along one axis: the values nearer to d than to its neighbours, closed.
void cellOf(double d, mpq_class& low, mpq_class& high) {
  low = (mpq_class(d) + std::nextafter(d, -INFINITY)) / 2;
  high = (mpq_class(d) + std::nextafter(d, INFINITY)) / 2;
}

bool inCell(const ExactPoint& p, Point centre) {
  mpq_class x0, x1, y0, y1;
  cellOf(centre.x, x0, x1), cellOf(centre.y, y0, y1);
  return x0 <= p.x && p.x <= x1 && y0 <= p.y && p.y <= y1;
}

// Where the segment a -> b meets the closed box [x0, x1] x [y0, y1], as the parameters along it
// where it enters and leaves (Liang and Barsky); false when it misses the box.
bool clip(const ExactPoint& a, const ExactPoint& b, const mpq_class& x0, const mpq_class& x1, const mpq_class& y0,
          const mpq_class& y1, mpq_class& enter, mpq_class& leave) {
  enter = 0, leave = 1;
  auto axis = [&](const mpq_class& from, const mpq_class& delta, const mpq_class& lo, const mpq_class& hi) {
    if (delta == 0) return lo <= from && from <= hi;
    mpq_class t0 = (lo - from) / delta, t1 = (hi - from) / delta;
    if (t0 > t1) swap(t0, t1);
    if (t0 > enter) enter = t0;
    if (t1 < leave) leave = t1;
    return enter <= leave;
  };
  return axis(a.x, b.x - a.x, x0, x1) && axis(a.y, b.y - a.y, y0, y1);
}

// v moved `steps` doubles towards `toward`.
double step(double v, double toward, int steps) {
  for (int i = 0; i < steps && std::isfinite(v); ++i) v = std::nextafter(v, toward);
  return v;
}

// The box of a and b, `steps` doubles wider on every side.
Box widened(Point a, Point b, int steps) {
  return {step(std::min(a.x, b.x), -INFINITY, steps), step(std::max(a.x, b.x), INFINITY, steps),
          step(std::min(a.y, b.y), -INFINITY, steps), step(std::max(a.y, b.y), INFINITY, steps), 0};
}

bool holds(const Box& b, Point p) { return p.x >= b.minX && p.x <= b.maxX && p.y >= b.minY && p.y <= b.maxY; }

class Snapper {
 public:
  Snapper(const NodedBoundary& noded, const LinedRings& rings, const std::vector<Point>& positions, ExactCounters& counters)
      : n_(noded), rings_(rings), counters_(counters), base_(positions), exact_(noded.rounded.size()) {
    std::vector<Box> nodes(base_.size());
    for (std::uint32_t v = 0; v < base_.size(); ++v) nodes[v] = {base_[v].x, base_[v].x, base_[v].y, base_[v].y, v};
    nodeGrid_ = std::make_unique<BoxGrid>(nodes);
    piecesAt_.resize(base_.size());
    for (std::uint32_t p = 0; p < noded.pieceFrom.size(); ++p) {
      piecesAt_[noded.pieceFrom[p]].push_back(p);
      piecesAt_[noded.pieceTo[p]].push_back(p);
    }
  }

  // The trouble nodes snapped, and with them every node in their cells; while the paths still meet
  // wrongly somewhere, the nodes at the ends of the edges there join the trouble.
  PlaneGraph run(const std::vector<std::uint32_t>& trouble, RoundingStats& stats) {
    std::vector<char> inTrouble(base_.size(), 0);
    std::vector<std::uint32_t> joining = trouble;
    std::string refusal;
    for (;;) {
      bool grew = false;
      for (const std::uint32_t v : joining) {
        if (!inTrouble[v]) inTrouble[v] = 1, grew = true;
      }
      if (!grew) throw LayoutRefusal(refusal);
      std::vector<Point> wrongEnds;
      if (std::optional<PlaneGraph> g = snap(inTrouble, stats, wrongEnds, refusal)) return std::move(*g);
      joining.clear();
      for (const Point q : wrongEnds) {
        nodeGrid_->near(widened(q, q, 2), [&](std::uint32_t v) {
          if (base_[v] == q || at_[v] == q) joining.push_back(v);
        });
      }
    }
  }

 private:
  const ExactPoint& exact(std::uint32_t v) {
    if (!exact_[v]) {
      if (n_.isExact(v)) {
        exact_[v] = exactPoint(n_.rounded[v]);
      } else {
        const LinedRings::Line &a = rings_.lines[n_.lineA[v]], &b = rings_.lines[n_.lineB[v]];
        exact_[v] = exactCrossingPoint(a.from, a.to, b.from, b.to);
      }
    }
    return *exact_[v];
  }

  // Snap rounding of the trouble nodes and of the pieces through their cells; the graph, or nothing
  // when it meets itself wrongly (wrongEnds then holds the ends of the edges that do).
  std::optional<PlaneGraph> snap(const std::vector<char>& inTrouble, RoundingStats& stats, std::vector<Point>& wrongEnds,
                                 std::string& refusal) {
    // Every node in the region to its nearest double, the centre of a hot cell; then every node
    // whose exact point lies in a hot cell too (its nearest double is that centre).
    at_ = base_;
    std::vector<Point> hot;
    nodesAt_.clear();
    std::vector<char> snapped(at_.size(), 0);
    auto snapNode = [&](std::uint32_t v) {
      snapped[v] = 1;
      at_[v] = {nearestDouble(exact(v).x), nearestDouble(exact(v).y)};
      std::vector<std::uint32_t>& there = nodesAt_[at_[v]];
      if (there.empty()) hot.push_back(at_[v]);
      there.push_back(v);
    };
    for (std::uint32_t v = 0; v < at_.size(); ++v) {
      if (inTrouble[v]) snapNode(v);
    }
    for (std::size_t h = 0; h < hot.size(); ++h) {
      const Point centre = hot[h];
      nodeGrid_->near(widened(centre, centre, 2), [&](std::uint32_t v) {
        if (!snapped[v] && inCell(exact(v), centre)) snapNode(v);
      });
    }
    // Every piece near the region as the path through the hot cells it passes through, in order.
    std::vector<Box> cells(hot.size());
    for (std::uint32_t c = 0; c < hot.size(); ++c) cells[c] = {hot[c].x, hot[c].x, hot[c].y, hot[c].y, c};
    BoxGrid hotGrid(cells);
    struct Passed {
      mpq_class enter, leave;
      Point centre;
    };
    std::vector<Passed> passed;
    std::vector<std::pair<Point, Point>> segments;
    mpq_class x0, x1, y0, y1, enter, leave;
    stats.routed = 0;
    for (std::uint32_t p = 0; p < n_.pieceFrom.size(); ++p) {
      const std::uint32_t a = n_.pieceFrom[p], b = n_.pieceTo[p];
      // A piece lies within an ulp of the box of its ends' doubles, and a cell it meets has its
      // centre within one more (two steps: cells beyond a power of two are twice the size).
      const Box near = widened(at_[a], at_[b], 2);
      passed.clear();
      const LinedRings::Line& line = rings_.lines[n_.pieceLine[p]];
      hotGrid.near(near, [&](std::uint32_t c) {
        const Point centre = hot[c];
        if (!holds(near, centre) || centre == at_[a] || centre == at_[b]) return;
        // The cell lies within the box of the doubles around its centre: when all four corners of
        // that box lie on one side of the piece's line, the piece misses the cell.
        const Point lo{std::nextafter(centre.x, -INFINITY), std::nextafter(centre.y, -INFINITY)};
        const Point hi{std::nextafter(centre.x, INFINITY), std::nextafter(centre.y, INFINITY)};
        const Sign s = orientation(line.from, line.to, lo, counters_);
        if (s != Sign::Zero && orientation(line.from, line.to, hi, counters_) == s &&
            orientation(line.from, line.to, {lo.x, hi.y}, counters_) == s &&
            orientation(line.from, line.to, {hi.x, lo.y}, counters_) == s) {
          return;
        }
        cellOf(centre.x, x0, x1), cellOf(centre.y, y0, y1);
        if (clip(exact(a), exact(b), x0, x1, y0, y1, enter, leave)) passed.push_back({enter, leave, centre});
      });
      std::sort(passed.begin(), passed.end(), [](const Passed& u, const Passed& v) {
        return u.enter != v.enter ? u.enter < v.enter : u.leave < v.leave;
      });
      stats.routed += passed.size();
      Point last = at_[a];
      for (const Passed& q : passed) segments.emplace_back(last, q.centre), last = q.centre;
      segments.emplace_back(last, at_[b]);
    }
    PlaneGraph g = planeGraph(segments);
    stats.merged = mergedNodes(at_);
    stats.rerounded = 0;
    for (std::uint32_t v = 0; v < at_.size(); ++v) stats.rerounded += !(at_[v] == n_.rounded[v]);
    const std::vector<std::pair<std::uint32_t, std::uint32_t>> wrong = wrongEdges(g, counters_);
    if (wrong.empty()) return g;
    for (const auto& [e, f] : wrong) {
      for (const std::uint32_t v : {g.edges[e].first, g.edges[e].second, g.edges[f].first, g.edges[f].second}) {
        wrongEnds.push_back(g.vertices[v]);
      }
    }
    const auto [e, f] = wrong.front();
    refusal = "the rounded boundary meets itself: " + pointText(g.vertices[g.edges[e].first]) + " - " +
              pointText(g.vertices[g.edges[e].second]) + " and " + pointText(g.vertices[g.edges[f].first]) + " - " +
              pointText(g.vertices[g.edges[f].second]) + " meet within ulps of rounded crossings, even snap-rounded";
    return std::nullopt;
  }

  const NodedBoundary& n_;
  const LinedRings& rings_;
  ExactCounters& counters_;
  std::vector<std::vector<std::uint32_t>> piecesAt_;
  std::unordered_map<Point, std::vector<std::uint32_t>, PointHash> nodesAt_;  // the nodes in each hot cell
  const std::vector<Point>& base_;  // where the faithful roundings put every node
  std::vector<Point> at_;           // where this round puts them
  std::vector<std::optional<ExactPoint>> exact_;
  std::unique_ptr<BoxGrid> nodeGrid_;  // the nodes by base_
};

}  // namespace

PlaneGraph snapRoundAround(const NodedBoundary& noded, const LinedRings& rings, const std::vector<Point>& positions,
                           const std::vector<std::uint32_t>& trouble, ExactCounters& counters, RoundingStats& stats) {
  return Snapper(noded, rings, positions, counters).run(trouble, stats);
}

}  // namespace gh::detail
