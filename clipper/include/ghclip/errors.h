// The two ways a clip can fail: the input is bad, or the algorithm could not finish.
#pragma once

#include <stdexcept>
#include <string>

namespace gh {

// Bad input: non-finite or too large coordinates, rings with fewer than 3 distinct vertices.
// The message names the ring and vertex.
class InvalidInput : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// The algorithm gave up on a valid input: degeneracies that perturbation did not resolve,
// or a trace that did not close within its bound (inconsistent floating-point decisions).
// Only the floating-point variants can throw it; each occurrence is a finding about them.
class ClipFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace gh
