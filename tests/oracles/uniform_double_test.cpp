#include "uniform_double.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <utility>
#include <vector>

namespace gh::oracle {
namespace {

std::uint64_t bitsOf(double v) {
  std::uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

// An engine of 64-bit draws that replays a list: the draws that round up to 2^64, which
// mt19937_64 gives once in 2^54 draws, are then met on purpose.
struct Replay {
  using result_type = std::uint64_t;
  static constexpr result_type min() { return 0; }
  static constexpr result_type max() { return ~result_type{0}; }
  std::vector<result_type> draws;
  std::size_t next = 0;
  result_type operator()() { return draws[next++ % draws.size()]; }
};

const std::vector<std::pair<double, double>> kIntervals = {
    {0, 1}, {-1, 1}, {5, 5}, {-3.5, 1e-300}, {1e-310, 3e-308}, {-1e300, 1e300},  // the last: hi - lo overflows
    {0.1, 0.30000000000000004}, {-7e15, 9e15}, {std::numeric_limits<double>::lowest(), std::numeric_limits<double>::max()}};

TEST(UniformDouble, SameBitsAsTheStandardDistributionOnMersenneTwister) {
  for (const auto& [lo, hi] : kIntervals) {
    std::mt19937_64 ours(42), theirs(42);
    std::uniform_real_distribution<double> standard(lo, hi);
    for (int i = 0; i < 20000; ++i) {
      const double a = uniformIn(ours, lo, hi), b = standard(theirs);
      ASSERT_EQ(bitsOf(a), bitsOf(b)) << "draw " << i << " over [" << lo << ", " << hi << ")";
    }
  }
}

TEST(UniformDouble, DrawsThatRoundUpToOneStayBelowHiAsTheStandardOnes) {
  // 2^64 - 1 and its neighbours round to 2^64 as doubles: u would be 1 without the clamp.
  Replay ours{{~std::uint64_t{0}, ~std::uint64_t{0} - 1000, ~std::uint64_t{0} - 4000, 0, 1, std::uint64_t{1} << 63}};
  Replay theirs = ours;
  for (const auto& [lo, hi] : kIntervals) {
    std::uniform_real_distribution<double> standard(lo, hi);
    for (std::size_t i = 0; i < ours.draws.size(); ++i) {
      const double a = uniformIn(ours, lo, hi), b = standard(theirs);
      ASSERT_EQ(bitsOf(a), bitsOf(b)) << "draw " << i << " over [" << lo << ", " << hi << ")";
      if (lo == 0 && hi == 1) EXPECT_LT(a, 1.0);
    }
  }
}

}  // namespace
}  // namespace gh::oracle
