// What one clip did: counts and time per phase.
#pragma once

#include <cstdint>

namespace gh {

struct Stats {
  std::uint64_t subjectVertices = 0;  // after normalisation
  std::uint64_t clipVertices = 0;
  std::uint64_t candidatePairs = 0;   // edge pairs handed to the intersection test
  std::uint64_t intersections = 0;    // crossings inserted into both vertex lists
  std::uint64_t perturbations = 0;    // vertices moved (paper arithmetic) to break degeneracies
  std::uint64_t perturbationRounds = 0;  // phase-1 restarts after perturbing
  std::uint64_t filterFailures = 0;   // exact predicates that needed rationals (any phase, clean-up too)
  std::uint64_t expansionDecisions = 0;  // ...that the filter could not decide, decided exactly in doubles
  std::uint64_t exactConstructions = 0;  // crossing points the exact arithmetic rounded from rationals
  std::uint64_t outputRings = 0;
  std::uint64_t outputVertices = 0;
  double phase1Seconds = 0;  // crossings found and ordered (including perturbation rounds)
  double phase2Seconds = 0;  // vertex graph built, ring starts located, entry/exit marked
  double phase3Seconds = 0;  // tracing and output clean-up
};

}  // namespace gh
