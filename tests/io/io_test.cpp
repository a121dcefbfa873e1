// WKT and GeoJSON readers and writers.
#include <gtest/gtest.h>

#include "ghclip/errors.h"
#include "ghclip/measure.h"
#include "ghio/formats.h"
#include "ghio/svg.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

namespace gh {
namespace {

TEST(Wkt, PolygonRingsArePooled) {
  const Region r = io::readWkt("POLYGON((0 0,4 0,4 4,0 4,0 0),(1 1,3 1,3 3,1 3,1 1))");
  ASSERT_EQ(r.size(), 2u);
  EXPECT_NEAR(evenOddArea(r), 12, 1e-12);
}

TEST(Wkt, MultipolygonRingsArePooledUnderEvenOdd) {
  // Two overlapping squares given as a multipolygon: even-odd leaves the overlap out.
  const Region r = io::readWkt("MULTIPOLYGON(((0 0,2 0,2 2,0 2,0 0)),((1 1,3 1,3 3,1 3,1 1)))");
  ASSERT_EQ(r.size(), 2u);
  EXPECT_NEAR(evenOddArea(r), 6, 1e-12);
}

TEST(Wkt, MultiLineTextWithTrailingNewline) {
  const Region r = io::readWkt("POLYGON((0 0,\n\t4 0,4 4,\r\n0 4,0 0))\n\n");
  ASSERT_EQ(r.size(), 1u);
  EXPECT_NEAR(evenOddArea(r), 16, 1e-12);
}

TEST(Wkt, RoundTripsEveryDouble) {
  const Region r{{{0.1, 1.0 / 3}, {2e-300, 7}, {-1e150, 5e-324}}};
  const Region back = io::readWkt(io::writeWkt(r));
  ASSERT_EQ(back.size(), 1u);
  ASSERT_EQ(back[0].size(), 4u);  // closed on output
  for (int i = 0; i < 3; ++i) EXPECT_EQ(back[0][i], r[0][i]);
}

TEST(Wkt, EmptyAndMalformedInput) {
  EXPECT_TRUE(io::readWkt("POLYGON EMPTY").empty());
  EXPECT_THROW(io::readWkt("POLYGON((0 0,1 0,1 1"), InvalidInput);
  EXPECT_THROW(io::readWkt("POINT(1 2)"), InvalidInput);
  EXPECT_THROW(io::readWkt("POLYGON((0 0,1 x,1 1,0 0))"), InvalidInput);
  EXPECT_THROW(io::readWkt(""), InvalidInput);
}

// What PostGIS writes: ST_Collect's GEOMETRYCOLLECTION of polygons (nested, with EMPTY members
// and their own Z tags), after EWKT's "SRID=n;". Every ring is pooled as in a MULTIPOLYGON.
TEST(Wkt, CollectionsOfPolygonsAndSridPrefix) {
  const Region r = io::readWkt(
      "SRID=4326;GEOMETRYCOLLECTION(POLYGON((0 0,4 0,4 4,0 4,0 0)),POLYGON EMPTY,"
      "GEOMETRYCOLLECTION Z(MULTIPOLYGON Z(((1 1 9,3 1 9,3 3 9,1 3 9,1 1 9)))),GEOMETRYCOLLECTION EMPTY)");
  ASSERT_EQ(r.size(), 2u);
  EXPECT_NEAR(evenOddArea(r), 12, 1e-12);
  EXPECT_EQ(r[1][2], (Point{3, 3}));
  EXPECT_TRUE(io::readWkt("GEOMETRYCOLLECTION EMPTY").empty());
  EXPECT_EQ(io::readWkt("srid=-1 ; polygon((0 0,1 0,1 1,0 0))").size(), 1u);
  // Anything else in a collection is refused, as a bare POINT is; so are a bad prefix and
  // nesting deeper than the reader follows.
  EXPECT_THROW(io::readWkt("GEOMETRYCOLLECTION(POLYGON((0 0,1 0,1 1,0 0)),POINT(1 2))"), InvalidInput);
  EXPECT_THROW(io::readWkt("SRID=;POLYGON((0 0,1 0,1 1,0 0))"), InvalidInput);
  EXPECT_THROW(io::readWkt("SRID=4326 POLYGON((0 0,1 0,1 1,0 0))"), InvalidInput);
  std::string deep;
  for (int i = 0; i < 100000; ++i) deep += "GEOMETRYCOLLECTION(";
  try {
    io::readWkt(deep);
    ADD_FAILURE() << "deep nesting read";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("nested"), std::string::npos) << e.what();
  }
  std::string fine = "POLYGON((0 0,1 0,1 1,0 0))";
  for (int i = 0; i < 64; ++i) fine = "GEOMETRYCOLLECTION(" + fine + ")";
  EXPECT_EQ(io::readWkt(fine).size(), 1u);
  EXPECT_THROW(io::readWkt("GEOMETRYCOLLECTION(" + fine + ")"), InvalidInput);
}

TEST(GeoJson, GeometriesFeaturesAndCollections) {
  const std::string square = "[[0,0],[2,0],[2,2],[0,2],[0,0]]";
  EXPECT_NEAR(evenOddArea(io::readGeoJson(R"({"type":"Polygon","coordinates":[)" + square + "]}")),
              4, 1e-12);
  const Region fc = io::readGeoJson(
      R"({"type":"FeatureCollection","features":[{"type":"Feature","properties":{},"geometry":)"
      R"({"type":"MultiPolygon","coordinates":[[)" +
      square + R"(]]}}]})");
  EXPECT_NEAR(evenOddArea(fc), 4, 1e-12);
}

TEST(GeoJson, RoundTrip) {
  const Region r{{{0, 0}, {1, 0}, {0.5, 1.0 / 3}}};
  const Region back = io::readGeoJson(io::writeGeoJson(r));
  ASSERT_EQ(back.size(), 1u);
  EXPECT_EQ(back[0][2], r[0][2]);
}

// Every writer must print digits that read back to the very double: random bit patterns over the
// whole finite range, subnormals, signed zeros and the extremes, through all three GeoJSON writers.
std::vector<double> awkwardDoubles() {
  std::vector<double> v{0.0, -0.0, 5e-324, -5e-324, 2.2250738585072014e-308, 2.2250738585072009e-308,
                        1.7976931348623157e308, -1.7976931348623157e308, 0.1, 1.0 / 3, 1e23, 9007199254740993.0,
                        123456789012345678.0, 5e-310, 1e-7, 1e21, 1e22};
  std::mt19937_64 random(18);
  while (v.size() < 200000) {
    const std::uint64_t bits = random();
    double d;
    std::memcpy(&d, &bits, sizeof d);
    if (std::isfinite(d)) v.push_back(d);
  }
  return v;
}

Ring ringOf(const std::vector<double>& values, std::size_t first, std::size_t n) {
  Ring r;
  for (std::size_t i = first; i + 1 < first + 2 * n && i + 1 < values.size(); i += 2) {
    r.push_back({values[i], values[i + 1]});
  }
  return r;
}

std::uint64_t bitsOf(double d) {
  std::uint64_t bits;
  std::memcpy(&bits, &d, sizeof bits);
  return bits;
}

// The readers keep the closing position the writers add, so `back` has one point more per ring.
void expectSameBits(const Region& back, const Region& written) {
  ASSERT_EQ(back.size(), written.size());
  for (std::size_t i = 0; i < back.size(); ++i) {
    ASSERT_EQ(back[i].size(), written[i].size() + 1);
    for (std::size_t k = 0; k < back[i].size(); ++k) {
      const Point& w = written[i][k % written[i].size()];
      ASSERT_EQ(bitsOf(back[i][k].x), bitsOf(w.x)) << w.x;
      ASSERT_EQ(bitsOf(back[i][k].y), bitsOf(w.y)) << w.y;
    }
  }
}

TEST(GeoJson, EveryWriterRoundTripsEveryDouble) {
  const std::vector<double> values = awkwardDoubles();
  const Region rings{ringOf(values, 0, 50000), ringOf(values, 100000, 50000)};
  expectSameBits(io::readGeoJson(io::writeGeoJson(rings)), rings);

  const std::vector<PolygonWithHoles> polygons{{rings[0], {rings[1]}}};
  expectSameBits(io::readGeoJson(io::writeGeoJson(polygons)), rings);

  const io::RegionPair pair = io::readPair(io::writeGeoJsonPair(Region{rings[1]}, Region{rings[0]}));
  expectSameBits(pair.subject, Region{rings[1]});
  expectSameBits(pair.clip, Region{rings[0]});
}

TEST(GeoJson, EmptyAnswersAreEmptyMultiPolygons) {
  EXPECT_EQ(io::writeGeoJson(Region{}), R"({"type":"MultiPolygon","coordinates":[]})");
  EXPECT_EQ(io::writeGeoJson(std::vector<PolygonWithHoles>{}), R"({"type":"MultiPolygon","coordinates":[]})");
  EXPECT_TRUE(io::readGeoJson(io::writeGeoJson(Region{})).empty());
}

TEST(GeoJson, MalformedInput) {
  EXPECT_THROW(io::readGeoJson("{"), InvalidInput);
  EXPECT_THROW(io::readGeoJson(R"({"type":"Point","coordinates":[1,2]})"), InvalidInput);
  EXPECT_THROW(io::readGeoJson(R"({"type":"Polygon","coordinates":[[[0,"a"]]]})"), InvalidInput);
  EXPECT_THROW(io::readGeoJson(R"({"type":"Polygon"})"), InvalidInput);
}

TEST(Auto, DetectsTheFormat) {
  EXPECT_EQ(io::readAuto("  {\"type\":\"Polygon\",\"coordinates\":[]}").size(), 0u);
  EXPECT_EQ(io::readAuto("POLYGON((0 0,1 0,1 1,0 0))").size(), 1u);
  EXPECT_THROW(io::readAuto("   "), InvalidInput);
}

TEST(Svg, UsesTheEvenOddFillRule) {
  const Region r{{{0, 0}, {1, 0}, {0, 1}}};
  const std::string svg = io::svgPicture({{&r, "#00f", "#000", "a <b>"}}, "t");
  EXPECT_NE(svg.find("fill-rule=\"evenodd\""), std::string::npos);
  EXPECT_NE(svg.find("a &lt;b&gt;"), std::string::npos);
}

}  // namespace
}  // namespace gh
