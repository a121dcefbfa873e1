// What the exact predicates and constructions could not decide with the floating-point filter:
// the context every exact computation is given, so that a clip reports its own fallbacks (phase
// 1, phase 2 and clean-up alike) and threads never share a counter.
#pragma once

#include <cstdint>

namespace gh::detail {

struct ExactCounters {
  std::uint64_t filterFailures = 0;      // predicates decided in GMP integers (integer_stage.h)
  std::uint64_t expansionDecisions = 0;  // predicates past the filter, decided exactly in doubles
  std::uint64_t exactConstructions = 0;  // crossing points rounded from rationals

  ExactCounters& operator+=(const ExactCounters& o) {
    filterFailures += o.filterFailures, expansionDecisions += o.expansionDecisions;
    exactConstructions += o.exactConstructions;
    return *this;
  }
};

}  // namespace gh::detail
