// Which candidate search the exact arithmetic uses when the caller leaves it to the library
// (Search::Auto).
//
// The sweep only pays when it can skip pairs: with edges of x-widths w_i (subject) and v_j (clip)
// in a common x-range of width W, a pair's x-intervals overlap with probability about
// (w_i + v_j) / W, so the share of pairs the sweep must still report is about
// (mean w + mean v) / W. On the paper's random workload (edges spanning a third of the square on
// average) that is ~0.67 and the sweep's bookkeeping makes it slower than testing all pairs; on
// realistic outlines (circles, coastlines) it is ~0 and the sweep is orders of magnitude faster.
// Small inputs are not worth the sweep's set-up either.
#pragma once

#include <algorithm>
#include <cmath>

#include "operand.h"

namespace gh::detail {

inline constexpr double kSweepOverlapShare = 0.25;  // calibrated by experiments/sweep_benchmark
inline constexpr std::size_t kSweepMinPairs = 256;

inline bool sweepPays(const Operand& subject, const Operand& clip) {
  if (subject.size() * clip.size() < kSweepMinPairs) return false;
  double lo = INFINITY, hi = -INFINITY, widthS = 0, widthC = 0;
  for (const Operand* op : {&subject, &clip}) {
    double& width = op == &subject ? widthS : widthC;
    for (std::uint32_t e = 0; e < op->size(); ++e) {
      const double a = op->from(e).x, b = op->to(e).x;
      lo = std::min(lo, a), hi = std::max(hi, a);
      width += std::abs(b - a);
    }
  }
  const double span = hi - lo;
  if (!(span > 0)) return false;  // everything on one vertical line: every pair overlaps
  const double share = (widthS / static_cast<double>(subject.size()) + widthC / static_cast<double>(clip.size())) / span;
  return share < kSweepOverlapShare;
}

}  // namespace gh::detail
