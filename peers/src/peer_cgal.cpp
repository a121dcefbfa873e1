// CGAL 5.5 Boolean_set_operations_2 on Polygon_set_2 with the exact-constructions kernel (Epeck):
// exact arithmetic throughout, so its answers are exact up to the final rounding to double.
// Valid polygons with holes only. The second CGAL translation unit of the project.
#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <cmath>

#include "ghclip/polygons_with_holes.h"
#include "ghpeers/peer.h"

namespace gh::peers {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using CPolygon = CGAL::Polygon_2<Kernel>;
using CPolygonWithHoles = CGAL::Polygon_with_holes_2<Kernel>;
using CPolygonSet = CGAL::Polygon_set_2<Kernel>;

struct CgalOperand : Prepared {
  CPolygonSet set;
};

CPolygon toCgal(const Ring& ring) {
  CPolygon poly;
  for (const Point& p : ring) poly.push_back(Kernel::Point_2(p.x, p.y));
  return poly;
}

Ring toRing(const CPolygon& poly) {
  Ring ring;
  for (auto v = poly.vertices_begin(); v != poly.vertices_end(); ++v) {
    ring.push_back({CGAL::to_double(v->x()), CGAL::to_double(v->y())});
  }
  return ring;
}

class Cgal : public Peer {
 public:
  std::string_view name() const override { return "cgal"; }
  std::string_view description() const override { return "CGAL 5.5 Boolean_set_operations_2 (Epeck, exact)"; }
  std::string_view accepts() const override { return "valid simple polygons with holes"; }
  bool validInputOnly() const override { return true; }

  std::unique_ptr<Prepared> prepare(const Region& region) const override {
    // CGAL 5.5's line intersection trusts an interval filter whose degree-3 numerators overflow
    // to infinity near 2^341 and then dereferences an empty result (a segmentation fault; the
    // oracle works around it in robust_segment_traits.h). Refused well before that.
    for (const Ring& ring : region) {
      for (const Point& p : ring) {
        if (std::abs(p.x) > 0x1p300 || std::abs(p.y) > 0x1p300) {
          throw PeerRefusal("cgal refuses: a coordinate above 2^300 (about 2e90) would overflow CGAL 5.5's interval "
                            "filter in segment intersections and crash it");
        }
      }
    }
    const PolygonsWithHoles pwh = toPolygonsWithHoles(region);
    if (pwh.refusal) throw PeerRefusal("cgal refuses: " + *pwh.refusal);
    auto out = std::make_unique<CgalOperand>();
    std::vector<CPolygonWithHoles> polys;
    for (const PolygonWithHoles& p : pwh.polygons) {
      std::vector<CPolygon> holes;
      for (const Ring& h : p.holes) holes.push_back(toCgal(h));
      polys.emplace_back(toCgal(p.shell), holes.begin(), holes.end());
    }
    // Disjoint polygons with holes: insert them all at once.
    out->set.insert(polys.begin(), polys.end());
    return out;
  }

  Region run(const Prepared& subject, const Prepared& clip, Op op) const override {
    const CPolygonSet& s = static_cast<const CgalOperand&>(subject).set;
    const CPolygonSet& c = static_cast<const CgalOperand&>(clip).set;
    CPolygonSet result = op == Op::ReverseDifference ? c : s;
    switch (op) {
      case Op::Intersection: result.intersection(c); break;
      case Op::Union: result.join(c); break;
      case Op::Difference: result.difference(c); break;
      case Op::ReverseDifference: result.difference(s); break;
      case Op::Xor: result.symmetric_difference(c); break;
    }
    std::vector<CPolygonWithHoles> polys;
    result.polygons_with_holes(std::back_inserter(polys));
    Region out;
    for (const CPolygonWithHoles& p : polys) {
      if (!p.is_unbounded()) out.push_back(toRing(p.outer_boundary()));
      for (auto h = p.holes_begin(); h != p.holes_end(); ++h) out.push_back(toRing(*h));
    }
    return out;
  }
};

}  // namespace

const Peer& cgalPeer() {
  static const Cgal peer;
  return peer;
}

}  // namespace gh::peers
