// The OGC layout (ogc_layout.h): valid polygons with holes (decided exactly, ogc_validity.h) whose
// even-odd interior is the rings' up to the rounding of their crossings (the exact oracle), for
// rings that cross, touch, overlap and nest, at every magnitude; and a clip's polygons, laid out
// from the operand edges its answer runs along, judged against op(S, C).
#include <gtest/gtest.h>

#include <cmath>

#include "ghclip/clip.h"
#include "ghclip/clipping.h"
#include "ghclip/errors.h"
#include "ghclip/measure.h"
#include "ghclip/ogc_layout.h"
#include "ghclip/ogc_validity.h"
#include "ghio/formats.h"
#include "ghoracle/exact_oracle.h"
#include "ghwork/generators.h"

namespace gh {
namespace {

Ring rect(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }
Ring pentagram() {
  Ring r;
  for (int k = 0; k < 5; ++k) {
    const double a = M_PI / 2 + 4 * M_PI * k / 5;
    r.push_back({std::cos(a), std::sin(a)});
  }
  return r;
}
Region transformed(const Region& region, int scale, double offset = 0) {
  Region out = region;
  for (Ring& ring : out) {
    for (Point& p : ring) p = {std::ldexp(p.x, scale) + offset, std::ldexp(p.y, scale)};
  }
  return out;
}

// Laid out, valid, and the rings' region up to rounding (the exact oracle judges the polygons as
// the answer to "region union nothing").
std::vector<PolygonWithHoles> laidOut(const Region& region, const std::string& where) {
  const std::vector<PolygonWithHoles> polygons = ogcLayout(region);
  const auto invalid = ogcInvalidity(polygons);
  EXPECT_FALSE(invalid) << where << ": " << *invalid;
  EXPECT_TRUE(oracle::exactCheck(region, {}, Op::Union, toRegion(polygons)).pass) << where;
  return polygons;
}

std::size_t holes(const std::vector<PolygonWithHoles>& polygons) {
  std::size_t n = 0;
  for (const PolygonWithHoles& p : polygons) n += p.holes.size();
  return n;
}

struct Case {
  const char* name;
  Region rings;
  std::size_t polygons, holes;
};
const std::vector<Case>& cases() {
  static const std::vector<Case> all{
      {"pentagram: the five points", {pentagram()}, 5, 0},
      {"bowtie: two triangles touching at the new node", {{{0, 0}, {2, 2}, {2, 0}, {0, 2}}}, 2, 0},
      {"a ring twice: nothing", {rect(0, 0, 1, 1), rect(0, 0, 1, 1)}, 0, 0},
      {"squares sharing an edge: one rectangle", {rect(0, 0, 1, 1), rect(1, 0, 2, 1)}, 1, 0},
      {"square with a hole", {rect(0, 0, 10, 10), rect(2, 2, 8, 8)}, 1, 1},
      {"square, hole, island", {rect(0, 0, 10, 10), rect(2, 2, 8, 8), rect(4, 4, 6, 6)}, 2, 1},
      {"checkerboard: shells touching at a point", {rect(0, 0, 1, 1), rect(1, 1, 2, 2)}, 2, 0},
      {"a hole touching its shell at a vertex", {rect(0, 0, 4, 4), {{2, 0}, {3, 2}, {1, 2}}}, 1, 1},
      {"a ring touching itself: a shell and a hole", {{{0, 0}, {4, 0}, {4, 4}, {0, 4}, {0, 2}, {2, 1}, {1, 3}, {0, 2}}}, 1, 1},
      {"a ring through its own edge: two shells", {{{0, 0}, {4, 0}, {4, 4}, {2, 0}, {0, 4}}}, 2, 0},
      {"overlapping squares: the ring around minus the middle", {rect(0, 0, 2, 2), rect(1, 1, 3, 3)}, 2, 0},
  };
  return all;
}

TEST(OgcLayout, CrossingTouchingOverlappingAndNestedRings) {
  for (const Case& c : cases()) {
    const auto polygons = laidOut(c.rings, c.name);
    EXPECT_EQ(polygons.size(), c.polygons) << c.name;
    EXPECT_EQ(holes(polygons), c.holes) << c.name;
  }
  // Straight-through nodes are not vertices: the rectangle of two squares has four corners.
  EXPECT_EQ(ogcLayout({rect(0, 0, 1, 1), rect(1, 0, 2, 1)}).front().shell.size(), 4u);
}

// Near 1e-300 products underflow, near 1e150 they overflow, near 1e15 the ulp is 0.125: the
// same answers, judged exactly at their own scale.
TEST(OgcLayout, EveryMagnitude) {
  for (const Case& c : cases()) {
    for (const auto& [scale, offset] : std::vector<std::pair<int, double>>{{-1000, 0}, {-1070, 0}, {480, 0}, {0, 1e15}}) {
      const std::string where = std::string(c.name) + " at 2^" + std::to_string(scale) + " + " + std::to_string(offset);
      const auto polygons = laidOut(transformed(c.rings, scale, offset), where);
      if (scale != -1070) {  // at subnormal scale small features may merge
        EXPECT_EQ(polygons.size(), c.polygons) << where;
        EXPECT_EQ(holes(polygons), c.holes) << where;
      }
    }
  }
}

// The README's example (experiments/examples/pentagram.wkt and half_square.wkt): written through
// GEOS's noder, every operation's answer failed the exact oracle (1e-18 of the area beyond
// rounding: the star's self-crossings rounded GEOS's way). And near 1e-300, written empty (the
// union: "MULTIPOLYGON EMPTY", exit 0), because GEOS's area check underflowed.
TEST(OgcLayout, TheReadmeExampleAtEveryMagnitude) {
  const std::string dir = GHCLIP_EXAMPLES;
  const Region star = io::readAuto(io::readText(dir + "/pentagram.wkt"));
  const Region square = io::readAuto(io::readText(dir + "/half_square.wkt"));
  for (const int scale : {0, -997, -1060, 400}) {
    const Region s = transformed(star, scale), c = transformed(square, scale);
    Clipping clipping(s, c);
    for (const Op op : kAllOps) {
      const std::string where = std::string(name(op)) + " at 2^" + std::to_string(scale);
      const auto polygons = clipping.polygons(op);
      const auto invalid = ogcInvalidity(polygons);
      EXPECT_FALSE(invalid) << where << ": " << *invalid;
      // As written: the text read back.
      for (const io::Format format : {io::Format::Wkt, io::Format::GeoJson}) {
        const Region written = io::readAuto(io::write(polygons, format));
        const auto v = oracle::exactCheck(s, c, op, written);
        EXPECT_TRUE(v.pass) << where << ": relative beyond rounding " << v.relativeBeyondRounding();
        if (op == Op::Union) EXPECT_FALSE(written.empty()) << where;
      }
    }
  }
}

// A clip's polygons are its answer: the same even-odd interior as its rings, on every workload.
TEST(OgcLayout, ClipPolygonsAreTheAnswer) {
  for (const std::string& workload : {"random", "grid", "holes", "pie", "archipelago", "sliver", "identical"}) {
    const auto w = work::generate(workload, 20, 3);
    Clipping clipping(w.subject, w.clip);
    for (const Op op : kAllOps) {
      const auto polygons = clipping.polygons(op);
      EXPECT_FALSE(ogcInvalidity(polygons)) << workload << " " << name(op);
      EXPECT_TRUE(oracle::exactCheck(w.subject, w.clip, op, toRegion(polygons)).pass) << workload << " " << name(op);
    }
  }
}

// Features finer than the doubles: a pie and a turned copy whose centres moved by one ulp from
// the origin to (+-5e-324, +-5e-324). Their xor's pieces meet within the subnormal grid, where no
// choice of faithful roundings keeps them apart (these were refused, exit 1): snap rounding does,
// within the rounding the exact oracle allows.
TEST(OgcLayout, FeaturesFinerThanTheDoublesAreSnapRounded) {
  const auto w = work::generate("pie+ulp", 12, 1);
  LayoutStats stats;
  const auto polygons = Clipping(w.subject, w.clip).polygons(Op::Xor, nullptr, &stats);
  EXPECT_TRUE(stats.snapRounded);
  EXPECT_FALSE(ogcInvalidity(polygons));
  EXPECT_TRUE(oracle::exactCheck(w.subject, w.clip, Op::Xor, toRegion(polygons)).pass);
}

TEST(OgcLayout, LinedRingsThatBreakTheirRulesAreRefused) {
  LinedRings r;
  r.lines = {{{0, 0}, {1, 0}}, {{1, 0}, {0, 1}}, {{0, 1}, {0, 0}}};
  r.points = {{0, 0}, {1, 0}, {0, 1}};
  r.ringStart = {0, 3};
  r.line = {0, 1, 2};
  r.exact = {1, 1, 1};
  EXPECT_NO_THROW(ogcLayout(r));
  LinedRings off = r;
  off.points[2] = {0, 2};  // off the lines of its edges
  EXPECT_THROW(ogcLayout(off), InvalidInput);
  LinedRings parallel = r;
  parallel.lines.push_back({{5, 0}, {6, 0}});
  parallel.line = {0, 3, 2};
  parallel.exact = {1, 0, 1};  // vertex 1 the crossing of two parallel lines
  EXPECT_THROW(ogcLayout(parallel), InvalidInput);
  LinedRings outOfRange = r;
  outOfRange.line[1] = 7;
  EXPECT_THROW(ogcLayout(outOfRange), InvalidInput);
  EXPECT_THROW(ogcLayout(Region{{{0, 0}, {1, NAN}, {0, 1}}}), InvalidInput);
}

}  // namespace
}  // namespace gh
