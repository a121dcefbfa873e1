// What a GIS tool reads from our output: every answer written as WKT and GeoJSON is read back by
// GEOS's own readers (the C API: a real, independent reader). The OGC layout (the library's:
// ghclip/ogc_layout.h) must be valid by GEOSisValid as well as by our exact check, and pass the
// exact oracle as GEOS read it; the rings layout must parse, and its rings give the answer.
#include <geos_c.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "ghclip/clip.h"
#include "ghclip/measure.h"
#include "ghclip/ogc_validity.h"
#include "ghclip/polygons_with_holes.h"
#include "ghio/formats.h"
#include "ghoracle/exact_oracle.h"
#include "ghwork/generators.h"

namespace gh {
namespace {

class GeosReader {
 public:
  GeosReader() : h_(GEOS_init_r()) {
    wkt_ = GEOSWKTReader_create_r(h_);
    json_ = GEOSGeoJSONReader_create_r(h_);
  }
  ~GeosReader() {
    GEOSWKTReader_destroy_r(h_, wkt_);
    GEOSGeoJSONReader_destroy_r(h_, json_);
    GEOS_finish_r(h_);
  }
  struct Read {
    bool parsed = false, valid = false;
    double area = 0;  // GEOS's (OGC) area
    Region rings;     // every ring, for an even-odd area
  };
  Read read(const std::string& text, io::Format format) {
    GEOSGeometry* g = format == io::Format::Wkt ? GEOSWKTReader_read_r(h_, wkt_, text.c_str())
                                                : GEOSGeoJSONReader_readGeometry_r(h_, json_, text.c_str());
    Read r;
    if (!g) return r;
    r.parsed = true;
    r.valid = GEOSisValid_r(h_, g) == 1;
    GEOSArea_r(h_, g, &r.area);
    collectRings(g, r.rings);
    GEOSGeom_destroy_r(h_, g);
    return r;
  }

 private:
  void addRing(const GEOSGeometry* ring, Region& out) {
    const GEOSCoordSequence* seq = GEOSGeom_getCoordSeq_r(h_, ring);
    unsigned n = 0;
    GEOSCoordSeq_getSize_r(h_, seq, &n);
    Ring r;
    for (unsigned i = 0; i + 1 < n; ++i) {
      double x, y;
      GEOSCoordSeq_getXY_r(h_, seq, i, &x, &y);
      r.push_back({x, y});
    }
    out.push_back(r);
  }
  void collectRings(const GEOSGeometry* g, Region& out) {
    const int type = GEOSGeomTypeId_r(h_, g);
    if (type == GEOS_POLYGON) {
      if (GEOSisEmpty_r(h_, g)) return;
      addRing(GEOSGetExteriorRing_r(h_, g), out);
      for (int i = 0; i < GEOSGetNumInteriorRings_r(h_, g); ++i) addRing(GEOSGetInteriorRingN_r(h_, g, i), out);
    } else {
      for (int i = 0; i < GEOSGetNumGeometries_r(h_, g); ++i) collectRings(GEOSGetGeometryN_r(h_, g, i), out);
    }
  }
  GEOSContextHandle_t h_;
  GEOSWKTReader* wkt_;
  GEOSGeoJSONReader* json_;
};

bool close(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b)) + 1e-300; }

TEST(OgcOutput, GeosReadsEveryAnswerValidAndRight) {
  GeosReader geos;
  int answers = 0, crossingRings = 0;
  for (const std::string& workload : work::workloadNames()) {
    for (std::uint64_t seed = 1; seed <= 2; ++seed) {
      const auto w = work::generate(workload, 40, seed);
      for (Op op : kAllOps) {
        const Region r = clip(w.subject, w.clip, op);
        const auto polygons = clipPolygons(w.subject, w.clip, op);
        crossingRings += toPolygonsWithHoles(r).refusal.has_value();
        const auto invalid = ogcInvalidity(polygons);
        EXPECT_FALSE(invalid) << workload << " seed " << seed << " " << name(op) << ": " << *invalid;
        for (io::Format format : {io::Format::Wkt, io::Format::GeoJson}) {
          const std::string where = workload + " seed " + std::to_string(seed) + " " + std::string(name(op)) +
                                    (format == io::Format::Wkt ? " wkt" : " geojson");
          const auto ogc = geos.read(io::write(polygons, format), format);
          ASSERT_TRUE(ogc.parsed) << where;
          EXPECT_TRUE(ogc.valid) << where;
          EXPECT_TRUE(oracle::exactCheck(w.subject, w.clip, op, ogc.rings).pass) << where;
          const auto rings = geos.read(io::write(r, format, io::Layout::Rings), format);
          ASSERT_TRUE(rings.parsed) << where;
          EXPECT_TRUE(close(evenOddArea(rings.rings), evenOddArea(r))) << where;
          ++answers;
        }
      }
    }
  }
  RecordProperty("answers", answers);
  EXPECT_GT(crossingRings, 0) << "no answer's rings cross: the test does not reach the noding";
}

