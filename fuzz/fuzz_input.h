// Bytes -> two regions, shared by the clip fuzz targets. One consume per statement.
//   mode 0: small integer-grid coordinates (0..8): shared vertices, vertex-on-edge, overlaps
//   mode 1: raw doubles (any bit pattern: NaN, infinities, huge and tiny values included)
//   mode 2: doubles near the grid (grid points moved by a few ulps or by 2^-k)
#pragma once

#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstdint>

#include "ghclip/region.h"
#include "new_problem_mutator.h"

namespace gh::fuzz {

inline double coordinate(FuzzedDataProvider& in, int mode) {
  if (mode == 0) return static_cast<double>(in.ConsumeIntegralInRange<int>(0, 8));
  if (mode == 1) return in.ConsumeFloatingPoint<double>();
  const double base = static_cast<double>(in.ConsumeIntegralInRange<int>(0, 8));
  const int kind = in.ConsumeIntegralInRange<int>(0, 2);
  if (kind == 0) return base;
  if (kind == 1) {
    double x = base;
    const int ulps = in.ConsumeIntegralInRange<int>(-3, 3);
    for (int k = 0; k < std::abs(ulps); ++k) x = std::nextafter(x, ulps > 0 ? 9.0 : -1.0);
    return x;
  }
  return base + std::ldexp(1.0, -in.ConsumeIntegralInRange<int>(1, 60));
}

inline Region region(FuzzedDataProvider& in, int mode, int maxRings, int maxVertices) {
  Region r;
  const int rings = in.ConsumeIntegralInRange<int>(0, maxRings);
  for (int k = 0; k < rings; ++k) {
    Ring ring;
    const int n = in.ConsumeIntegralInRange<int>(3, maxVertices);
    for (int v = 0; v < n; ++v) {
      const double x = coordinate(in, mode);
      const double y = coordinate(in, mode);
      ring.push_back({x, y});
    }
    r.push_back(std::move(ring));
  }
  return r;
}

struct Pair {
  int mode = 0;
  Region subject, clip;
};

inline Pair pair(const std::uint8_t* data, std::size_t size, int maxRings, int maxVertices) {
  FuzzedDataProvider in(data, size);
  Pair p;
  p.mode = in.ConsumeIntegralInRange<int>(0, 2);
  p.subject = region(in, p.mode, maxRings, maxVertices);
  p.clip = region(in, p.mode, maxRings, maxVertices);
  return p;
}

inline ProblemKey keyOf(const Pair& p) { return ProblemKey().add(p.mode).add(p.subject).add(p.clip); }

}  // namespace gh::fuzz
