#include "ghio/ogc_layout.h"

#include <geos_c.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
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

// Why one way of building the faces failed; the next is tried.
struct NotThisWay {
  std::string why;
};

// The point that decides a face's side of the region: one strictly inside it, not on its
// boundary. GEOS's interior point can land on the boundary where its scan line meets a vertex (a
// unit square turned by 30 degrees: the face was then taken for outside), so it is verified, and
// else the centroid and the centroids of the shell's corners are tried. A face with no double
// strictly inside is an ulp wide: either side of it is within the rounding the area check allows
// (which catches a wide face taken wrongly), and GEOS's interior point decides, or a corner's
// centroid where GEOS's is not finite. Empty only when GEOS fails.
std::optional<Point> decidingPoint(const Geos& g, const GEOSGeometry* face) {
  // Only a finite point: GEOS gave a face at subnormal coordinates a point on its surface with x
  // NaN (0/0), which no even-odd test can decide.
  auto pointOf = [&](const Geometry& point) -> std::optional<Point> {
    double x, y;
    if (!point || GEOSGeomGetX_r(g.get(), point.get(), &x) != 1 || GEOSGeomGetY_r(g.get(), point.get(), &y) != 1 ||
        !std::isfinite(x) || !std::isfinite(y)) {
      return std::nullopt;
    }
    return Point{x, y};
  };
  auto strictlyInside = [&](GEOSGeometry* candidate) -> std::optional<Point> {
    const Geometry point(candidate, Deleter{g.get()});
    if (!point || GEOSContains_r(g.get(), face, point.get()) != 1) return std::nullopt;
    return pointOf(point);
  };
  const Geometry onSurface(GEOSPointOnSurface_r(g.get(), face), Deleter{g.get()});
  if (onSurface && GEOSContains_r(g.get(), face, onSurface.get()) == 1) return pointOf(onSurface);
  if (auto p = strictlyInside(GEOSGetCentroid_r(g.get(), face))) return p;
  const Ring shell = ringOf(g, GEOSGetExteriorRing_r(g.get(), face));
  // A corner's centroid, in thirds: the sum of three coordinates near 1e308 would overflow.
  auto cornerCentroid = [&](std::size_t k) {
    const std::size_t n = shell.size();
    const Point a = shell[(k + n - 1) % n], b = shell[k], c = shell[(k + 1) % n];
    return Point{a.x / 3 + b.x / 3 + c.x / 3, a.y / 3 + b.y / 3 + c.y / 3};
  };
  for (std::size_t k = 0; k < shell.size(); ++k) {
    const Point p = cornerCentroid(k);
    if (auto inside = strictlyInside(GEOSGeom_createPointFromXY_r(g.get(), p.x, p.y))) return inside;
  }
  if (auto p = pointOf(onSurface)) return p;
  // No finite point strictly inside, and none from GEOS: the face is an ulp wide, so either side
  // will do (see above); a corner's centroid is one.
  if (!shell.empty()) return cornerCentroid(0);
  return std::nullopt;
}

