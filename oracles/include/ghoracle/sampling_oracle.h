// The sampling oracle: cheap, CGAL-free, good enough to call inside a fuzzer.
//
// Points are drawn (seeded) uniformly in the joint bounding box of S and C, where every
// operation's answer lies (an answer reaching beyond it gets as many more drawn over the box of S,
// C and R, of which those outside S and C's box are judged), and around every vertex of S, C and
// R in eight directions (from a phase fixed by the vertex and the seed, so a vertex shared by S
// and R is sampled at the same points) plus both ways along the corner's bisector, at radii both
// global (extent of S and C's box * 2^-8, 2^-14, 2^-20, 2^-26) and local (the vertex's shorter
// edge times 2^-2, 2^-5, 2^-10, 2^-20; a corner's within a factor 2 of a smaller corner's at the
// same vertex, that one's), so that a small feature next to a large one, or a thin spike, is
// sampled at its own size. Each point's sides of S, C and R are decided exactly:
// even-odd ray tests with an exact orientation, except that near a vertex, where the answer's
// only edges are rays from the vertex, one ray test decides R's side for the points there and the
// exact order of their directions among the rays the rest. Points that cannot change a verdict
// are left out: around a vertex, the smaller radii inside its clearance, and a point that the
// segment from a point judged farther out in its direction joins without meeting an edge (one
// face). At the one radius kept inside the clearance, where only the edges through the vertex
// cut, every sector between them is judged at its angular middle (a thin sector no direction
// falls in included), and a direction's point only where its sector's middle was not judged.
// Where a radius is kept so, only the smallest radius outside the clearance is sampled too, in
// the sectors' middle directions and both ways along the bisector: the larger radii reach the
// neighbourhoods of other vertices, which are sampled there. A vertex too near another edge for
// any radius to be kept gets every radius, but beyond the disk where only the edges nearest it
// cut, the eight directions at the smallest only and its bisector at the others. Each corner's
// bisector is sampled at that corner's radii alone.
//
// Where a correct answer may legitimately disagree: within the rounding zones (exact_oracle.h),
// which lie along the lines of S and C. A point is skipped when it is within
// delta = (2 * constructionUlps + 6) ulps of the magnitude of an edge's largest crossing of that
// edge of S or C; points exactly on an edge of R are skipped too. So a unit square crossed by a
// 1e15-long edge is judged at the unit square's resolution. Where it is still blind: a wrong
// feature thinner than that delta lying along an edge of S or C (wider than the exact oracle's
// zone where one edge has crossings of very different magnitudes: the delta is the largest
// one's), and any feature no sample lands in (the samples near vertices find small features at
// vertices, not in the middle of long edges). The exact oracle has neither blind spot.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "ghclip/operation.h"
#include "ghclip/region.h"

namespace gh::oracle {

struct SampleOptions {
  std::uint64_t seed = 1;
  std::size_t uniformPoints = 2000;
  bool nearVertices = true;
  int constructionUlps = 1;  // as in ExactOptions
  // Judge no more once every answer has a mismatch, and give an answer with one no points of its
  // own beyond S and C's box: each verdict's pass() and firstMismatch are then the full check's,
  // its counts those up to where it stopped. For callers that read pass() alone (the fuzz
  // targets, where most of the naive and sweep variants' inputs have every answer wrong).
  bool stopWhenAllFail = false;
};

struct SampleVerdict {
  std::size_t checked = 0;     // points tested
  std::size_t skipped = 0;     // within an edge's delta of an edge of S or C, or on an edge of R
  std::size_t mismatched = 0;  // inside(R) != op(inside(S), inside(C))
  std::optional<Point> firstMismatch;
  double delta = 0;            // the largest local delta met (most are far smaller); by a
                               // SamplingJudge, over all its checks so far
  double seconds = 0;
  bool pass() const { return mismatched == 0; }
};

SampleVerdict sampleCheck(const Region& subject, const Region& clip, Op op, const Region& result,
                          const SampleOptions& options = {});

// Several answers for one S and C (the five operations, or several clippers' answers) judged
// with the work that does not depend on the answer done once: the uniform points and the points
// around the vertices of S and C, their distance to the edges of S and C, and their sides of S
// and C. Each check gives the verdict sampleCheck gives for the same arguments.
class SamplingJudge {
 public:
  SamplingJudge(const Region& subject, const Region& clip, const SampleOptions& options = {});
  ~SamplingJudge();
  SamplingJudge(const SamplingJudge&) = delete;
  SamplingJudge& operator=(const SamplingJudge&) = delete;
  SampleVerdict check(Op op, const Region& result);
  // Several answers (op, answer) at once: each is judged at every point check(op, answer) judges,
  // or at a point of the same face of the arrangement of S, C and all these answers, and also at
  // the points of the others (around their vertices too), with each point's sides of S and C, and
  // the clearances around each vertex, found once for all. So a mismatch check() finds is found
  // here too, and more may be; the fuzz targets judge their five answers so.
  std::vector<SampleVerdict> check(const std::vector<std::pair<Op, const Region*>>& answers);

 private:
  struct Shared;
  SampleOptions options_;
  std::unique_ptr<Shared> shared_;
};

}  // namespace gh::oracle
