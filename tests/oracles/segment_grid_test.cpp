// The sampling oracle's clearances (oracles/src/segment_grid.h): the walk over the grid's cells
// finds the nearest segment a brute-force scan finds, reaches each segment once a walk (a long
// segment is listed in many cells), and reports the segments through the vertex exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <vector>

#include "segment_grid.h"

namespace gh::oracle {
namespace {

// Long segments between points of the grid 0..8 (many through one point, overlapping, crossing),
// and short ones.
PooledVector<std::pair<Point, Point>> segments(std::mt19937_64& random, int count) {
  std::uniform_int_distribution<int> coordinate(0, 8);
  std::uniform_real_distribution<double> nudge(-0.3, 0.3);
  PooledVector<std::pair<Point, Point>> out;
  for (int i = 0; i < count; ++i) {
    const Point a{double(coordinate(random)), double(coordinate(random))};
    Point b{double(coordinate(random)), double(coordinate(random))};
    if (i % 4 == 0) b = {a.x + nudge(random), a.y + nudge(random)};
    out.push_back({a, b});
  }
  return out;
}

// What the clearance is, by a scan of every segment: a segment ending at q counts its length (its
// far end), one passing through q (exactly) the distance to its nearer end, any other its
// distance from q.
double clearanceByScan(const PooledVector<std::pair<Point, Point>>& all, Point q, double cap) {
  double least = cap;
  for (const auto& [a, b] : all) {
    const double dx = b.x - a.x, dy = b.y - a.y;
    double d;
    if (q == a || q == b) {
      d = std::hypot(dx, dy);
    } else {
      const double squared = dx * dx + dy * dy;
      const double t = squared > 0 ? std::clamp(((q.x - a.x) * dx + (q.y - a.y) * dy) / squared, 0.0, 1.0) : 0.0;
      d = std::hypot(q.x - a.x - t * dx, q.y - a.y - t * dy);
      if (t > 0 && t < 1 && filteredOrientation(a, b, q) == 0) d = std::min(std::hypot(q.x - a.x, q.y - a.y), std::hypot(q.x - b.x, q.y - b.y));
    }
    least = std::min(least, d);
  }
  return least;
}

TEST(SegmentGrid, ClearanceIsTheNearestSegmentsAndEachIsReachedOnce) {
  std::mt19937_64 random(20261202);
  std::uniform_real_distribution<double> anywhere(-1, 9);
  std::uniform_int_distribution<int> coordinate(0, 8);
  for (int round = 0; round < 30; ++round) {
    const auto all = segments(random, 20 + 10 * round);
    const SegmentGrid grid(all);
    for (int i = 0; i < 300; ++i) {
      // Points anywhere, grid points (segments' ends and crossings), and midpoints of segments.
      Point q{anywhere(random), anywhere(random)};
      if (i % 3 == 1) q = {double(coordinate(random)), double(coordinate(random))};
      if (i % 3 == 2) {
        const auto& [a, b] = all[static_cast<std::size_t>(i) % all.size()];
        q = {(a.x + b.x) / 2, (a.y + b.y) / 2};
      }
      const double cap = i % 2 ? 100.0 : 0.5;
      std::map<std::uint32_t, int> reached;
      std::vector<std::uint32_t> atQ;
      const double walked = grid.clearance(
          q, cap, [](std::size_t, double) { return false; }, &atQ, nullptr, nullptr,
          [&](std::uint32_t s, double, bool) { ++reached[s]; });
      const double scanned = clearanceByScan(all, q, cap);
      ASSERT_NEAR(walked, scanned, 1e-12 * (1 + scanned)) << "round " << round << " at (" << q.x << ", " << q.y << ")";
      for (const auto& [s, times] : reached) ASSERT_EQ(times, 1) << "segment " << s << " reached twice in one walk";
      // The segments at q, exactly: those ending at q or passing through it, each once.
      std::vector<std::uint32_t> expected;
      for (std::uint32_t s = 0; s < all.size(); ++s) {
        const auto& [a, b] = all[s];
        const bool on = q == a || q == b ||
                        (filteredOrientation(a, b, q) == 0 && q.x >= std::min(a.x, b.x) && q.x <= std::max(a.x, b.x) &&
                         q.y >= std::min(a.y, b.y) && q.y <= std::max(a.y, b.y) && a != b);
        if (on) expected.push_back(s);
      }
      if (walked > 0) {
        ASSERT_EQ(atQ, expected) << "round " << round << " at (" << q.x << ", " << q.y << ")";
      }
    }
  }
}

TEST(SegmentGrid, NearestHoldsEachSegmentOnceWhenOneCountsAsThrough) {
  // A segment counted as passing through q (passesNear), listed in many cells: met again after
  // the clearance has dropped below its distance, it must not also take a slot of the nearest.
  std::mt19937_64 random(5);
  bool countedSomewhere = false;
  for (int round = 0; round < 30; ++round) {
    auto all = segments(random, 40);
    all.push_back({{0, 0.001}, {8, 8.001}});  // long, passing 0.0007 from the diagonal's points
    const auto through = static_cast<std::uint32_t>(all.size() - 1);
    const SegmentGrid grid(all);
    for (int k = 1; k < 8; ++k) {
      const Point q{double(k), double(k)};
      SegmentGrid::Nearest nearest;
      bool counted = false;  // whether the walk took it as passing through q
      grid.clearance(
          q, 100.0, [&](std::size_t s, double d) { return s == through && d < 0.01; }, nullptr, nullptr, &nearest,
          [&](std::uint32_t s, double, bool passes) { counted |= s == through && passes; });
      std::map<std::uint32_t, int> times;
      for (const std::uint32_t s : nearest.segments) ++times[s];
      for (const auto& [s, n] : times) ASSERT_EQ(n, 1) << "segment " << s << " twice among the nearest";
      if (counted) EXPECT_EQ(times.count(through), 1u);
      countedSomewhere |= counted;
    }
  }
  EXPECT_TRUE(countedSomewhere);  // the case this test is about was met
}

}  // namespace
}  // namespace gh::oracle
