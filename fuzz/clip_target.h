// The body of fuzz_clip_<variant>: all five operations on a fuzzed pair; no crash, no hang, no
// leak (sanitizers), finite output, the cheap invariants, and the sampling oracle agrees.
// For the exact variant any disagreement traps; for naive and sweep it is recorded, and only
// crashes and hangs stop the campaign.
#pragma once

#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "findings.h"
#include "fuzz_input.h"
#include "judge_heap.h"
#include "ghclip/clip.h"
#include "ghclip/clipping.h"
#include "ghclip/errors.h"
#include "ghoracle/invariants.h"
#include "ghoracle/sampling_oracle.h"

namespace gh::fuzz {

// The clip targets' problems: up to 3 rings of up to 16 vertices each.
constexpr int kClipRings = 3, kClipVertices = 16;
inline Pair clipPair(const std::uint8_t* data, std::size_t size) { return pair(data, size, kClipRings, kClipVertices); }
inline ProblemKey clipProblem(const std::uint8_t* data, std::size_t size) {
  return problemKey(data, size, kClipRings, kClipVertices);
}

inline int clipTarget(const char* target, Variant variant, const std::uint8_t* data, std::size_t size) {
  const Pair p = clipPair(data, size);
  RecordedOperands operands(p.subject, p.clip);  // as its findings name them
  const bool strict = variant == Variant::Exact;
  oracle::SampleOptions so;
  so.uniformPoints = 200;
  so.stopWhenAllFail = true;  // only pass() is read below: the same verdicts
  // Phases 1 and 2 once for the five operations (clipping.h: each answer is clip()'s, bit for bit).
  std::optional<Clipping> clipping;
  try {
    clipping.emplace(p.subject, p.clip, optionsOf(variant));
  } catch (const InvalidInput&) {
    return 0;  // refused cleanly: the right answer to bad input
  } catch (const ClipFailure& e) {  // phase 1 gave up: clip() fails so for every operation
    for (Op op : kAllOps) {
      if (strict) trap(std::string("ClipFailure: ") + e.what(), p.subject, p.clip, op);
      record(target, std::string("ClipFailure: ") + e.what(), operands, op, data, size);
    }
    return 0;
  }
  std::vector<std::pair<Op, Region>> answers;
  for (Op op : kAllOps) {
    try {
      answers.emplace_back(op, clipping->result(op));
    } catch (const ClipFailure& e) {
      if (strict) trap(std::string("ClipFailure: ") + e.what(), p.subject, p.clip, op);
      record(target, std::string("ClipFailure: ") + e.what(), operands, op, data, size);
      continue;
    }
    for (const Ring& ring : answers.back().second) {
      for (const Point& q : ring) {
        if (!std::isfinite(q.x) || !std::isfinite(q.y)) trap("non-finite output", p.subject, p.clip, op);
      }
    }
  }
  if (answers.empty()) return 0;
#ifdef GHCLIP_FUZZ_UNJUDGED
  return 0;  // the ceiling: what an execution costs before any judge (fuzz/CMakeLists.txt)
#endif
  const JudgeHeap heap;  // the clips above ran outside it
  const oracle::InvariantJudge invariants(p.subject, p.clip);
  for (const auto& [op, r] : answers) {
    const auto violations = invariants.violations(op, r);
    if (!violations.empty()) {
      if (strict) trap("invariant: " + violations.front(), p.subject, p.clip, op);
      record(target, "invariant: " + violations.front(), operands, op, data, size);
    }
  }
  // The five answers at once: each at every point a check of it alone would judge, or at one in
  // the same face, and at the points of the others (sampling_oracle.h).
  std::vector<std::pair<Op, const Region*>> judged;
  for (const auto& [op, r] : answers) judged.emplace_back(op, &r);
  const auto verdicts = oracle::SamplingJudge(p.subject, p.clip, so).check(judged);
  for (std::size_t i = 0; i < answers.size(); ++i) {
    if (verdicts[i].pass()) continue;
    if (strict) trap("sampling oracle disagrees", p.subject, p.clip, answers[i].first);
    record(target, "sampling oracle disagrees", operands, answers[i].first, data, size);
  }
  return 0;
}

}  // namespace gh::fuzz
