// Which of several regions a point lies in (even-odd), and on whose boundaries: one horizontal
// ray per point for up to 64 regions at once, decided exactly. The sampling oracle's side tests.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "filtered_orientation.h"
#include "ghclip/region.h"
#include "ghoracle/mix_bits.h"
#include "point_hash.h"
#include "pooled_vector.h"
#include "uniform_bucket.h"

namespace gh::oracle {

// Several regions' edges in horizontal bands, so that a ray test visits only the edges whose
// y-range can hold the point's y (every other edge lies wholly above or below it and cannot
// count). The band of a y is a monotone function of y, so an edge with ymin <= y <= ymax is always
// found. A point right of its band's middle casts its ray to the right, one left of it to the
// left, so that a test reads about half the band: under the half-open rule every ring crosses the
// point's horizontal line an even number of times, so off the boundary both rays have the same
// parity. Up to 64 regions are tested by one ray, each distinct segment once with a mask of the
// regions it bounds: the five answers of a fuzz target share most of their edges (each piece of
// S's and C's boundaries bounds about three of them), and S and C are tested together.
//
// An edge that runs through a band from below it to above it (a through edge: the long edges of
// fuzzed rings run through most bands) crosses every point's line there exactly once, within the
// x-range its line has over the band's heights (widened by far more than the rounding of its
// computation). A band keeps those apart, ordered by that range's left end, with the parity of
// every suffix: the through edges whose range starts right of the point all cross its ray, one
// binary search; of the others only those whose range reaches the point (a backward walk, cut off
// by the ranges' running maximum) need an orientation, and the rest lie behind it. A ray to the
// left gets the through edges' parity from the right one's: each crosses the line once, so the two
// differ by the parity of all of them, wherever the point is not on one (its own boundary bits,
// whose sides are not asked). A test then reads the band's other edges, those that end inside it.
class EvenOddRegions {
 public:
  static constexpr std::size_t kMost = 64;
  struct Sides {
    std::uint64_t inside = 0;    // bit i: the point is inside region i (where it is not on it)
    std::uint64_t boundary = 0;  // bit i: the point lies on an edge of region i
    // Region i's side: nullopt on its boundary (inside and outside are a convention there).
    std::optional<bool> of(std::size_t i) const {
      if (boundary >> i & 1) return std::nullopt;
      return (inside >> i & 1) != 0;
    }
  };

