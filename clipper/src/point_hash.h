// Hashing points by their exact coordinates, for the open-addressing tables of the clean-up.
// Tables index by the low bits of the hash, and the low bits of a double's pattern are zero for
// every coordinate with a short significand (small integers, dyadic fractions: the grids that
// degenerate inputs live on), so each coordinate's bits go through a full avalanche (splitmix64's
// finalizer) before they are combined. A multiply-and-shift that left them zero put all 81 points
// of a 9 x 9 integer grid into one slot, and the tables went quadratic.
#pragma once

#include <cstdint>
#include <cstring>

#include "ghclip/region.h"

namespace gh::detail {

// Equal points hash alike: -0.0 and 0.0 compare equal, so both hash as 0.0.
struct PointHash {
  static std::uint64_t mix(std::uint64_t h) {
    h = (h ^ (h >> 30)) * 0xBF58476D1CE4E5B9ull;
    h = (h ^ (h >> 27)) * 0x94D049BB133111EBull;
    return h ^ (h >> 31);
  }
  std::size_t operator()(const Point& p) const {
    const double px = p.x + 0.0, py = p.y + 0.0;
    std::uint64_t x, y;
    std::memcpy(&x, &px, 8), std::memcpy(&y, &py, 8);
    return static_cast<std::size_t>(mix(mix(x) + y));
  }
};

}  // namespace gh::detail
