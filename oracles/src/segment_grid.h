// How far from a vertex the nearest segment lies that does not pass through it: the sampling
// oracle's clearances, over segments in a uniform grid.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "filtered_orientation.h"
#include "ghclip/region.h"
#include "pooled_vector.h"
#include "uniform_grid.h"

namespace gh::oracle {

// |(x, y)|: sqrt of the sum of squares where neither can over- or underflow (glibc's hypot,
// which guards against both, cost a tenth of the oracle's time), else hypot. Within an ulp or
// two of hypot: the clearance below is used with a margin (0.49 of it, not 0.5).
inline double length(double x, double y) {
  const double squared = x * x + y * y;
  if (squared > 0x1p-1000 && squared < 0x1p1000) return std::sqrt(squared);
  return std::hypot(x, y);
}

// Segments in a uniform grid, for one question: how far from a vertex q the nearest segment lies
// that does not pass through q.
class SegmentGrid {
 public:
  explicit SegmentGrid(const Region& region) {
    for (const Ring& ring : region) {
      for (std::size_t i = 0, n = ring.size(); i < n; ++i) segments_.push_back({ring[i], ring[(i + 1) % n]});
    }
    index();
  }
  explicit SegmentGrid(PooledVector<std::pair<Point, Point>> segments) : segments_(std::move(segments)) { index(); }

  // The segments near a point q: those that pass through q or are counted so, and up to
  // kNearest others, the nearest; and the clearance of all the rest.
  static constexpr std::size_t kNearest = 4;
  struct Nearest {
    PooledVector<std::uint32_t> segments;  // each once
    double beyond = 0;                     // no other segment comes nearer q (0: cannot tell)
  };

