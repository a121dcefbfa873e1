// The verdict of an arithmetic policy on one (subject edge, clip edge) pair.
#pragma once

#include <cstdint>

#include "phase1_result.h"

namespace gh::detail {

struct PairTest {
  enum class Kind : std::uint8_t {
    None,        // the edges do not meet
    Crossing,    // a proper crossing, in `crossing`
    Degenerate,  // they touch or overlap (paper arithmetic only): the vertices in `onOtherEdge`
                 // lie on the other operand's edge
  };
  // Bits of `onOtherEdge`: which endpoints lie on the other operand's edge.
  static constexpr std::uint8_t kSubjectFrom = 1, kSubjectTo = 2, kClipFrom = 4, kClipTo = 8;

  Kind kind = Kind::None;
  std::uint8_t onOtherEdge = 0;
  Crossing crossing;
};

}  // namespace gh::detail