  EvenOddRegions() = default;
  explicit EvenOddRegions(const std::vector<const Region*>& regions, bool throughBands = true) {
    // Every edge (either way round, zero-length ones too), with the bit of its region; equal
    // segments merged: `toggle` the regions that hold it an odd number of times (crossing it
    // changes their parity), `present` every region that holds it. Merged in a table open-addressed
    // by a hash of the coordinates (equal segments, equal hashes: -0 hashed as 0; a segment with a
    // NaN equals none), in the order met: the order is no concern, as the bands are put in their
    // own below, and a ray's parities and boundaries do not depend on the order it reads its
    // edges in. (Sorting the edges on the hash to bring equal ones together cost more than the
    // table: a sort of 48-byte records for the five answers' hundreds of edges.)
    PooledVector<Edge> edges;
    std::size_t count = 0;
    for (std::size_t r = 0; r < regions.size() && r < kMost; ++r) {
      for (const Ring& ring : *regions[r]) count += ring.size();
    }
    if (count == 0) return;
    std::size_t capacity = 16;
    while (capacity < 2 * count) capacity *= 2;
    constexpr std::uint32_t kFree = 0xffffffffu;
    PooledVector<std::uint32_t> slots(capacity, kFree);
    for (std::size_t r = 0; r < regions.size() && r < kMost; ++r) {
      const std::uint64_t bit = std::uint64_t{1} << r;
      for (const Ring& ring : *regions[r]) {
        for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
          Point a = ring[i], b = ring[(i + 1) % n];
          if (b.x < a.x || (b.x == a.x && b.y < a.y)) std::swap(a, b);
          const std::uint64_t hash = mixBits(mixedPointHash(a) + mixedPointHash(b) * 0x9E3779B97F4A7C15ull);
          for (std::size_t k = hash & (capacity - 1);; k = (k + 1) & (capacity - 1)) {
            if (slots[k] == kFree) {
              slots[k] = static_cast<std::uint32_t>(edges.size());
              Edge e = edgeOf(a, b);
              e.toggle = e.present = bit;
              edges.push_back(e);
              break;
            }
            Edge& e = edges[slots[k]];
            if (e.a == a && e.b == b) {
              e.toggle ^= bit, e.present |= bit;
              break;
            }
          }
        }
      }
    }
    minY_ = maxY_ = edges[0].a.y;
    for (const Edge& e : edges) {
      minY_ = std::min({minY_, e.a.y, e.b.y}), maxY_ = std::max({maxY_, e.a.y, e.b.y});
    }
    // Bands: about one per 4 edges (one per 2 with through edges, which a ray reads by a binary
    // search), fewer while long edges would be copied into too many (16 copies an edge on average,
    // 24 with through edges). Each edge's first and last band, as the count that settles the number
    // found them, are kept for the passes below (a band is a division).
    PooledVector<std::pair<std::size_t, std::size_t>> spans(edges.size());
    const std::size_t perBand = throughBands ? 2 : 4, mostCopies = throughBands ? 24 : 16;
    for (bands_ = std::clamp<std::size_t>(edges.size() / perBand, 1, 4096);; bands_ /= 2) {
      std::size_t copies = 0;
      for (std::size_t i = 0; i < edges.size(); ++i) {
        const Edge& e = edges[i];
        spans[i] = {band(std::min(e.a.y, e.b.y)), band(std::max(e.a.y, e.b.y))};
        copies += spans[i].second - spans[i].first + 1;
      }
      if (copies <= mostCopies * edges.size() || bands_ == 1) break;
    }
    double minX = edges[0].minX, maxX = edges[0].maxX;
    for (const Edge& e : edges) minX = std::min(minX, e.minX), maxX = std::max(maxX, e.maxX);
    const double narrow = 8 * (maxX / 2 - minX / 2) * 2 / static_cast<double>(bands_);
    // Each band's heights, widened by far more than the rounding of band() and of these bounds
    // (relative errors of a few ulps, and absolute ones of a few subnormal ulps, hence the
    // floor): every y that band() puts in band k lies in [low(k), high(k)]. Where they cannot be
    // computed (a range that overflows, or none), no edge runs through a band.
    const double height = (maxY_ - minY_) / static_cast<double>(bands_);
    const double margin = 0x1p-30 * (std::abs(minY_) + std::abs(maxY_) + height) + 0x1p-1000;
    const bool banded = throughBands && height > 0 && std::isfinite(height) && std::isfinite(margin);
    auto low = [&](std::size_t k) { return minY_ + static_cast<double>(k) * height - margin; };
    auto high = [&](std::size_t k) { return minY_ + static_cast<double>(k + 1) * height + margin; };
    // Whether edge e runs through band k, and the x-range its line has over the band's heights
    // (widened likewise: its crossing with any line there lies inside). Only a narrow range (at
    // most 8 bands' worth of the edges' x-extent) counts: a wide one would keep the running maximum
    // of the ranges high and a ray's backward walk long; such an edge is read with the others.
    auto through = [&](const Edge& e, std::size_t k, double& x0, double& x1) {
      if (!banded) return false;
      const double y0 = low(k), y1 = high(k);
      if (!(std::min(e.a.y, e.b.y) < y0 && std::max(e.a.y, e.b.y) > y1)) return false;
      const double dx = e.b.x - e.a.x, dy = e.b.y - e.a.y;
      const double xa = e.a.x + (y0 - e.a.y) / dy * dx, xb = e.a.x + (y1 - e.a.y) / dy * dx;
      const double widen = 0x1p-30 * (std::abs(e.a.x) + std::abs(e.b.x) + std::abs(dx)) + 0x1p-1000;
      x0 = std::min(xa, xb) - widen, x1 = std::max(xa, xb) + widen;
      return std::isfinite(x0) && std::isfinite(x1) && x1 - x0 <= narrow;
    };
    // Each band's other edges, and its through edges, each copy's range found once for the
    // passes below (NaN where it does not run through): edge i's copy in band k is
    // range[copyStart[i] + k - spans[i].first].
    PooledVector<std::size_t> copyStart(edges.size() + 1, 0);
    for (std::size_t i = 0; i < edges.size(); ++i) copyStart[i + 1] = copyStart[i] + spans[i].second - spans[i].first + 1;
    PooledVector<std::pair<double, double>> range(copyStart.back(), {std::numeric_limits<double>::quiet_NaN(), 0.0});
    start_.assign(bands_ + 1, 0);
    throughStart_.assign(bands_ + 1, 0);
    for (std::size_t i = 0; i < edges.size(); ++i) {
      for (std::size_t k = spans[i].first; k <= spans[i].second; ++k) {
        double x0, x1;
        const bool runs = through(edges[i], k, x0, x1);
        if (runs) range[copyStart[i] + k - spans[i].first] = {x0, x1};
        ++(runs ? throughStart_ : start_)[k + 1];
      }
    }
    auto rangeOf = [&](std::size_t i, std::size_t k) { return range[copyStart[i] + k - spans[i].first]; };
    for (std::size_t k = 0; k < bands_; ++k) start_[k + 1] += start_[k], throughStart_[k + 1] += throughStart_[k];
    // The through edges, with their ranges in the band, ordered by the range's left end (a sort
    // of (left end, place) pairs per band, not of the 64-byte copies).
    throughs_.resize(throughStart_[bands_]);
    {
      PooledVector<std::pair<double, std::uint32_t>> keys(throughs_.size());
      PooledVector<Edge> unsorted(throughs_.size());
      PooledVector<std::size_t> fill(throughStart_.begin(), throughStart_.end() - 1);
      for (std::size_t i = 0; i < edges.size(); ++i) {
        for (std::size_t k = spans[i].first; k <= spans[i].second; ++k) {
          const auto [x0, x1] = rangeOf(i, k);
          if (std::isnan(x0)) continue;
          Edge e = edges[i];
          e.minX = x0, e.maxX = x1;
          keys[fill[k]] = {x0, static_cast<std::uint32_t>(fill[k])};
          unsorted[fill[k]++] = e;
        }
      }
      suffixToggle_.resize(throughs_.size() + bands_);
      reach_.resize(throughs_.size());
      for (std::size_t k = 0; k < bands_; ++k) {
        const std::size_t first = throughStart_[k], last = throughStart_[k + 1];
        std::sort(keys.begin() + static_cast<std::ptrdiff_t>(first), keys.begin() + static_cast<std::ptrdiff_t>(last));
        for (std::size_t j = first; j < last; ++j) throughs_[j] = unsorted[keys[j].second];
        // suffixToggle_[first + k + j]: the parity of the band's through edges from j on (one
        // more entry per band than it has edges: the empty suffix).
        std::uint64_t parity = 0;
        suffixToggle_[last + k] = 0;
        for (std::size_t j = last; j-- > first;) suffixToggle_[j + k] = parity ^= throughs_[j].toggle;
        double reach = -std::numeric_limits<double>::infinity();
        for (std::size_t j = first; j < last; ++j) reach_[j] = reach = std::max(reach, throughs_[j].maxX);
      }
    }
    // Each band holds copies of its other edges (a ray test reads them in order, not scattered),
    // twice: from the rightmost right end leftwards (a ray to the right stops at the first edge
    // wholly left of its point, as every edge after it is) and from the leftmost left end
    // rightwards. The edges are put in each order once, by their indices, and dealt out to the
    // bands in it: sorting every band's copies (of 64-byte edges) was a third of the
    // constructor's time.
    PooledVector<std::uint32_t> order(edges.size());
    for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
    auto deal = [&](PooledVector<Edge>& into) {
      into.resize(start_[bands_]);
      PooledVector<std::size_t> fill(start_.begin(), start_.end() - 1);
      for (const std::uint32_t i : order) {
        for (std::size_t k = spans[i].first; k <= spans[i].second; ++k) {
          if (std::isnan(rangeOf(i, k).first)) into[fill[k]++] = edges[i];
        }
      }
    };
    std::sort(order.begin(), order.end(), [&](std::uint32_t e, std::uint32_t f) { return edges[e].maxX > edges[f].maxX; });
    deal(rightward_);
    std::sort(order.begin(), order.end(), [&](std::uint32_t e, std::uint32_t f) { return edges[e].minX < edges[f].minX; });
    deal(leftward_);
    middle_.assign(bands_, 0);
    for (std::size_t k = 0; k < bands_; ++k) {
      // The middle of the band's x-range (in halves: no overflow near 2^1023).
      if (start_[k + 1] > start_[k]) middle_[k] = leftward_[start_[k]].minX / 2 + rightward_[start_[k]].maxX / 2;
    }
  }

