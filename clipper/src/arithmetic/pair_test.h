// The verdict of an arithmetic policy on one (subject edge, clip edge) pair: two bytes. The
// crossing itself, when there is one, is written by the policy into the caller's record.
#pragma once

#include <cstdint>

namespace gh::detail {

struct PairTest {
  enum class Kind : std::uint8_t {
    None,        // the edges do not meet
    Crossing,    // a proper crossing, written to the caller's Crossing
    Degenerate,  // they touch or overlap (paper arithmetic only): the vertices in `onOtherEdge`
                 // lie on the other operand's edge
  };
  // Bits of `onOtherEdge`: which endpoints lie on the other operand's edge.
  static constexpr std::uint8_t kSubjectFrom = 1, kSubjectTo = 2, kClipFrom = 4, kClipTo = 8;

  Kind kind = Kind::None;
  std::uint8_t onOtherEdge = 0;
};

}  // namespace gh::detail
