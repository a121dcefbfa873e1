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

}  // namespace gh::oracle
