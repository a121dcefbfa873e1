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

// Reads a region into `into`, reusing the storage of its rings.
inline void readRegion(FuzzedDataProvider& in, int mode, int maxRings, int maxVertices, Region& into) {
  const int rings = in.ConsumeIntegralInRange<int>(0, maxRings);
  into.resize(static_cast<std::size_t>(rings));
  for (Ring& ring : into) {
    ring.clear();
    const int n = in.ConsumeIntegralInRange<int>(3, maxVertices);
    ring.reserve(static_cast<std::size_t>(n));
    for (int v = 0; v < n; ++v) {
      const double x = coordinate(in, mode);
      const double y = coordinate(in, mode);
      ring.push_back({x, y});
    }
  }
}

struct Pair {
  int mode = 0;
  Region subject, clip;
};

inline void readPair(const std::uint8_t* data, std::size_t size, int maxRings, int maxVertices, Pair& into) {
  FuzzedDataProvider in(data, size);
  into.mode = in.ConsumeIntegralInRange<int>(0, 2);
  readRegion(in, into.mode, maxRings, maxVertices, into.subject);
  readRegion(in, into.mode, maxRings, maxVertices, into.clip);
}

inline Pair pair(const std::uint8_t* data, std::size_t size, int maxRings, int maxVertices) {
  Pair p;
  readPair(data, size, maxRings, maxVertices, p);
  return p;
}

inline ProblemKey keyOf(const Pair& p) { return ProblemKey().add(p.mode).add(p.subject).add(p.clip); }

// The key of the problem the bytes decode to, for the mutator, which decodes every mutation it
// makes (and its parent): into storage this thread keeps from one call to the next, as fresh
// rings for every decode were a third of its cost under ASan (perf, fuzz_clip_naive).
inline ProblemKey problemKey(const std::uint8_t* data, std::size_t size, int maxRings, int maxVertices) {
  thread_local Pair scratch;
  readPair(data, size, maxRings, maxVertices, scratch);
  return keyOf(scratch);
}

}  // namespace gh::fuzz