  // How many copies of edges the bands keep as through edges (for the tests: whether the path
  // that reads them is taken).
  std::size_t throughCopies() const { return throughs_.size(); }

  // Even-odd parity of a ray from p for every region at once, exactly, and the regions on whose
  // edges p lies.
  Sides inside(Point p) const {
    if (!(p.y >= minY_ && p.y <= maxY_) || start_.empty()) return {};
    const std::size_t k = band(p.y);
    const bool right = start_[k + 1] == start_[k] || p.x >= middle_[k];
    Sides sides = right ? parity<true>(p, rightward_.data() + start_[k], rightward_.data() + start_[k + 1])
                        : parity<false>(p, leftward_.data() + start_[k], leftward_.data() + start_[k + 1]);
    const std::size_t first = throughStart_[k], last = throughStart_[k + 1];
    if (first == last) return sides;
    // The through edges whose range starts right of p cross its ray to the right; of the others,
    // those whose range reaches p are decided by orientation.
    const auto* begin = throughs_.data() + first;
    const std::size_t after = static_cast<std::size_t>(
        std::upper_bound(begin, throughs_.data() + last, p.x, [](double x, const Edge& e) { return x < e.minX; }) - begin);
    std::uint64_t crossing = suffixToggle_[first + after + k];
    for (std::size_t j = first + after; j-- > first && reach_[j] >= p.x;) {
      const Edge& e = throughs_[j];
      if (e.maxX < p.x) continue;  // its crossing lies left of p
      const int o = filteredOrientation(e.a, e.b, p);
      if (o == 0) {  // on its line, strictly inside its y-range: on the edge
        sides.boundary |= e.present;
        continue;
      }
      if (e.b.y > e.a.y ? o > 0 : o < 0) crossing ^= e.toggle;  // as in parity<true>
    }
    // To the left: every through edge crosses the line once, so the left ray's parity differs from
    // the right one's by all of theirs (where p is on none of a region's edges: elsewhere its bit is
    // not read).
    if (!right) crossing ^= suffixToggle_[first + k];
    sides.inside ^= crossing;
    return sides;
  }

