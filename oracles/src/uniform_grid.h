// Segments listed in the cells of a uniform grid: the sampling oracle's indexes of edges (near
// which a point is too close to judge; how far the nearest lies from a vertex).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "ghclip/region.h"
#include "pooled_vector.h"
#include "uniform_bucket.h"

namespace gh::oracle {

// The cells of a uniform grid (side x side over [x0, x1] x [y0, y1], cells by bucket()) that a
// point within `widen` of the segment ab can fall in, a row at a time: f(row, first, last) for
// the columns first..last, within the rows and columns of the segment's box widened so. In each
// row only the columns between the segment's ends in that row (the row widened too, with a
// margin for the rounding of its bounds and of the ends, far above it), not the box's whole
// width: a long diagonal edge meets a few cells of each row, and its box most of the grid. Where
// that cannot be computed (a horizontal or vertical segment, overflow), the box's columns.
template <class F>
void forCellsNear(Point a, Point b, double widen, double x0, double x1, double y0, double y1, std::size_t side, F&& f) {
  const std::size_t firstRow = bucket(std::min(a.y, b.y) - widen, y0, y1, side), lastRow = bucket(std::max(a.y, b.y) + widen, y0, y1, side);
  const std::size_t firstColumn = bucket(std::min(a.x, b.x) - widen, x0, x1, side), lastColumn = bucket(std::max(a.x, b.x) + widen, x0, x1, side);
  const double dx = b.x - a.x, dy = b.y - a.y, rowHeight = (y1 - y0) / static_cast<double>(side);
  const double rowMargin = 0x1p-30 * (std::abs(y0) + std::abs(y1) + rowHeight);
  const double columnMargin = widen + 0x1p-30 * (std::abs(a.x) + std::abs(b.x) + std::abs(dx));
  const bool along = firstRow != lastRow && firstColumn != lastColumn && dy != 0 && std::isfinite(dx / dy) &&
                     std::isfinite(rowHeight) && std::isfinite(rowMargin) && std::isfinite(columnMargin);
  for (std::size_t row = firstRow; row <= lastRow; ++row) {
    std::size_t first = firstColumn, last = lastColumn;
    if (along) {
      const double ya = std::max(y0 + static_cast<double>(row) * rowHeight - widen - rowMargin, std::min(a.y, b.y));
      const double yb = std::min(y0 + static_cast<double>(row + 1) * rowHeight + widen + rowMargin, std::max(a.y, b.y));
      const double xa = a.x + (ya - a.y) / dy * dx, xb = a.x + (yb - a.y) / dy * dx;
      if (std::isfinite(xa) && std::isfinite(xb) && ya <= yb) {
        first = std::max(first, bucket(std::min(xa, xb) - columnMargin, x0, x1, side));
        last = std::min(last, bucket(std::max(xa, xb) + columnMargin, x0, x1, side));
      }
    }
    f(row, first, last);
  }
}

// n segments listed in the cells of a uniform grid, in compressed rows: the grid's side chosen
// from `initial` down, halving, until the segments are listed at most 32 times each on average;
// then start (each cell's first listing, one past the last cell's at the end) and members
// (member(i) in every cell of segment i). cells(i, side, f) calls f(cell) for each cell of
// segment i on a grid of that side. Returns the side.
template <class Member, class Cells, class MakeMember>
std::size_t listInCells(std::size_t n, std::size_t initial, Cells&& cells, MakeMember&& member,
                        std::vector<std::size_t>& start, std::vector<Member>& members) {
  std::size_t side = std::max<std::size_t>(initial, 1);
  for (;; side /= 2) {
    std::size_t copies = 0;
    for (std::size_t i = 0; i < n; ++i) cells(i, side, [&](std::size_t) { ++copies; });
    if (side == 1 || copies <= 32 * n) break;
  }
  start.assign(side * side + 1, 0);
  for (std::size_t i = 0; i < n; ++i) cells(i, side, [&](std::size_t k) { ++start[k + 1]; });
  for (std::size_t k = 0; k + 1 < start.size(); ++k) start[k + 1] += start[k];
  members.resize(start.back());
  PooledVector<std::size_t> fill(start.begin(), start.end() - 1);
  for (std::size_t i = 0; i < n; ++i) {
    const Member m = member(i);
    cells(i, side, [&](std::size_t k) { members[fill[k]++] = m; });
  }
  return side;
}

// The cells of a grid of `side` over [x0, x1] x [y0, y1] near segment ab (forCellsNear), each as
// f(cell).
template <class F>
void forEachCellNear(Point a, Point b, double widen, double x0, double x1, double y0, double y1, std::size_t side, F&& f) {
  forCellsNear(a, b, widen, x0, x1, y0, y1, side, [&](std::size_t row, std::size_t first, std::size_t last) {
    for (std::size_t column = first; column <= last; ++column) f(row * side + column);
  });
}

}  // namespace gh::oracle