// The rings' linework noded, every face of it whose inside point is inside the region by the
// even-odd rule (exact), merged. gridSize 0: GEOS's floating noder, new nodes rounded to doubles;
// else snap-rounded to that grid (OverlayNG with a fixed precision model: its result is valid
// by construction, every vertex moved by at most the grid). Checked valid, and of the region's
// even-odd area to within what moving the boundary by `moved` can change: its length times that.
struct Measures {
  double area;      // the region's even-odd area
  double boundary;  // the length of its rings
};
std::vector<PolygonWithHoles> evenOddFaces(const Region& region, const Measures& want, double gridSize, double moved) {
  Geos g;
  auto need = [&](bool ok) {
    if (!ok) throw NotThisWay{g.error()};
  };
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
  need(linework != nullptr);
  Geometry noded(gridSize > 0 ? GEOSUnaryUnionPrec_r(g.get(), linework.get(), gridSize) : GEOSNode_r(g.get(), linework.get()),
                 Deleter{g.get()});
  need(noded != nullptr);
  const GEOSGeometry* nodedPtr = noded.get();
  Geometry faces(GEOSPolygonize_r(g.get(), &nodedPtr, 1), Deleter{g.get()});
  need(faces != nullptr);
  std::vector<GEOSGeometry*> inside;
  for (int i = 0, n = GEOSGetNumGeometries_r(g.get(), faces.get()); i < n; ++i) {
    const GEOSGeometry* face = GEOSGetGeometryN_r(g.get(), faces.get(), i);
    const std::optional<Point> point = decidingPoint(g, face);
    need(point.has_value());
    if (insideEvenOdd(region, *point)) inside.push_back(GEOSGeom_clone_r(g.get(), face));
  }
  Geometry kept(
      GEOSGeom_createCollection_r(g.get(), GEOS_MULTIPOLYGON, inside.data(), static_cast<unsigned>(inside.size())),
      Deleter{g.get()});
  need(kept != nullptr);
  // The kept faces of one noded linework share whole edges: a coverage union dissolves those
  // without moving anything. GEOS's unary union nodes them again and may snap (Clipper2's test
  // polygons 20 turned by 30 degrees: its union's layout needed ghcheck --ulps 17, the coverage
  // union's passes at 2): only where the coverage union fails.
  Geometry merged(gridSize > 0 ? GEOSUnaryUnionPrec_r(g.get(), kept.get(), gridSize) : GEOSCoverageUnion_r(g.get(), kept.get()),
                  Deleter{g.get()});
  auto isValid = [&](const Geometry& m) { return m && GEOSisValid_r(g.get(), m.get()) == 1; };
  bool valid = isValid(merged);
  if (!valid && gridSize == 0) {
    merged.reset(GEOSUnaryUnion_r(g.get(), kept.get()));
    valid = isValid(merged);
  }
  need(merged != nullptr);
  if (!valid) throw NotThisWay{"GEOS's noding of the crossing rings is not valid"};
  std::vector<PolygonWithHoles> out;
  collect(g, merged.get(), out);
  // A face wrongly kept or left out changes the area by far more than moving the boundary does.
  const double got = evenOddArea(toRegion(out));
  if (!(std::abs(want.area - got) <= 1e-9 * std::abs(want.area) + want.boundary * moved)) {
    char why[160];
    std::snprintf(why, sizeof why, "the noded faces have area %.17g, the answer %.17g", got, want.area);
    throw NotThisWay{why};
  }
  return out;
}

}  // namespace

std::vector<PolygonWithHoles> ogcPolygons(const Region& region) {
  PolygonsWithHoles exact = toPolygonsWithHoles(region);
  if (!exact.refusal) return std::move(exact.polygons);
  // The unit in the last place of the largest coordinate: new nodes are rounded to doubles,
  // within about one of it (GEOS computes them in double-double arithmetic); two in hand.
  double largest = 0;
  for (const Ring& ring : region) {
    for (const Point& p : ring) largest = std::max({largest, std::abs(p.x), std::abs(p.y)});
  }
  const double ulp = std::nextafter(largest, INFINITY) - largest;
  // Measured once for every way tried (the even-odd area is quadratic in the vertices).
  Measures want{evenOddArea(region), 0};
  for (const Ring& ring : region) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Point a = ring[i], b = ring[(i + 1) % ring.size()];
      want.boundary += std::hypot(b.x - a.x, b.y - a.y);
    }
  }
  std::string why;
  try {
    return evenOddFaces(region, want, 0, 2 * ulp);
  } catch (const NotThisWay& e) {
    why = e.why;
  }
  // Slivers a few ulps wide (a polygon against its copy moved by an ulp) can defeat floating
  // noding: snap-round them to the finest power-of-two grid that gives a valid answer.
  for (double grid = std::exp2(std::ceil(std::log2(ulp))), last = grid * 0x1p24; grid <= last; grid *= 16) {
    try {
      return evenOddFaces(region, want, grid, 2 * grid);
    } catch (const NotThisWay&) {
    }
  }
  fail(why);
}

}  // namespace gh::io
