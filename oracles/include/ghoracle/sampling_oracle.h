// The sampling oracle: cheap, CGAL-free, good enough to call inside a fuzzer.
//
// Points are drawn (seeded) uniformly in the joint bounding box of S, C and R, and around every
// vertex of S, C and R at radii extent * 2^-8, 2^-14, 2^-20, 2^-26 in eight directions (points
// near vertices catch moved vertices and slivers that uniform points miss). Each point gets
// three even-odd crossing tests; a point within delta = extent * 2^-32 + M * 2^-44 of any edge of
// S, C or R (M the largest |coordinate|, about 100 ulps of it) is skipped, since there a correct
// answer's rounding, or the tests' own, may legitimately disagree.
#pragma once

#include <cstdint>
#include <optional>

#include "ghclip/operation.h"
#include "ghclip/region.h"

namespace gh::oracle {

struct SampleOptions {
  std::uint64_t seed = 1;
  std::size_t uniformPoints = 2000;
  bool nearVertices = true;
};

struct SampleVerdict {
  std::size_t checked = 0;     // points tested
  std::size_t skipped = 0;     // within delta of an edge
  std::size_t mismatched = 0;  // inside(R) != op(inside(S), inside(C))
  std::optional<Point> firstMismatch;
  double delta = 0;
  double seconds = 0;
  bool pass() const { return mismatched == 0; }
};

// Even-odd crossing parity and distance to the nearest edge, in one pass over the edges.
SampleVerdict sampleCheck(const Region& subject, const Region& clip, Op op, const Region& result,
                          const SampleOptions& options = {});

}  // namespace gh::oracle
