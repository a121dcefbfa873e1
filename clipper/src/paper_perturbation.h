// The paper's answer to degenerate input (Section 5, Figure 12), as a wrapper around phase 1, the
// way GEOS's OverlayNGRobust wraps its overlay: run phase 1; if the paper arithmetic found vertices
// on the other operand's edges, move them by a tiny vector and run phase 1 again, until none is
// left or kMaxPerturbationRounds is reached (then ClipFailure). Phase 1 itself knows nothing of
// it, and the exact arithmetic never needs it: under Simulation of Simplicity there is no
// degeneracy to resolve.
#pragma once

#include <string>

#include "arithmetic/paper_arithmetic.h"
#include "ghclip/errors.h"
#include "phase1_intersections.h"

namespace gh::detail {

inline constexpr int kMaxPerturbationRounds = 32;

// Relative size of a perturbation: |move| = kPerturbationScale * max |coordinate| of both
// operands. About 2^10 ulps of the largest coordinate, so the moved vertex is clearly off the
// line in double arithmetic, and still far below a pixel at any sensible scale.
inline constexpr double kPerturbationScale = 0x1p-42;

// Moves the flagged vertices of one operand (the clip's when any are flagged, else the
// subject's) by one common vector of length kPerturbationScale * scale; the direction turns by
// the golden angle each round so that a vertex moved twice does not walk back onto a line.
// Returns how many vertices moved.
std::size_t perturb(Operand& subject, Operand& clip, const Degeneracies& degeneracies, int round);

template <class Search>
Phase1Result findIntersectionsPerturbed(Operand subject, Operand clip, const Search& search,
                                        const PaperArithmetic& arithmetic, Stats& stats, unsigned threads = 1) {
  for (int round = 0;; ++round) {
    Degeneracies degeneracies;
    Phase1Result r =
        findIntersections(std::move(subject), std::move(clip), search, arithmetic, stats, &degeneracies, threads);
    if (degeneracies.empty()) return r;
    if (round + 1 >= kMaxPerturbationRounds) {
      throw ClipFailure("degeneracies remain after " + std::to_string(kMaxPerturbationRounds) +
                        " rounds of perturbation");
    }
    stats.perturbations += perturb(r.subject, r.clip, degeneracies, round);
    ++stats.perturbationRounds;
    subject = std::move(r.subject);
    clip = std::move(r.clip);
  }
}

}  // namespace gh::detail
