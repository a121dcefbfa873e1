// The Boolean operations, with their command-line names.
#pragma once

#include <optional>
#include <string_view>

namespace gh {

enum class Op {
  Intersection,       // S ∩ C
  Union,              // S ∪ C
  Difference,         // S \ C
  ReverseDifference,  // C \ S
  Xor,                // (S \ C) ∪ (C \ S)
};

inline constexpr Op kAllOps[] = {Op::Intersection, Op::Union, Op::Difference,
                                 Op::ReverseDifference, Op::Xor};

std::string_view name(Op op);
std::optional<Op> parseOp(std::string_view text);

// The truth table of an operation on "inside subject" and "inside clip".
constexpr bool apply(Op op, bool inSubject, bool inClip) {
  switch (op) {
    case Op::Intersection: return inSubject && inClip;
    case Op::Union: return inSubject || inClip;
    case Op::Difference: return inSubject && !inClip;
    case Op::ReverseDifference: return inClip && !inSubject;
    case Op::Xor: return inSubject != inClip;
  }
  return false;
}

}  // namespace gh