 private:
  struct Edge {
    Point a, b;
    double minX, maxX;  // its x-range; for a through edge, its line's over the band's heights
    std::uint64_t toggle = 0, present = 0;
  };
  static Edge edgeOf(Point a, Point b) { return {a, b, std::min(a.x, b.x), std::max(a.x, b.x)}; }

  // The parities of the edges in [first, last) that cross p's horizontal line on the ray's side
  // of p, and the edges p lies on.
  template <bool kToTheRight>
  static Sides parity(Point p, const Edge* first, const Edge* last) {
    Sides sides;
    for (const Edge* e = first; e != last; ++e) {
      if (kToTheRight ? p.x > e->maxX : p.x < e->minX) break;  // this edge and all after it lie behind p
      const Point& a = e->a;
      const Point& b = e->b;
      if (p.y < std::min(a.y, b.y) || p.y > std::max(a.y, b.y)) continue;
      const bool crosses = (a.y > p.y) != (b.y > p.y);
      const bool within = p.x >= e->minX && p.x <= e->maxX;
      if (!crosses && !within) continue;
      if (crosses && !within) {  // wholly on the ray's side of p: no orientation needed
        sides.inside ^= e->toggle;
        continue;
      }
      const int o = filteredOrientation(a, b, p);
      if (o == 0) {  // within its x-range and on its line: on the edge
        sides.boundary |= e->present;
        continue;
      }
      // The edge crosses p's horizontal line to the right of p when p is on its left going
      // upward (on its right going downward); to the left of p in the other two cases.
      if (crosses && ((b.y > a.y ? o > 0 : o < 0) == kToTheRight)) sides.inside ^= e->toggle;
    }
    return sides;
  }

  std::size_t band(double y) const { return bucket(y, minY_, maxY_, bands_); }
  double minY_ = 0, maxY_ = 0;
  std::size_t bands_ = 1;
  PooledVector<std::size_t> start_;          // per band, its other edges' first place
  PooledVector<Edge> rightward_, leftward_;  // each band's other edges, by right end down, by left end up
  PooledVector<double> middle_;              // per band: rays from points left of it go left
  PooledVector<std::size_t> throughStart_;   // per band, its through edges' first place
  PooledVector<Edge> throughs_;              // each band's through edges, by their range's left end
  PooledVector<std::uint64_t> suffixToggle_;  // per band, the parity of each suffix of them (and the empty one)
  PooledVector<double> reach_;               // the largest right end of each prefix of them
};

}  // namespace gh::oracle
