// Which of n equal buckets over a range holds a value: the one division every grid and band of
// the sampling oracle places things with.
#pragma once

#include <cstddef>

namespace gh::oracle {

// Which of n equal buckets over [lo, hi] holds v, clamped to the ends: a monotone function of
// v, so that everything stored under the buckets of [a, b] is found from any v in [a, b]. A
// zero-width range puts v = lo (NaN) in bucket 0, and v beyond it (infinite) in the last.
inline std::size_t bucket(double v, double lo, double hi, std::size_t n) {
  const double f = (v - lo) / (hi - lo) * static_cast<double>(n);
  if (!(f > 0)) return 0;
  if (!(f < static_cast<double>(n))) return n - 1;  // before the conversion: inf does not fit
  return static_cast<std::size_t>(f);
}

}  // namespace gh::oracle
