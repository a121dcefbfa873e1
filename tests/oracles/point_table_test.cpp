// The sampling oracle's point table: one entry per exact point (0 and -0 alike), values kept
// across growth.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>

#include "common/hash_spread.h"
#include "point_table.h"

namespace gh::oracle {
namespace {

TEST(PointTable, OneEntryPerExactPointAcrossGrowth) {
  PointTable<int> table;
  std::map<std::pair<double, double>, int> reference;  // the same points in an ordered map
  std::mt19937_64 random(7);
  std::uniform_int_distribution<int> coordinate(-40, 40);
  for (int i = 0; i < 20000; ++i) {
    // Neighbouring doubles too: a table that compared rounded keys would merge them.
    double x = coordinate(random) / 4.0, y = coordinate(random) / 4.0;
    if (i % 3 == 0) x = std::nextafter(x, 100.0);
    auto [value, fresh] = table.findOrAdd({x, y});
    const auto key = std::make_pair(x + 0.0, y + 0.0);
    EXPECT_EQ(fresh, reference.count(key) == 0);
    if (fresh) value = i, reference[key] = i;
    EXPECT_EQ(value, reference[key]);
  }
  EXPECT_EQ(table.size(), reference.size());
  for (const auto& [key, value] : reference) {
    auto [found, fresh] = table.findOrAdd({key.first, key.second});
    EXPECT_FALSE(fresh);
    EXPECT_EQ(found, value);
  }
}

TEST(PointTable, MinusZeroIsZero) {
  PointTable<int> table;
  table.findOrAdd({0.0, -0.0}).first = 5;
  auto [value, fresh] = table.findOrAdd({-0.0, 0.0});
  EXPECT_FALSE(fresh);
  EXPECT_EQ(value, 5);
}

// A table's slot array is kept for the thread's next table: the next starts empty, whatever the
// last held and however large it grew, and both hold what they were given. The 10-point table
// leaves the next one a prefix of the 5,000-point table's array, which that one grows within
// (rehashing in place, no new array); the 20,000-point one grows past it.
TEST(PointTable, TheNextTableOnAThreadStartsEmpty) {
  std::vector<Point> points;
  for (int i = 0; i < 5000; ++i) points.push_back({i * 0.5, -i * 0.25});
  {
    PointTable<int> first;
    for (int i = 0; i < 5000; ++i) first.findOrAdd(points[i]).first = i;
  }
  for (const std::size_t n : {std::size_t{10}, std::size_t{5000}, std::size_t{20000}}) {
    PointTable<int> next;
    EXPECT_EQ(next.size(), 0u);
    for (std::size_t i = 0; i < n; ++i) {
      const Point p = i < points.size() ? points[i] : Point{static_cast<double>(i), 7.0};
      auto [value, fresh] = next.findOrAdd(p);
      EXPECT_TRUE(fresh) << n << " " << i;
      EXPECT_EQ(value, 0);
      value = static_cast<int>(i) + 1;
    }
    EXPECT_EQ(next.size(), n);
    for (std::size_t i = 0; i < n; i += 97) {
      const Point p = i < points.size() ? points[i] : Point{static_cast<double>(i), 7.0};
      EXPECT_EQ(next.findOrAdd(p).first, static_cast<int>(i) + 1);
    }
  }
}

// clear() empties the slots in use one by one (those it filled, and where growth moved them),
// not the whole array: after it every point is new again, however the table grew before.
TEST(PointTable, ClearEmptiesEverySlotUsedAcrossGrowth) {
  PointTable<int> table;
  for (int round = 0; round < 3; ++round) {
    const int n = round == 1 ? 300 : 6000;  // grows past its first array, then within it
    for (int i = 0; i < n; ++i) {
      auto [value, fresh] = table.findOrAdd({i * 0.75, round - i * 0.5});
      EXPECT_TRUE(fresh) << round << " " << i;
      EXPECT_EQ(value, 0);
      value = i + 1;
    }
    EXPECT_EQ(table.size(), static_cast<std::size_t>(n));
    table.clear();
    EXPECT_EQ(table.size(), 0u);
    for (int i = 0; i < n; i += 7) EXPECT_TRUE(table.findOrAdd({i * 0.75, round - i * 0.5}).second) << round << " " << i;
    table.clear();
  }
}

// Slots are the hash's low bits, which a multiply-and-shift left alike for grid points: 9 of
// 256 slots held the 9 x 9 integer grid.
TEST(PointTable, HashSpreadsGridPointsOverTheSlots) {
  for (const auto& points : test::gridPointSets()) {
    for (std::uint64_t slots : {256u, 4096u}) {
      EXPECT_GT(test::spreadOverSlots(points, slots, PointTable<int>::hash), 0.9) << points.size() << " points, " << slots << " slots";
    }
  }
}

}  // namespace
}  // namespace gh::oracle
