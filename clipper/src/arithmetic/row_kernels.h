// Phase 1's all-pairs rows, vectorized: one subject edge against four clip edges at a time (AVX2,
// chosen at run time; the scalar loop elsewhere). Each lane computes exactly what the scalar code
// computes, operation for operation (the library is compiled without contraction into fma), so
// answers are the same bit for bit; lanes that need more than the common case (a degenerate
// contact, an uncertain sign) are handed to the scalar test.
#pragma once

#include <cstdint>
#include <vector>

#include "operand.h"

namespace gh::detail {

// The clip's edges as arrays of coordinates: edge e from (x1[e], y1[e]) to (x2[e], y2[e]).
struct EdgeArrays {
  std::vector<double> x1, y1, x2, y2;
  EdgeArrays() = default;
  explicit EdgeArrays(const Operand& op);
  std::size_t size() const { return x1.size(); }
};

// Whether this processor runs the vectorized kernels.
bool rowKernelsAvailable();

// The paper's intersect() of p1p2 against clip edges [0, m): calls crossing(ce, alphaS, alphaC,
// x, y) for every proper crossing and special(ce) for every pair the scalar test must decide
// (degenerate contacts); other pairs do not meet. Requires rowKernelsAvailable().
void paperRow(double p1x, double p1y, double p2x, double p2y, const EdgeArrays& clip,
              void (*crossing)(void*, std::uint32_t, double, double, double, double), void (*special)(void*, std::uint32_t),
              void* context);

// The exact arithmetic's first look at p1p2 against clip edges [0, m): calls candidate(ce) for
// every pair it cannot reject (boxes apart by its tie rules, or both endpoints of one edge
// certainly on one side of the other's line); those go to the exact test.
void exactRowCandidates(double p1x, double p1y, double p2x, double p2y, const EdgeArrays& clip,
                        void (*candidate)(void*, std::uint32_t), void* context);

}  // namespace gh::detail
