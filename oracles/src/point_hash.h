// Hashing points by their exact coordinates (for sets of input vertices).
#pragma once

#include <cstdint>
#include <cstring>
#include <functional>

#include "ghclip/region.h"
#include "ghoracle/mix_bits.h"

namespace gh::oracle {

// A point's hash by its exact coordinates (-0 as 0: they are equal points), every bit of each
// coordinate moving every bit of the hash (mix_bits.h): a coordinate with a short significand (a
// small integer, a dyadic fraction) has all its low bits zero.
inline std::uint64_t mixedPointHash(Point p) {
  const double x = p.x + 0.0, y = p.y + 0.0;
  std::uint64_t bx, by;
  std::memcpy(&bx, &x, sizeof bx), std::memcpy(&by, &y, sizeof by);
  return mixBits(mixBits(bx) + by);
}

struct PointHash {
  std::size_t operator()(const Point& p) const {
    return std::hash<double>()(p.x) * 31 + std::hash<double>()(p.y);
  }
};

}  // namespace gh::oracle