  // The least of: the distance from q to every segment that does not pass through q, and the
  // distances from q to the ends of every segment that does (ends there, or crosses there); cap
  // when all are at least cap. 0 when it cannot tell (a distance that over- or underflows).
  // passesNear(i, d) may count segment i, d from q and not through it, as passing through q.
  // With `atQ`, also the segments that end at q or pass through it (decided exactly), each
  // once, complete whenever the clearance is not 0; with `strict`, the clearance with no
  // segment counted as passing through q by passesNear (never more than the one returned); with
  // `nearest`, the segments near q and the clearance of all the others (Nearest).
  // onSegment(i, d, through), when given, sees every segment i the walk reaches, its distance d
  // from q, and whether it passes through q or is counted so: a segment the walk does not reach
  // lies farther from q than the clearance returned.
  template <class PassesNear, class OnSegment = void (*)(std::uint32_t, double, bool)>
  double clearance(Point q, double cap, PassesNear&& passesNear, std::vector<std::uint32_t>* atQ = nullptr,
                   double* strict = nullptr, Nearest* nearest = nullptr,
                   OnSegment&& onSegment = [](std::uint32_t, double, bool) {}) const {
    double least = cap, strictLeast = cap;
    if (atQ) atQ->clear();
    if (strict) *strict = cap;
    // The clearance without the nearest: `through` for what passes through q (never left out),
    // and the distances of the kNearest + 1 nearest others (each segment once: a segment is listed
    // in every cell its box meets).
    double through = cap;
    std::size_t count = 0;
    std::uint32_t ids[kNearest + 1];
    double distances[kNearest + 1];
    auto beyond = [&] { return std::min(through, count == kNearest + 1 ? distances[kNearest] : cap); };
    auto keep = [&](std::uint32_t id, double d) {
      for (std::size_t i = 0; i < count; ++i) {
        if (ids[i] == id) return;
      }
      if (count == kNearest + 1 && d >= distances[kNearest]) return;
      std::size_t i = count < kNearest + 1 ? count++ : kNearest;
      for (; i > 0 && distances[i - 1] > d; --i) ids[i] = ids[i - 1], distances[i] = distances[i - 1];
      ids[i] = id, distances[i] = d;
    };
    if (nearest) nearest->segments.clear(), nearest->beyond = cap;
    if (segments_.empty()) return least;
    // A box farther than `least` from q holds nothing nearer, and no segment through q (farther
    // than the clearance without the nearest, when they are asked for).
    auto reach = [&] { return nearest ? beyond() : least; };
    // A segment is listed in every cell it passes through: each is measured once a walk (stamped
    // with the walk's number), the first time its box is within reach (which only shrinks).
    if (++walk_ == 0) std::fill(stamps_.begin(), stamps_.end(), 0), walk_ = 1;
    forCellsNearestFirst(q, cap, reach, [&](std::size_t k) {
      for (std::size_t m = start_[k]; m < start_[k + 1] && least > 0; ++m) {
        const Member& box = members_[m];
        if (stamps_[box.segment] == walk_) continue;
        const double r = reach();
        if (box.x0 - q.x > r || q.x - box.x1 > r || box.y0 - q.y > r || q.y - box.y1 > r) continue;
        stamps_[box.segment] = walk_;
        const auto& s = segments_[box.segment];
        const Distance d = distance(q, s);
        const bool passes = d.interior && d.line < least && passesNear(box.segment, d.line);
        least = std::min(least, passes ? endDistance(q, s) : d.line);
        strictLeast = std::min(strictLeast, d.line);
        onSegment(box.segment, d.line, passes || d.atQ);
        if (atQ && d.atQ) atQ->push_back(box.segment);
        if (nearest) {
          // A segment through q, or counted so, bounds the clearance by its ends; another (even
          // one at an unknown distance, 0) may be left out.
          if (passes || d.atQ) {
            through = std::min(through, passes ? endDistance(q, s) : d.line);
            nearest->segments.push_back(box.segment);
          } else {
            keep(box.segment, d.line);
          }
        }
      }
    });
    if (strict) *strict = strictLeast;  // never more than least: d.line <= endDistance
    if (atQ) {  // a segment is listed in every cell its box meets
      std::sort(atQ->begin(), atQ->end());
      atQ->erase(std::unique(atQ->begin(), atQ->end()), atQ->end());
    }
    if (nearest) {
      std::vector<std::uint32_t>& near = nearest->segments;
      near.insert(near.end(), ids, ids + std::min(count, kNearest));
      std::sort(near.begin(), near.end());
      near.erase(std::unique(near.begin(), near.end()), near.end());
      nearest->beyond = least > 0 ? std::max(least, beyond()) : 0.0;
    }
    return least;
  }
  double clearance(Point q, double cap, std::vector<std::uint32_t>* atQ = nullptr) const {
    return clearance(q, cap, [](std::size_t, double) { return false; }, atQ);
  }
  const std::pair<Point, Point>& segment(std::uint32_t i) const { return segments_[i]; }

