#include "ghio/ogc_layout.h"

#include <geos_c.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <utility>

#include "ghclip/measure.h"
#include "ghio/output_files.h"

namespace gh::io {
namespace {

class Geos {
 public:
  Geos() : h_(GEOS_init_r()) { GEOSContext_setErrorMessageHandler_r(h_, &Geos::onError, this); }
  ~Geos() { GEOS_finish_r(h_); }
  Geos(const Geos&) = delete;
  Geos& operator=(const Geos&) = delete;
  GEOSContextHandle_t get() const { return h_; }
  std::string error() const { return error_.empty() ? "GEOS failed" : error_; }

 private:
  static void onError(const char* message, void* self) { static_cast<Geos*>(self)->error_ = message; }
  GEOSContextHandle_t h_;
  std::string error_;
};

struct Deleter {
  GEOSContextHandle_t h;
  void operator()(GEOSGeometry* g) const { GEOSGeom_destroy_r(h, g); }
};
using Geometry = std::unique_ptr<GEOSGeometry, Deleter>;

[[noreturn]] void fail(const std::string& why) {
  throw WriteError("cannot write a valid OGC layout (" + why + "); --layout rings writes the raw rings");
}

GEOSGeometry* ringPolygon(const Geos& g, const Ring& ring) {
  GEOSCoordSequence* seq = GEOSCoordSeq_create_r(g.get(), static_cast<unsigned>(ring.size() + 1), 2);
  for (std::size_t i = 0; i <= ring.size(); ++i) {
    const Point& p = ring[i % ring.size()];
    GEOSCoordSeq_setXY_r(g.get(), seq, static_cast<unsigned>(i), p.x, p.y);
  }
  GEOSGeometry* shell = GEOSGeom_createLinearRing_r(g.get(), seq);
  if (!shell) fail(g.error());
  return GEOSGeom_createPolygon_r(g.get(), shell, nullptr, 0);
}

Ring ringOf(const Geos& g, const GEOSGeometry* ring) {
  const GEOSCoordSequence* seq = GEOSGeom_getCoordSeq_r(g.get(), ring);
  unsigned n = 0;
  GEOSCoordSeq_getSize_r(g.get(), seq, &n);
  Ring out;
  out.reserve(n);
  for (unsigned i = 0; i + 1 < n; ++i) {  // without the closing point
    double x, y;
    GEOSCoordSeq_getXY_r(g.get(), seq, i, &x, &y);
    out.push_back({x, y});
  }
  return out;
}

void orient(Ring& ring, bool counterClockwise) {
  if ((signedArea(ring) > 0) != counterClockwise) std::reverse(ring.begin(), ring.end());
}

void collect(const Geos& g, const GEOSGeometry* geometry, std::vector<PolygonWithHoles>& out) {
  const int type = GEOSGeomTypeId_r(g.get(), geometry);
  if (type == GEOS_POLYGON) {
    if (GEOSisEmpty_r(g.get(), geometry)) return;
    PolygonWithHoles p;
    p.shell = ringOf(g, GEOSGetExteriorRing_r(g.get(), geometry));
    orient(p.shell, true);
    const int holes = GEOSGetNumInteriorRings_r(g.get(), geometry);
    for (int i = 0; i < holes; ++i) {
      p.holes.push_back(ringOf(g, GEOSGetInteriorRingN_r(g.get(), geometry, i)));
      orient(p.holes.back(), false);
    }
    out.push_back(std::move(p));
  } else if (type == GEOS_MULTIPOLYGON || type == GEOS_GEOMETRYCOLLECTION) {
    const int n = GEOSGetNumGeometries_r(g.get(), geometry);
    for (int i = 0; i < n; ++i) collect(g, GEOSGetGeometryN_r(g.get(), geometry, i), out);
  }
  // Lines and points (collapsed pieces of zero area) carry no area: dropped.
}

}  // namespace

std::vector<PolygonWithHoles> ogcPolygons(const Region& region) {
  PolygonsWithHoles exact = toPolygonsWithHoles(region);
  if (!exact.refusal) return std::move(exact.polygons);

  // Node every ring's linework, take every face of it, keep the faces whose inside point is
  // inside the region by the even-odd rule (exact), and merge them.
  Geos g;
  std::vector<GEOSGeometry*> lines;
  for (const Ring& ring : region) {
    if (ring.size() < 3) continue;
    GEOSGeometry* polygon = ringPolygon(g, ring);
    lines.push_back(GEOSGeom_clone_r(g.get(), GEOSGetExteriorRing_r(g.get(), polygon)));
    GEOSGeom_destroy_r(g.get(), polygon);
  }
  Geometry linework(
      GEOSGeom_createCollection_r(g.get(), GEOS_MULTILINESTRING, lines.data(), static_cast<unsigned>(lines.size())),
      Deleter{g.get()});
  if (!linework) fail(g.error());
  Geometry noded(GEOSNode_r(g.get(), linework.get()), Deleter{g.get()});
  if (!noded) fail(g.error());
  const GEOSGeometry* nodedPtr = noded.get();
  Geometry faces(GEOSPolygonize_r(g.get(), &nodedPtr, 1), Deleter{g.get()});
  if (!faces) fail(g.error());
  std::vector<GEOSGeometry*> inside;
  for (int i = 0, n = GEOSGetNumGeometries_r(g.get(), faces.get()); i < n; ++i) {
    const GEOSGeometry* face = GEOSGetGeometryN_r(g.get(), faces.get(), i);
    Geometry point(GEOSPointOnSurface_r(g.get(), face), Deleter{g.get()});
    double x, y;
    if (!point || GEOSGeomGetX_r(g.get(), point.get(), &x) != 1 || GEOSGeomGetY_r(g.get(), point.get(), &y) != 1) {
      fail(g.error());
    }
    if (insideEvenOdd(region, {x, y})) inside.push_back(GEOSGeom_clone_r(g.get(), face));
  }
  Geometry kept(
      GEOSGeom_createCollection_r(g.get(), GEOS_MULTIPOLYGON, inside.data(), static_cast<unsigned>(inside.size())),
      Deleter{g.get()});
  if (!kept) fail(g.error());
  Geometry valid(GEOSUnaryUnion_r(g.get(), kept.get()), Deleter{g.get()});
  if (!valid) fail(g.error());
  if (GEOSisValid_r(g.get(), valid.get()) != 1) fail("GEOS's noding of the crossing rings is not valid");
  std::vector<PolygonWithHoles> out;
  collect(g, valid.get(), out);
  // The even-odd area must survive (up to the rounding of the new nodes).
  const double want = evenOddArea(region), got = evenOddArea(toRegion(out));
  if (!(std::abs(want - got) <= 1e-9 * std::max(std::abs(want), 1e-300) + 1e-300)) {
    fail("the noded faces have area " + std::to_string(got) + ", the answer " + std::to_string(want));
  }
  return out;
}

}  // namespace gh::io
