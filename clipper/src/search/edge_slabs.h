// An operand's edges in horizontal slabs, for locating many points in it at once: a ray from a
// point towards +x can only cross edges whose y-range holds the point's y, and those are all
// listed in the point's slab. Phase 2 locates every ring's first vertex this way: O(R * E / S + E)
// for R rings against E edges in S slabs, instead of R * E (archipelagos have thousands of rings).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "operand.h"

namespace gh::detail {

class EdgeSlabs {
 public:
  explicit EdgeSlabs(const Operand& op) {
    double y0 = INFINITY, y1 = -INFINITY;
    for (const Point& p : op.vertices) y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    y0_ = y0;
    // About 4 edges per slab, coarser while edges would be listed more than 8 times over.
    std::size_t slabs = std::max<std::size_t>(1, std::min<std::size_t>(op.size() / 4, std::size_t{1} << 20));
    for (;; slabs /= 2) {
      height_ = (y1 - y0) / static_cast<double>(slabs);
      if (!(height_ > 0) || !std::isfinite(height_)) slabs = 1, height_ = INFINITY;
      count_ = static_cast<std::uint32_t>(slabs);
      std::size_t listed = 0;
      for (std::uint32_t e = 0; e < op.size() && listed <= 8 * op.size(); ++e) {
        const auto [lo, hi] = range(op, e);
        listed += hi - lo + 1;
      }
      if (slabs == 1 || listed <= 8 * op.size()) break;
    }
    start_.assign(std::size_t{count_} + 1, 0);
    for (std::uint32_t e = 0; e < op.size(); ++e) {
      const auto [lo, hi] = range(op, e);
      for (std::uint32_t s = lo; s <= hi; ++s) ++start_[s + 1];
    }
    for (std::uint32_t s = 0; s < count_; ++s) start_[s + 1] += start_[s];
    edges_.resize(start_.back());
    std::vector<std::uint32_t> at(start_.begin(), start_.end() - 1);
    for (std::uint32_t e = 0; e < op.size(); ++e) {
      const auto [lo, hi] = range(op, e);
      for (std::uint32_t s = lo; s <= hi; ++s) edges_[at[s]++] = e;
    }
  }

  // The edges listed in the slab of height y: among them, every edge whose y-range holds y.
  std::pair<const std::uint32_t*, const std::uint32_t*> near(double y) const {
    const std::uint32_t s = slab(y);
    return {edges_.data() + start_[s], edges_.data() + start_[s + 1]};
  }

 private:
  // Monotone in y, so an edge's slabs [slab(ymin), slab(ymax)] hold the slab of every y between.
  std::uint32_t slab(double y) const {
    const double t = (y - y0_) / height_;
    if (!(t > 0)) return 0;  // also NaN: 0 / infinity
    return static_cast<std::uint32_t>(std::min(std::floor(t), static_cast<double>(count_ - 1)));
  }
  std::pair<std::uint32_t, std::uint32_t> range(const Operand& op, std::uint32_t e) const {
    const double a = op.from(e).y, b = op.to(e).y;
    return {slab(std::min(a, b)), slab(std::max(a, b))};
  }

  double y0_ = 0, height_ = INFINITY;
  std::uint32_t count_ = 1;
  std::vector<std::uint32_t> start_, edges_;
};

}  // namespace gh::detail
