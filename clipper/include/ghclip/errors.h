// The two ways a clip can fail: the input is bad, or the algorithm could not finish.
#pragma once

#include <stdexcept>
#include <string>

namespace gh {

// Bad input: non-finite or too large coordinates, rings with fewer than 3 distinct vertices.
// The message names the ring and vertex; from gh::clip also the operand ("subject: ring 2, ..."),
// which operand() and problem() give apart so that a tool can name the file instead.
class InvalidInput : public std::invalid_argument {
 public:
  explicit InvalidInput(const std::string& problem) : std::invalid_argument(problem), problem_(problem) {}
  InvalidInput(const std::string& operand, const std::string& problem)
      : std::invalid_argument(operand + ": " + problem), operand_(operand), problem_(problem) {}
  // "subject" or "clip" when a clip refused one of its operands, else empty.
  const std::string& operand() const { return operand_; }
  // The message without the operand.
  const std::string& problem() const { return problem_; }

 private:
  std::string operand_, problem_;
};

// The algorithm gave up on a valid input: degeneracies that perturbation did not resolve,
// or a trace that did not close within its bound (inconsistent floating-point decisions).
// Only the floating-point variants can throw it; each occurrence is a finding about them.
class ClipFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace gh
