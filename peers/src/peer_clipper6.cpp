// Clipper 6.4.2 (Angus Johnson; Debian libpolyclipping): Vatti's algorithm, the paper's comparator.
//
// Clipper works on 64-bit integers. Doubles are scaled by s = 2^(61 - e), where 2^e is the
// smallest power of two above the largest |coordinate| of both operands, and rounded to the
// nearest integer; s is a power of two, so scaling is exact and only the rounding moves points:
// by at most 2^(e-62) per coordinate, about 1/1000 of an ulp of the largest coordinate for inputs
// that use their full double precision. Intersection points are rounded to integers by Clipper
// likewise. |values| < 2^62 = Clipper's hiRange, so Clipper uses its 128-bit products (slower than
// its 32-bit range, but a 32-bit grid would round inputs by ~1e-9 relative: gross errors to the
// exact oracle). Both operands use the even-odd fill rule, as our regions do.
#include <polyclipping/clipper.hpp>

#include <cmath>

#include "ghpeers/peer.h"

namespace gh::peers {
namespace {

struct ClipperOperand : Prepared {
  Region region;  // scaling needs both operands, so conversion happens in run()
};

class Clipper6 : public Peer {
 public:
  std::string_view name() const override { return "clipper6"; }
  std::string_view description() const override { return "Clipper 6.4.2 (Vatti), even-odd fill, 2^62 integer grid"; }
  std::string_view accepts() const override { return "any rings (self-intersecting too)"; }
  bool validInputOnly() const override { return false; }

  std::unique_ptr<Prepared> prepare(const Region& region) const override {
    auto p = std::make_unique<ClipperOperand>();
    p->region = region;
    return p;
  }

  Region run(const Prepared& subject, const Prepared& clip, Op op) const override {
    const Region& s = static_cast<const ClipperOperand&>(subject).region;
    const Region& c = static_cast<const ClipperOperand&>(clip).region;
    double m = 0;
    for (const Region* r : {&s, &c}) {
      for (const Ring& ring : *r) {
        for (const Point& p : ring) m = std::max({m, std::abs(p.x), std::abs(p.y)});
      }
    }
    const int e = m > 0 ? std::ilogb(m) + 1 : 0;
    // ldexp per coordinate, not a product with 2^(61 - e): that factor overflows for coordinates
    // below ~2^-962 (and its inverse underflows for huge ones).
    auto toPaths = [e](const Region& r) {
      ClipperLib::Paths paths(r.size());
      for (std::size_t i = 0; i < r.size(); ++i) {
        paths[i].reserve(r[i].size());
        for (const Point& p : r[i]) {
          paths[i].emplace_back(static_cast<ClipperLib::cInt>(std::llround(std::ldexp(p.x, 61 - e))),
                                static_cast<ClipperLib::cInt>(std::llround(std::ldexp(p.y, 61 - e))));
        }
      }
      return paths;
    };
    ClipperLib::Clipper clipper;
    ClipperLib::Paths solution;
    auto execute = [&](ClipperLib::ClipType type, const Region& a, const Region& b) {
      clipper.Clear();
      clipper.AddPaths(toPaths(a), ClipperLib::ptSubject, true);
      clipper.AddPaths(toPaths(b), ClipperLib::ptClip, true);
      ClipperLib::Paths out;
      // Clipper 6.4.2 reports failure when it has no edges at all; op(empty, empty) is empty.
      if (a.empty() && b.empty()) return out;
      if (!clipper.Execute(type, out, ClipperLib::pftEvenOdd, ClipperLib::pftEvenOdd)) {
        throw ClipFailure("Clipper 6.4.2 reported failure");
      }
      return out;
    };
    switch (op) {
      case Op::Intersection: solution = execute(ClipperLib::ctIntersection, s, c); break;
      case Op::Union: solution = execute(ClipperLib::ctUnion, s, c); break;
      case Op::Difference: solution = execute(ClipperLib::ctDifference, s, c); break;
      case Op::ReverseDifference: solution = execute(ClipperLib::ctDifference, c, s); break;
      case Op::Xor: solution = execute(ClipperLib::ctXor, s, c); break;
    }
    Region out;
    out.reserve(solution.size());
    for (const auto& path : solution) {
      Ring ring;
      ring.reserve(path.size());
      for (const auto& q : path) {
        ring.push_back({std::ldexp(static_cast<double>(q.X), e - 61), std::ldexp(static_cast<double>(q.Y), e - 61)});
      }
      out.push_back(std::move(ring));
    }
    return out;
  }
};

}  // namespace

const Peer& clipper6Peer() {
  static const Clipper6 peer;
  return peer;
}

}  // namespace gh::peers