 private:
  struct Distance {
    double line;    // from q to the segment (to its ends, for a segment through q), 0 if unknown
    bool interior;  // q projects strictly inside the segment, which does not pass through q
    bool atQ;       // the segment ends at q or passes through it
  };
  // In halves, so that coordinates near 2^256 do not overflow.
  static Distance distance(Point q, const std::pair<Point, Point>& s) {
    const auto& [a, b] = s;
    const double dx = b.x / 2 - a.x / 2, dy = b.y / 2 - a.y / 2;
    if (q == a || q == b) return {length(dx, dy) * 2, false, true};
    const double qx = q.x / 2 - a.x / 2, qy = q.y / 2 - a.y / 2, squared = dx * dx + dy * dy;
    const double t = squared > 0 ? std::clamp((qx * dx + qy * dy) / squared, 0.0, 1.0) : 0.0;
    const double d = length(qx - t * dx, qy - t * dy) * 2;
    if (!std::isfinite(d) || !std::isfinite(t) || (squared <= 0x1p-1000 && squared != 0)) return {0.0, false, false};
    // A segment through q (a crossing of the operands that is a vertex of the answer) is two
    // rays from q, as good as two edges ending there: decided exactly.
    if (d <= 0x1p-40 * length(dx, dy) * 2 && t > 0 && t < 1 && filteredOrientation(a, b, q) == 0) return {endDistance(q, s), false, true};
    return {d, t > 0 && t < 1, false};
  }
  // From q to the nearer end of s, in halves.
  static double endDistance(Point q, const std::pair<Point, Point>& s) {
    const auto& [a, b] = s;
    return std::min(length(q.x / 2 - a.x / 2, q.y / 2 - a.y / 2), length(b.x / 2 - q.x / 2, b.y / 2 - q.y / 2)) * 2;
  }
  void index() {
    if (segments_.empty()) return;
    stamps_.assign(segments_.size(), 0);
    x0_ = y0_ = std::numeric_limits<double>::infinity(), x1_ = y1_ = -x0_;
    for (const auto& [a, b] : segments_) {
      x0_ = std::min({x0_, a.x, b.x}), x1_ = std::max({x1_, a.x, b.x});
      y0_ = std::min({y0_, a.y, b.y}), y1_ = std::max({y1_, a.y, b.y});
    }
    // A segment is listed in the cells it passes through (forCellsNear), so a walk over the cells
    // near q meets every segment that comes near q. About one cell per two segments, fewer while
    // the segments would be listed more than 32 times each on average.
    side_ = listInCells(
        segments_.size(), std::min<std::size_t>(static_cast<std::size_t>(std::sqrt(segments_.size() / 2.0)), 256),
        [&](std::size_t i, std::size_t side, auto&& f) {
          forEachCellNear(segments_[i].first, segments_[i].second, 0.0, x0_, x1_, y0_, y1_, side, f);
        },
        [&](std::size_t i) {
          const auto& [a, b] = segments_[i];
          return Member{std::min(a.x, b.x), std::max(a.x, b.x), std::min(a.y, b.y), std::max(a.y, b.y), static_cast<std::uint32_t>(i)};
        },
        start_, members_);
  }
  std::size_t axis(double v, double lo, double hi) const { return bucket(v, lo, hi, side_); }
  // The cells of the box q +- cap, in rings around q's cell, nearest first, while a ring can hold
  // a point within reach() of q: every point of a cell k rings out lies more than k - 1 cell
  // widths from q (q's cell is the one q is clamped to, by the same monotone function).
  template <class Reach, class F>
  void forCellsNearestFirst(Point q, double cap, Reach&& reach, F&& f) const {
    const std::size_t ax0 = axis(q.x - cap, x0_, x1_), ax1 = axis(q.x + cap, x0_, x1_);
    const std::size_t ay0 = axis(q.y - cap, y0_, y1_), ay1 = axis(q.y + cap, y0_, y1_);
    const std::size_t cx = axis(q.x, x0_, x1_), cy = axis(q.y, y0_, y1_);
    double width = std::min(x1_ - x0_, y1_ - y0_) / static_cast<double>(side_) * (1 - 0x1p-40);
    if (!std::isfinite(width)) width = 0;  // an overflowing range: no ring is passed over
    const std::size_t rings = std::max({cx - ax0, ax1 - cx, cy - ay0, ay1 - cy});
    for (std::size_t k = 0; k <= rings; ++k) {
      if (k >= 2 && static_cast<double>(k - 1) * width > reach()) return;
      const std::size_t y0 = cy - std::min(k, cy - ay0), y1 = cy + std::min(k, ay1 - cy);
      const std::size_t x0 = cx - std::min(k, cx - ax0), x1 = cx + std::min(k, ax1 - cx);
      for (std::size_t y = y0; y <= y1; ++y) {
        if (y + k == cy || y == cy + k) {  // the ring's top or bottom row: all of it
          for (std::size_t x = x0; x <= x1; ++x) f(y * side_ + x);
          continue;
        }
        if (x0 + k == cx) f(y * side_ + x0);  // its left and right columns, where the box has them
        if (x1 == cx + k) f(y * side_ + x1);
      }
    }
  }
  PooledVector<std::pair<Point, Point>> segments_;
  double x0_ = 0, x1_ = 0, y0_ = 0, y1_ = 0;
  std::size_t side_ = 1;
  PooledVector<std::size_t> start_;
  struct Member {  // a segment listed in a cell, with its box (the cells are read in order)
    double x0, x1, y0, y1;
    std::uint32_t segment;
  };
  PooledVector<Member> members_;
  mutable PooledVector<std::uint32_t> stamps_;  // per segment: the last walk that measured it
  mutable std::uint32_t walk_ = 0;
};

}  // namespace gh::oracle
