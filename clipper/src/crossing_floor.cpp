#include "crossing_floor.h"

#include "arithmetic/paper_arithmetic.h"

namespace gh::detail {

std::size_t crossingFloor(const Region& subject, const Region& clip, std::vector<Crossing>& out, bool vectorized) {
  // Validated and flattened as gh::clip does it, so the two are timed on the same footing.
  const Operand s(subject, false), c(clip, false);
  ExactCounters counters;
  const PaperArithmetic paper(counters);
  PaperArithmetic::Extra none;
  out.clear();
  if (vectorized && rowKernelsAvailable()) {
    // Into the clip's own kind of buffer (kept from call to call, as the clip keeps it).
    const EdgeArrays arrays(c);
    thread_local CrossingBuffer<PaperArithmetic::Extra> buffer;
    buffer.clear();
    for (std::uint32_t i = 0; i < s.size(); ++i) paper.testRow(s, i, c, &arrays, buffer);
    return buffer.crossings.size();
  }
  Crossing crossing;
  for (std::uint32_t i = 0; i < s.size(); ++i) {
    for (std::uint32_t j = 0; j < c.size(); ++j) {
      if (paper.test(s, i, c, j, crossing, none).kind == PairTest::Kind::Crossing) out.push_back(crossing);
    }
  }
  return out.size();
}

}  // namespace gh::detail
