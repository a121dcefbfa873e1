// GEOS 3.11 through its stable, reentrant C API (geos_c.h). Since 3.9 the overlay functions
// GEOSIntersection_r & co. run OverlayNG with its robust noding. Valid polygons with holes only.
#include <geos_c.h>

#include <cstdarg>
#include <cstdio>
#include <memory>
#include <utility>
#include <vector>
#include <string>

#include "ghclip/polygons_with_holes.h"
#include "ghpeers/peer.h"

namespace gh::peers {
namespace {

// One GEOS context per thread, with errors collected instead of printed.
class GeosContext {
 public:
  GeosContext() : handle_(GEOS_init_r()) {
    GEOSContext_setErrorMessageHandler_r(handle_, &GeosContext::onError, this);
  }
  ~GeosContext() { GEOS_finish_r(handle_); }
  GEOSContextHandle_t get() const { return handle_; }
  std::string takeError() { return std::exchange(error_, ""); }

 private:
  static void onError(const char* message, void* self) { static_cast<GeosContext*>(self)->error_ = message; }
  GEOSContextHandle_t handle_;
  std::string error_;
};

GeosContext& context() {
  thread_local GeosContext ctx;
  return ctx;
}

struct GeomDeleter {
  void operator()(GEOSGeometry* g) const { GEOSGeom_destroy_r(context().get(), g); }
};
using Geom = std::unique_ptr<GEOSGeometry, GeomDeleter>;

struct GeosOperand : Prepared {
  Geom geometry;
};

GEOSGeometry* linearRing(const Ring& ring) {
  const auto h = context().get();
  const auto n = static_cast<unsigned>(ring.size());
  GEOSCoordSequence* seq = GEOSCoordSeq_create_r(h, n + 1, 2);
  for (unsigned i = 0; i <= n; ++i) {
    const Point& p = ring[i % n];  // closed: the first point again at the end
    GEOSCoordSeq_setXY_r(h, seq, i, p.x, p.y);
  }
  return GEOSGeom_createLinearRing_r(h, seq);
}

void appendRings(const GEOSGeometry* g, Region& out) {
  const auto h = context().get();
  const int type = GEOSGeomTypeId_r(h, g);
  if (type == GEOS_MULTIPOLYGON || type == GEOS_GEOMETRYCOLLECTION) {
    for (int i = 0, n = GEOSGetNumGeometries_r(h, g); i < n; ++i) appendRings(GEOSGetGeometryN_r(h, g, i), out);
    return;
  }
  if (type != GEOS_POLYGON || GEOSisEmpty_r(h, g)) return;  // lines and points have no area
  auto add = [&](const GEOSGeometry* ring) {
    const GEOSCoordSequence* seq = GEOSGeom_getCoordSeq_r(h, ring);
    unsigned size = 0;
    GEOSCoordSeq_getSize_r(h, seq, &size);
    Ring r;
    r.reserve(size);
    for (unsigned k = 0; k + 1 < size; ++k) {  // the closing point is dropped
      Point p;
      GEOSCoordSeq_getXY_r(h, seq, k, &p.x, &p.y);
      r.push_back(p);
    }
    out.push_back(std::move(r));
  };
  add(GEOSGetExteriorRing_r(h, g));
  for (int i = 0, n = GEOSGetNumInteriorRings_r(h, g); i < n; ++i) add(GEOSGetInteriorRingN_r(h, g, i));
}

class Geos : public Peer {
 public:
  std::string_view name() const override { return "geos"; }
  std::string_view description() const override { return "GEOS 3.11 OverlayNG (C API)"; }
  std::string_view accepts() const override { return "valid simple polygons with holes"; }
  bool validInputOnly() const override { return true; }

  std::unique_ptr<Prepared> prepare(const Region& region) const override {
    const PolygonsWithHoles pwh = toPolygonsWithHoles(region);
    if (pwh.refusal) throw PeerRefusal("geos refuses: " + *pwh.refusal);
    const auto h = context().get();
    std::vector<GEOSGeometry*> polys;
    for (const PolygonWithHoles& p : pwh.polygons) {
      std::vector<GEOSGeometry*> holes;
      for (const Ring& hole : p.holes) holes.push_back(linearRing(hole));
      polys.push_back(GEOSGeom_createPolygon_r(h, linearRing(p.shell), holes.data(), static_cast<unsigned>(holes.size())));
    }
    auto out = std::make_unique<GeosOperand>();
    out->geometry.reset(GEOSGeom_createCollection_r(h, GEOS_MULTIPOLYGON, polys.data(), static_cast<unsigned>(polys.size())));
    if (!out->geometry) throw PeerRefusal("geos refuses: " + context().takeError());
    return out;
  }

  Region run(const Prepared& subject, const Prepared& clip, Op op) const override {
    const auto h = context().get();
    const GEOSGeometry* s = static_cast<const GeosOperand&>(subject).geometry.get();
    const GEOSGeometry* c = static_cast<const GeosOperand&>(clip).geometry.get();
    Geom result;
    switch (op) {
      case Op::Intersection: result.reset(GEOSIntersection_r(h, s, c)); break;
      case Op::Union: result.reset(GEOSUnion_r(h, s, c)); break;
      case Op::Difference: result.reset(GEOSDifference_r(h, s, c)); break;
      case Op::ReverseDifference: result.reset(GEOSDifference_r(h, c, s)); break;
      case Op::Xor: result.reset(GEOSSymDifference_r(h, s, c)); break;
    }
    if (!result) throw ClipFailure("GEOS failed: " + context().takeError());
    Region out;
    appendRings(result.get(), out);
    return out;
  }
};

}  // namespace

const Peer& geosPeer() {
  static const Geos peer;
  return peer;
}

}  // namespace gh::peers
