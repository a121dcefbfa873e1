#include "ghclip/operation.h"

namespace gh {

std::string_view name(Op op) {
  switch (op) {
    case Op::Intersection: return "intersection";
    case Op::Union: return "union";
    case Op::Difference: return "difference";
    case Op::ReverseDifference: return "reverse-difference";
    case Op::Xor: return "xor";
  }
  return "?";
}

std::optional<Op> parseOp(std::string_view text) {
  for (Op op : kAllOps) {
    if (name(op) == text) return op;
  }
  return std::nullopt;
}

}  // namespace gh
