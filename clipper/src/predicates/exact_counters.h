// What the exact predicates and constructions had to compute in rational arithmetic: the context
// every exact computation is given, so that a clip reports its own fallbacks (phase 1, phase 2
// and clean-up alike) and threads never share a counter.
#pragma once

#include <cstdint>

namespace gh::detail {

struct ExactCounters {
  std::uint64_t filterFailures = 0;      // predicates the floating-point filter could not decide
  std::uint64_t exactConstructions = 0;  // crossing points rounded from rationals
};

}  // namespace gh::detail
