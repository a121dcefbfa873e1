// WKT and GeoJSON readers and writers.
#include <gtest/gtest.h>

#include "ghclip/errors.h"
#include "ghclip/measure.h"
#include "ghio/formats.h"
#include "ghio/svg.h"

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
