// Where phase 1 collects what a piece of its search found: crossings (with whatever the
// arithmetic's ordering needs beside them), degenerate contacts, and counts. One buffer per piece
// of work (parallel.h), reused by the calling thread from clip to clip: a clip on 10^3-gons finds
// ~2.3 * 10^5 crossings, and fresh memory for them costs as much as finding them (page faults).
#pragma once

#include <cstdint>
#include <type_traits>
#include <vector>

#include "arithmetic/pair_test.h"
#include "chunked_vector.h"
#include "operand.h"
#include "phase1_result.h"
#include "predicates/exact_counters.h"

namespace gh::detail {

template <class Extra>
struct CrossingBuffer {
  static constexpr bool kHasExtra = !std::is_empty_v<Extra>;
  ChunkedVector<Crossing> crossings;
  ChunkedVector<Extra> extras;  // beside crossings, when the arithmetic has anything to keep
  std::vector<std::uint32_t> degenerateSubject, degenerateClip;
  std::uint64_t pairs = 0;  // candidate pairs tested
  ExactCounters counters;

  void clear() {
    crossings.clear(), extras.clear(), degenerateSubject.clear(), degenerateClip.clear();
    pairs = 0, counters = {};
  }
  void add(const Crossing& c, const Extra& e) {
    crossings.push_back(c);
    if constexpr (kHasExtra) extras.push_back(e);
  }
  // The vertices of a degenerate pair that lie on the other operand's edge.
  void addDegenerate(PairTest t, std::uint32_t se, std::uint32_t ce, const Operand& subject, const Operand& clip) {
    if (t.onOtherEdge & PairTest::kSubjectFrom) degenerateSubject.push_back(se);
    if (t.onOtherEdge & PairTest::kSubjectTo) degenerateSubject.push_back(subject.next[se]);
    if (t.onOtherEdge & PairTest::kClipFrom) degenerateClip.push_back(ce);
    if (t.onOtherEdge & PairTest::kClipTo) degenerateClip.push_back(clip.next[ce]);
  }
  // Gives back memory beyond what a large clip needs, so that one huge clip does not pin it.
  void trim() {
    constexpr std::size_t kKeep = std::size_t{1} << 20;  // crossings: 40 MiB at most
    crossings.trim(kKeep), extras.trim(kKeep);
  }
};

// The calling thread's buffers, one per piece.
template <class Extra>
std::vector<CrossingBuffer<Extra>>& crossingBuffers(std::size_t pieces) {
  thread_local std::vector<CrossingBuffer<Extra>> buffers;
  if (buffers.size() < pieces) buffers.resize(pieces);
  for (std::size_t p = 0; p < pieces; ++p) buffers[p].clear();
  return buffers;
}

}  // namespace gh::detail
