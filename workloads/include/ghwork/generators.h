// Workload generators, deterministic by seed, shared by tests, fuzzers and experiments.
#pragma once

#include <cstdint>

#include "ghclip/region.h"

namespace gh::work {

// The paper's workload (Section 6): n vertices uniform in the unit square, joined in order.
// Two such n-gons cross about 0.23 n^2 times.
Ring randomRing(std::size_t n, std::uint64_t seed);

// Vertices on the integer grid 0..gridSize, joined in order: shared vertices, vertex-on-edge and
// collinear overlaps are frequent.
Ring gridRing(std::size_t n, int gridSize, std::uint64_t seed);

}  // namespace gh::work