// An empty answer (once written MULTIPOLYGON(), which GEOS refuses), and a square with a hole
// united with a gate through the frame (once written as overlapping polygons: GEOS read more area).
TEST(OgcOutput, EmptyAnswersAndHolesReadRight) {
  GeosReader geos;
  for (io::Format format : {io::Format::Wkt, io::Format::GeoJson}) {
    const auto empty = geos.read(io::write(std::vector<PolygonWithHoles>{}, format), format);
    ASSERT_TRUE(empty.parsed);
    EXPECT_EQ(empty.area, 0);
    EXPECT_TRUE(io::readAuto(io::write(std::vector<PolygonWithHoles>{}, format)).empty());
    const Region squareWithHole{{{0, 0}, {5, 0}, {5, 5}, {0, 5}}, {{1, 1}, {4, 1}, {4, 4}, {1, 4}}};
    const Region gate{{{2, -1}, {3, -1}, {3, 2}, {2, 2}}};
    const Region u = clip(squareWithHole, gate, Op::Union);
    const auto read = geos.read(io::write(clipPolygons(squareWithHole, gate, Op::Union), format), format);
    EXPECT_TRUE(read.valid);
    EXPECT_DOUBLE_EQ(read.area, evenOddArea(u));
    EXPECT_DOUBLE_EQ(read.area, 18);  // the frame's 16, the gate's part below it and in the hole
  }
}

// Regression (real data, Natural Earth's country outlines): valid polygons against copies moved by
// one ulp or 1e-9 make answers of slivers a few ulps wide whose rings cross. GEOS's floating
// noder failed to converge on one ("Iterated noding failed"), and the noded faces' area missed the
// answer's by more than 1e-9 of it on the others, so ghclip refused to write them (exit 2) though
// both inputs were valid and the answer right. The OGC layout of each must be written, valid, and
// right up to the rounding of the nodes: the exact oracle, at its faithful rounding (the GEOS-noded
// layout needed 2 ulps).
TEST(OgcOutput, SliversOfShiftedCopiesAreWrittenValid) {
  struct Case {
    const char* name;
    Region a, b;
    Op op;
  };
  const std::vector<Case> cases{
      {"Lesotho's corner xor its 1-ulp shift",
       {{{28.107205, -30.545732}, {27.749397, -30.645106}, {28.074338, -28.851469}}},
       {{{28.107205000000004, -30.545732}, {27.749397000000002, -30.645106}, {28.074338000000004, -28.851469}}},
       Op::Xor},
      {"a corner of the USA xor its 1-ulp shift (GEOS's noder did not converge)",
       {{{-72.295, 41.27}, {-72.87643, 41.22065}, {-73.71, 40.931102}}},
       {{{-72.29499999999999, 41.27}, {-72.87642999999998, 41.22065}, {-73.70999999999998, 40.931102}}},
       Op::Xor},
      {"Canada's border on y = 49 minus its 1e-9 shift",
       {{{-104.04826, 48.99986}, {-110.05, 49}, {-113, 49}, {-116.04818, 49}, {-91.51964, 70.19129}}},
       {{{-104.048259999, 48.99986}, {-110.049999999, 49}, {-112.999999999, 49}, {-116.048179999, 49},
         {-91.51963999899999, 70.19129}}},
       Op::Difference},
  };
  GeosReader geos;
  for (const Case& c : cases) {
    for (const Op op : {c.op, Op::Xor, Op::Difference, Op::ReverseDifference}) {
      const Region r = clip(c.a, c.b, op);
      ASSERT_TRUE(oracle::exactCheck(c.a, c.b, op, r).pass) << c.name;
      for (io::Format format : {io::Format::Wkt, io::Format::GeoJson}) {
        const std::string where = std::string(c.name) + ", " + std::string(name(op)) + (format == io::Format::Wkt ? ", wkt" : ", geojson");
        std::string text;
        ASSERT_NO_THROW(text = io::write(clipPolygons(c.a, c.b, op), format)) << where;
        const auto read = geos.read(text, format);
        ASSERT_TRUE(read.parsed) << where;
        EXPECT_TRUE(read.valid) << where;
        const auto verdict = oracle::exactCheck(c.a, c.b, op, read.rings);
        EXPECT_TRUE(verdict.pass) << where << ": GEOS reads area " << read.area << ", the answer's is " << evenOddArea(r);
      }
    }
  }
}

