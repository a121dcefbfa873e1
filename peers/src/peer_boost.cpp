// Boost.Geometry 1.74: multi_polygon overlays (intersection, union_, difference, sym_difference)
// on double coordinates. Valid polygons with holes only.
#include <boost/geometry.hpp>
#include <boost/geometry/geometries/multi_polygon.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>

#include "ghclip/polygons_with_holes.h"
#include "ghpeers/peer.h"

namespace gh::peers {
namespace {

namespace bg = boost::geometry;
using BPoint = bg::model::d2::point_xy<double>;
using BPolygon = bg::model::polygon<BPoint, /*ClockWise=*/false, /*Closed=*/true>;
using BMulti = bg::model::multi_polygon<BPolygon>;

struct BoostOperand : Prepared {
  BMulti geometry;
};

void fill(bg::model::ring<BPoint, false, true>& out, const Ring& ring) {
  out.reserve(ring.size() + 1);
  for (const Point& p : ring) out.push_back(BPoint(p.x, p.y));
  out.push_back(BPoint(ring.front().x, ring.front().y));
}

Ring toRing(const bg::model::ring<BPoint, false, true>& r) {
  Ring ring;
  for (std::size_t i = 0; i + 1 < r.size(); ++i) ring.push_back({r[i].x(), r[i].y()});
  return ring;
}

class Boost : public Peer {
 public:
  std::string_view name() const override { return "boost"; }
  std::string_view description() const override { return "Boost.Geometry 1.74 overlay"; }
  std::string_view accepts() const override { return "valid simple polygons with holes"; }
  bool validInputOnly() const override { return true; }

  std::unique_ptr<Prepared> prepare(const Region& region) const override {
    const PolygonsWithHoles pwh = toPolygonsWithHoles(region);
    if (pwh.refusal) throw PeerRefusal("boost refuses: " + *pwh.refusal);
    auto out = std::make_unique<BoostOperand>();
    for (const PolygonWithHoles& p : pwh.polygons) {
      BPolygon poly;
      fill(poly.outer(), p.shell);  // counter-clockwise, as declared
      for (const Ring& hole : p.holes) {
        poly.inners().emplace_back();
        fill(poly.inners().back(), hole);
      }
      out->geometry.push_back(std::move(poly));
    }
    return out;
  }

  Region run(const Prepared& subject, const Prepared& clip, Op op) const override {
    const BMulti& s = static_cast<const BoostOperand&>(subject).geometry;
    const BMulti& c = static_cast<const BoostOperand&>(clip).geometry;
    BMulti result;
    switch (op) {
      case Op::Intersection: bg::intersection(s, c, result); break;
      case Op::Union: bg::union_(s, c, result); break;
      case Op::Difference: bg::difference(s, c, result); break;
      case Op::ReverseDifference: bg::difference(c, s, result); break;
      case Op::Xor: bg::sym_difference(s, c, result); break;
    }
    Region out;
    for (const BPolygon& poly : result) {
      out.push_back(toRing(poly.outer()));
      for (const auto& inner : poly.inners()) out.push_back(toRing(inner));
    }
    return out;
  }
};

}  // namespace

const Peer& boostPeer() {
  static const Boost peer;
  return peer;
}

}  // namespace gh::peers
