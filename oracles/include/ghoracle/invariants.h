// Cheap invariants any answer must satisfy, callable by anyone (fuzzers call them on every
// input): finite coordinates, no zero-length edges, and the area inequalities of the operation
// (intersection no larger than either operand, union no smaller, differences no larger than
// their minuend, xor no larger than the sum), with slack for rounding.
#pragma once

#include <string>
#include <vector>

#include "ghclip/operation.h"
#include "ghclip/region.h"

namespace gh::oracle {

// One message per violated invariant; empty when all hold.
std::vector<std::string> invariantViolations(const Region& subject, const Region& clip, Op op,
                                             const Region& result);

// Several answers for one S and C (the five operations) checked with the operands' areas
// measured once. Each check gives what invariantViolations gives for the same arguments.
class InvariantJudge {
 public:
  InvariantJudge(const Region& subject, const Region& clip);
  std::vector<std::string> violations(Op op, const Region& result) const;

 private:
  Region subject_, clip_;              // as given
  int k_;                              // the judging exponent of S and C alone
  Region scaledSubject_, scaledClip_;  // at that scale (when k_ is not 0)
  double subjectArea_, clipArea_;      // at that scale
};

}  // namespace gh::oracle
