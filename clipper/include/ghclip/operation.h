// The Boolean operations and the clipper variants, with their command-line names.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace gh {

enum class Op {
  Intersection,       // S ∩ C
  Union,              // S ∪ C
  Difference,         // S \ C
  ReverseDifference,  // C \ S
  Xor,                // (S \ C) ∪ (C \ S)
};

// How phase 1 finds and decides intersections; phases 2 and 3 are shared by all variants.
enum class Variant {
  Naive,  // the paper: all pairs, doubles, perturbation of degenerate vertices
  Sweep,  // same decisions as Naive, sub-quadratic candidate search
  Exact,  // exact predicates with symbolic perturbation: no input vertex is moved
};

inline constexpr Op kAllOps[] = {Op::Intersection, Op::Union, Op::Difference,
                                 Op::ReverseDifference, Op::Xor};

std::string_view name(Op op);
std::string_view name(Variant variant);
std::optional<Op> parseOp(std::string_view text);
std::optional<Variant> parseVariant(std::string_view text);

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
