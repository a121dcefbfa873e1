// Doubles drawn uniformly over an interval, as the sampling judge draws its points.
#pragma once

#include <cmath>
#include <cstdint>

namespace gh::oracle {

// A double uniform over [lo, hi) from one 64-bit draw: the same bits as libstdc++'s
// uniform_real_distribution<double>(lo, hi) on mt19937_64 (generate_canonical: the draw rounded
// to a double, over 2^64, kept below 1; then times hi - lo, plus lo), so the judge samples the
// points it sampled with that distribution, without the two long double logarithms
// generate_canonical takes on every call (glibc's logl alone was 1.5 % of fuzz_clip_naive's
// samples in fork mode: its answers reaching beyond S and C's box get 200 uniform points more each).
template <class Engine>  // mt19937_64, or any engine of 64-bit draws over the full range
double uniformIn(Engine& rng, double lo, double hi) {
  static_assert(Engine::min() == 0 && Engine::max() == ~std::uint64_t{0}, "one draw must be 64 random bits");
  double u = static_cast<double>(rng()) * 0x1p-64;
  if (u >= 1) u = std::nextafter(1.0, 0.0);
  return u * (hi - lo) + lo;
}

}  // namespace gh::oracle
