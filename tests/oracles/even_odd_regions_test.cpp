// The sampling oracle's side tests (oracles/src/even_odd_regions.h) against the definition: a
// point's side of each region by a half-open ray over every edge, decided exactly, and whether it
// lies on one. On small grids (vertices on the ray's line, horizontal edges, points on edges,
// edges shared by several regions), with long edges that run through many bands (the bands'
// through edges), and at magnitudes from subnormal to near overflow.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "even_odd_regions.h"
#include "filtered_orientation.h"

namespace gh::oracle {
namespace {

// The definition, one region at a time.
std::optional<bool> sideByDefinition(const Region& region, Point p) {
  bool inside = false;
  for (const Ring& ring : region) {
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
      const Point a = ring[i], b = ring[(i + 1) % n];
      const int o = filteredOrientation(a, b, p);
      if (o == 0 && p.x >= std::min(a.x, b.x) && p.x <= std::max(a.x, b.x) && p.y >= std::min(a.y, b.y) &&
          p.y <= std::max(a.y, b.y)) {
        return std::nullopt;
      }
      if ((a.y > p.y) != (b.y > p.y)) {
        // Crosses p's line; to the right of p when p is left of it going up, right of it going down.
        if (b.y > a.y ? o > 0 : o < 0) inside = !inside;
      }
    }
  }
  return inside;
}

// Every region's side of every point, as the bands give it and by the definition.
void expectSidesAsDefined(const std::vector<Region>& regions, const std::vector<Point>& points, bool throughBands) {
  std::vector<const Region*> pointers;
  for (const Region& r : regions) pointers.push_back(&r);
  const EvenOddRegions bands(pointers, throughBands);
  for (const Point& p : points) {
    const EvenOddRegions::Sides sides = bands.inside(p);
    for (std::size_t r = 0; r < regions.size(); ++r) {
      ASSERT_EQ(sides.of(r), sideByDefinition(regions[r], p)) << "region " << r << " at (" << p.x << ", " << p.y << ")";
    }
  }
}

// Rings of up to 40 vertices on the grid 0..8 (scaled), most of their edges long.
std::vector<Region> gridRegions(std::mt19937_64& random, int count, double scale) {
  std::uniform_int_distribution<int> coordinate(0, 8), vertices(3, 40), rings(1, 3);
  std::vector<Region> regions(static_cast<std::size_t>(count));
  for (Region& region : regions) {
    for (int k = rings(random); k > 0; --k) {
      Ring ring;
      for (int v = vertices(random); v > 0; --v) ring.push_back({coordinate(random) * scale, coordinate(random) * scale});
      region.push_back(ring);
    }
  }
  // An edge shared by two regions, and one ring in two regions (edges that toggle several bits).
  if (count >= 2) regions[1].push_back(regions[0][0]);
  return regions;
}

// The grid's points and the halves and quarters between them, and the vertices moved by an ulp.
std::vector<Point> gridPoints(const std::vector<Region>& regions, double scale) {
  std::vector<Point> points;
  for (int i = -1; i <= 36; ++i) {
    for (int j = -1; j <= 36; ++j) points.push_back({i * (scale / 4), j * (scale / 4)});
  }
  for (const Region& region : regions) {
    for (const Ring& ring : region) {
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const Point a = ring[i], b = ring[(i + 1) % ring.size()];
        points.push_back({(a.x + b.x) / 2, (a.y + b.y) / 2});
        points.push_back({std::nextafter(a.x, INFINITY), a.y});
        points.push_back({a.x, std::nextafter(a.y, -INFINITY)});
      }
    }
  }
  return points;
}

TEST(EvenOddRegions, SidesAsDefinedOnGrids) {
  std::mt19937_64 random(20261202);
  std::size_t throughCopies = 0;
  for (int round = 0; round < 40; ++round) {
    const auto regions = gridRegions(random, 1 + round % 5, 1.0);
    const auto points = gridPoints(regions, 1.0);
    expectSidesAsDefined(regions, points, true);
    expectSidesAsDefined(regions, points, false);
    std::vector<const Region*> pointers;
    for (const Region& r : regions) pointers.push_back(&r);
    throughCopies += EvenOddRegions(pointers, true).throughCopies();
    EXPECT_EQ(EvenOddRegions(pointers, false).throughCopies(), 0u);
  }
  EXPECT_GT(throughCopies, 1000u);  // the through edges' path is the one tested
}

TEST(EvenOddRegions, SidesAsDefinedAtEveryMagnitude) {
  std::mt19937_64 random(7);
  // Subnormal (the bands' margins have a floor there), tiny, ordinary, huge (a range that
  // overflows: no through edges; the points stay finite, as the sampling oracle's are).
  for (const double scale : {0x1p-1070, 0x1p-1060, 0x1p-1000, 1e-300, 0.1, 1e10, 1e300, 0x1p1019}) {
    for (int round = 0; round < 6; ++round) {
      const auto regions = gridRegions(random, 3, scale);
      const auto points = gridPoints(regions, scale);
      expectSidesAsDefined(regions, points, true);
    }
  }
}

TEST(EvenOddRegions, StarsThroughManyBands) {
  // Long edges fanning through a point, with points on them and a ring's vertex ulps off the
  // ray's line: the through edges of every band, and their ranges overlapping.
  std::mt19937_64 random(11);
  for (int round = 0; round < 5; ++round) {
    Region star;
    Ring ring;
    for (int k = 0; k < 41; ++k) {
      const double a = k * 2 * 2 * std::acos(-1.0) * 20 / 41;  // a {41/20} star: every edge long
      ring.push_back({std::round(1000 * std::cos(a)) / 8, std::round(1000 * std::sin(a)) / 8});
    }
    star.push_back(ring);
    Region other;
    other.push_back({{-130, -1}, {130, std::nextafter(-1.0, 0.0)}, {0, 130}});
    std::vector<Point> points;
    std::uniform_real_distribution<double> coordinate(-130, 130);
    for (int i = 0; i < 6000; ++i) points.push_back({coordinate(random), coordinate(random)});
    for (const Point& v : ring) points.push_back({v.x / 2, v.y / 2});
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Point a = ring[i], b = ring[(i + 1) % ring.size()];
      points.push_back({(a.x + b.x) / 2, (a.y + b.y) / 2});  // on the edge
      points.push_back({(3 * a.x + b.x) / 4, (3 * a.y + b.y) / 4});
    }
    expectSidesAsDefined({star, other}, points, true);
    const EvenOddRegions bands({&star, &other}, true);
    EXPECT_GE(bands.throughCopies(), 20u);  // the path tested
  }
}

}  // namespace
}  // namespace gh::oracle
