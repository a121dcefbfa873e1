// RapidCheck generators of property inputs, one per workload family. Inputs are valid by
// construction (every ring gets 3 distinct vertices), so shrinking never leaves the domain.
//   random  rings of 3..12 vertices at dyadic coordinates k / 2^20 in [0, 1]: in general
//           position in practice, and exact under dyadic translation and power-of-two scaling
//   grid    rings of 3..10 vertices on the integer grid 0..8: degenerate contacts everywhere
//   family  the named degenerate families of the workloads library
//   bitset  unions of unit cells of a k x k bitset, k = 2..5
#pragma once

#include <rapidcheck.h>

#include <algorithm>
#include <string>
#include <vector>

#include "ghwork/generators.h"
#include "property_case.h"

namespace gh::props {

// Drops consecutive repeats, then appends points until the ring has 3 distinct vertices.
inline Ring withThreeDistinct(Ring input, double unit) {
  Ring ring;
  for (const Point& p : input) {
    if (ring.empty() || ring.back() != p) ring.push_back(p);
  }
  std::vector<Point> extra{{0, 0}, {unit, 0}, {0, unit}};
  for (const Point& p : extra) {
    std::vector<std::pair<double, double>> d;
    for (const Point& q : ring) d.emplace_back(q.x, q.y);
    std::sort(d.begin(), d.end());
    if (std::unique(d.begin(), d.end()) - d.begin() >= 3) break;
    if (ring.empty() || ring.back() != p) ring.push_back(p);
  }
  while (ring.size() > 1 && ring.back() == ring.front()) ring.pop_back();
  return ring;
}

inline rc::Gen<Ring> ringOf(rc::Gen<Point> point, int minSize, int maxSize, double unit) {
  return rc::gen::map(
      rc::gen::mapcat(rc::gen::inRange(minSize, maxSize + 1),
                      [point](int n) { return rc::gen::container<std::vector<Point>>(n, point); }),
      [unit](std::vector<Point> pts) { return withThreeDistinct(std::move(pts), unit); });
}

// Coordinates are drawn at full size: RapidCheck scales ranges with its size parameter, which
// would make the first cases all zeros (degenerate) instead of the paper's general position.
inline rc::Gen<int> fullRange(int lo, int hi) { return rc::gen::resize(rc::kNominalSize, rc::gen::inRange(lo, hi)); }

inline rc::Gen<Point> dyadicPoint() {
  return rc::gen::map(rc::gen::pair(fullRange(0, (1 << 20) + 1), fullRange(0, (1 << 20) + 1)),
                      [](std::pair<int, int> p) {
                        return Point{std::ldexp(p.first, -20), std::ldexp(p.second, -20)};
                      });
}

inline rc::Gen<Point> gridPoint() {
  return rc::gen::map(rc::gen::pair(fullRange(0, 9), fullRange(0, 9)),
                      [](std::pair<int, int> p) { return Point{double(p.first), double(p.second)}; });
}

inline rc::Gen<Op> anyOp() {
  return rc::gen::element(Op::Intersection, Op::Union, Op::Difference, Op::ReverseDifference,
                          Op::Xor);
}

inline rc::Gen<PropertyCase> casesOf(rc::Gen<Ring> ring) {
  return rc::gen::map(rc::gen::tuple(ring, ring, anyOp()), [](std::tuple<Ring, Ring, Op> t) {
    return PropertyCase{{std::get<0>(t)}, {std::get<1>(t)}, std::get<2>(t)};
  });
}

inline rc::Gen<PropertyCase> randomCase() { return casesOf(ringOf(dyadicPoint(), 3, 12, 1)); }
inline rc::Gen<PropertyCase> gridCase() { return casesOf(ringOf(gridPoint(), 3, 10, 1)); }

inline rc::Gen<PropertyCase> familyCase() {
  return rc::gen::map(
      rc::gen::tuple(rc::gen::element<std::string>("identical", "shared-edge", "touching-vertex",
                                                   "nested-touching", "sliver", "sub-boundary"),
                     rc::gen::inRange(3, 9), rc::gen::inRange(0, 1000), anyOp()),
      [](std::tuple<std::string, int, int, Op> t) {
        const auto w = work::generate(std::get<0>(t), static_cast<std::size_t>(std::get<1>(t)),
                                      static_cast<std::uint64_t>(std::get<2>(t)));
        return PropertyCase{w.subject, w.clip, std::get<3>(t)};
      });
}

// Bitset cases carry their bitsets so the exact answer is known without any oracle.
struct BitsetCase {
  work::BitsetGrid grid;
  Op op = Op::Intersection;
  PropertyCase asCase() const {
    return {work::cellsRegion(grid, grid.subject), work::cellsRegion(grid, grid.clip), op};
  }
};

inline void showValue(const BitsetCase& c, std::ostream& os) { showValue(c.asCase(), os); }

inline rc::Gen<BitsetCase> bitsetCase() {
  return rc::gen::mapcat(rc::gen::inRange(2, 6), [](int k) {
    const auto cells = static_cast<std::size_t>(k * k);
    return rc::gen::map(
        rc::gen::tuple(rc::gen::container<std::vector<bool>>(cells, rc::gen::arbitrary<bool>()),
                       rc::gen::container<std::vector<bool>>(cells, rc::gen::arbitrary<bool>()),
                       anyOp()),
        [k](std::tuple<std::vector<bool>, std::vector<bool>, Op> t) {
          BitsetCase c;
          c.grid.size = k;
          c.grid.subject = std::get<0>(t);
          c.grid.clip = std::get<1>(t);
          c.op = std::get<2>(t);
          return c;
        });
  });
}

}  // namespace gh::props