// Found by the fuzz campaign at a66d06c (fuzz_clip_naive's finding input-1cff621a1c070b84, whose
// picture ghclip drew): the exact union of these operands is one crossing ring with a vertex at
// (denorm_min, -2 denorm_min), and GEOS gave the face there a point on its surface with x NaN;
// the writer's even-odd test of that point reached GMP, which raised SIGFPE. Every operation's
// answer must be written, valid, and right (it needed 2 ulps through GEOS's noding).
TEST(OgcOutput, AFaceAtSubnormalCoordinatesGetsAFinitePoint) {
  const Region s = io::readWkt("MULTIPOLYGON(((5e-324 -1e-323,7.999999999999999 0,0 0,8 4,6 0,5e-324 -1e-323)))");
  const Region c = io::readWkt(
      "MULTIPOLYGON(((8 1.0000000000000002,8 6.001953125,4.440892098500626e-16 6,8.000000000000002 7,"
      "0 3.0000000004656613,2 5,7 4,3 0,0 0,0 0,0 0,0 0,8 1.0000000000000002)))");
  GeosReader geos;
  for (Op op : kAllOps) {
    const Region r = clip(s, c, op);
    EXPECT_TRUE(oracle::exactCheck(s, c, op, r).pass) << name(op);
    for (io::Format format : {io::Format::Wkt, io::Format::GeoJson}) {
      const std::string where = std::string(name(op)) + (format == io::Format::Wkt ? ", wkt" : ", geojson");
      std::string text;
      ASSERT_NO_THROW(text = io::write(clipPolygons(s, c, op), format)) << where;
      const auto read = geos.read(text, format);
      ASSERT_TRUE(read.parsed) << where;
      EXPECT_TRUE(read.valid) << where;
      EXPECT_TRUE(oracle::exactCheck(s, c, op, read.rings).pass) << where << ": GEOS reads area " << read.area;
    }
  }
}

// GEOS's own robustness case (libgeos/geos, tests/xmltester/tests/robust/overlay/
// TestOverlay-misc-5.xml, case 1: two parcels near 5.4e6 with nearly coincident vertices): the
// difference's rings cross. Laid out by GEOS's iterated floating noding, the new nodes drifted
// more than 2 ulps (the exact oracle wanted 8); laid out from the operand edges the answer runs
// along, it is right to the faithful rounding.
TEST(OgcOutput, NodesWhereRingsCrossAreRoundedFaithfully) {
  const Region a = io::readAuto(io::readText(std::string(GHCLIP_TEST_DATA) + "/geos_overlay_misc5_a.wkt"));
  const Region b = io::readAuto(io::readText(std::string(GHCLIP_TEST_DATA) + "/geos_overlay_misc5_b.wkt"));
  const Region r = clip(a, b, Op::Difference);
  ASSERT_TRUE(oracle::exactCheck(a, b, Op::Difference, r).pass);
  ASSERT_TRUE(toPolygonsWithHoles(r).refusal.has_value()) << "the rings no longer cross: no node is new";
  GeosReader geos;
  const auto read = geos.read(io::write(clipPolygons(a, b, Op::Difference), io::Format::Wkt), io::Format::Wkt);
  ASSERT_TRUE(read.parsed);
  EXPECT_TRUE(read.valid);
  EXPECT_TRUE(oracle::exactCheck(a, b, Op::Difference, read.rings).pass);
}

// Boost.Geometry's overlay case case_recursive_boxes_2 (boostorg/geometry,
// test/algorithms/overlay/multi_overlay_cases.hpp), turned by 30 degrees in doubles: unit boxes
// touching at corners, so the xor's rings touch. When GEOS built the faces, its interior point of
// one square face fell on its boundary, the face was taken for outside, and the layout was
// snap-rounded (every vertex moved; the exact oracle wanted 8 ulps). The faces' sides are now
// decided by a sweep, exactly.
TEST(OgcOutput, FacesAreClassifiedByPointsStrictlyInside) {
  const std::string data = GHCLIP_TEST_DATA;
  const Region a = io::readAuto(io::readText(data + "/boost_recursive_boxes_2_turned_a.wkt"));
  const Region b = io::readAuto(io::readText(data + "/boost_recursive_boxes_2_turned_b.wkt"));
  GeosReader geos;
  for (const Op op : kAllOps) {
    const auto read = geos.read(io::write(clipPolygons(a, b, op), io::Format::Wkt), io::Format::Wkt);
    ASSERT_TRUE(read.parsed) << name(op);
    EXPECT_TRUE(read.valid) << name(op);
    EXPECT_TRUE(oracle::exactCheck(a, b, op, read.rings).pass) << name(op);
  }
}

}  // namespace
}  // namespace gh
