// Boxes in a uniform grid: which of them lie near a box asked about. Each box is listed in every
// cell it meets; the cell size follows the boxes' count, coarsened while boxes would be listed too
// often. The OGC layout's repairs ask it for the pieces near a node they move, and its snap
// rounding for the nodes near a piece (layout/).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "search/box_overlaps.h"

namespace gh::detail {

class BoxGrid {
 public:
  explicit BoxGrid(const std::vector<Box>& boxes) : seen_(boxes.size(), 0) {
    x0_ = y0_ = INFINITY;
    double x1 = -INFINITY, y1 = -INFINITY;
    for (const Box& b : boxes) x0_ = std::min(x0_, b.minX), y0_ = std::min(y0_, b.minY), x1 = std::max(x1, b.maxX), y1 = std::max(y1, b.maxY);
    const double n = static_cast<double>(std::max<std::size_t>(boxes.size(), 1));
    for (int side = static_cast<int>(std::min(1024.0, std::ceil(std::sqrt(n)))); side >= 1; side /= 2) {
      side_ = static_cast<std::uint32_t>(side);
      w_ = (x1 - x0_) / side, h_ = (y1 - y0_) / side;
      if (!(w_ > 0) || !(h_ > 0) || !std::isfinite(w_) || !std::isfinite(h_)) {
        side_ = 1, w_ = h_ = INFINITY;
        break;
      }
      std::size_t listed = 0;
      for (const Box& b : boxes) listed += std::size_t{cell(b.maxX, x0_, w_) - cell(b.minX, x0_, w_) + 1} * (cell(b.maxY, y0_, h_) - cell(b.minY, y0_, h_) + 1);
      if (listed <= 8 * boxes.size() + 64) break;
    }
    cells_.assign(std::size_t{side_} * side_, {});
    for (std::uint32_t i = 0; i < boxes.size(); ++i) {
      forCells(boxes[i], [&](std::size_t c) { cells_[c].push_back(i); });
    }
  }
  // Calls visit(i) once for every listed box i whose cells meet those of `query`.
  template <class Visit>
  void near(const Box& query, Visit&& visit) {
    ++stamp_;
    forCells(query, [&](std::size_t c) {
      for (const std::uint32_t i : cells_[c]) {
        if (seen_[i] == stamp_) continue;
        seen_[i] = stamp_;
        visit(i);
      }
    });
  }

 private:
  std::uint32_t cell(double v, double origin, double size) const {
    const double t = (v - origin) / size;
    if (!(t > 0)) return 0;
    return t < static_cast<double>(side_ - 1) ? static_cast<std::uint32_t>(t) : side_ - 1;
  }
  template <class F>
  void forCells(const Box& b, F&& f) const {
    for (std::uint32_t cy = cell(b.minY, y0_, h_), y1 = cell(b.maxY, y0_, h_); cy <= y1; ++cy) {
      for (std::uint32_t cx = cell(b.minX, x0_, w_), x1 = cell(b.maxX, x0_, w_); cx <= x1; ++cx) f(std::size_t{cy} * side_ + cx);
    }
  }
  std::vector<std::vector<std::uint32_t>> cells_;
  std::vector<std::uint32_t> seen_;
  std::uint32_t stamp_ = 0, side_ = 1;
  double x0_ = 0, y0_ = 0, w_ = 1, h_ = 1;
};

}  // namespace gh::detail
