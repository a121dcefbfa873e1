// The body of fuzz_clip_<variant>: all five operations on a fuzzed pair; no crash, no hang, no
// leak (sanitizers), finite output, the cheap invariants, and the sampling oracle agrees (or, for
// the exact variant, the boundary certificate proves what it would find: nothing). The exact
// variant's answers are judged as written too (docs/semantics.md): the OGC layout of each, which
// must be valid OGC (decided exactly) and pass the same judges.
// For the exact variant any disagreement traps; for naive and sweep it is recorded, and only
// crashes, hangs and non-finite output stop the campaign.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "findings.h"
#include "fuzz_input.h"
#include "judge_heap.h"
#include "ghclip/clip.h"
#include "ghclip/clipping.h"
#include "ghclip/errors.h"
#include "ghclip/ogc_layout.h"
#include "ghclip/ogc_validity.h"
#include "ghoracle/boundary_certificate.h"
#include "ghoracle/invariants.h"
#include "ghoracle/same_boundary.h"
#include "ghoracle/sampling_oracle.h"

namespace gh::fuzz {

// The clip targets' problems: up to 3 rings of up to 16 vertices each.
constexpr int kClipRings = 3, kClipVertices = 16;
inline Pair clipPair(const std::uint8_t* data, std::size_t size) { return pair(data, size, kClipRings, kClipVertices); }
inline ProblemKey clipProblem(const std::uint8_t* data, std::size_t size) {
  return problemKey(data, size, kClipRings, kClipVertices);
}

// What a clip target finds on one pair, every judge run: per operation, in the order found.
struct ClipFinding {
  enum class Kind { ClipFailure, NonFinite, Invariant, Sampling, Layout };
  Op op;
  Kind kind;
  std::string what;  // as a trap or a record names it
  // Non-finite output traps for every variant, not only the exact one.
  bool trapsAlways() const { return kind == Kind::NonFinite; }
};
struct ClipOutcome {
  bool refused = false;  // InvalidInput: the right answer to bad input, nothing judged
  std::vector<ClipFinding> findings;
};

// The sampling oracle as the clip targets run it (experiments/judge_cost.cpp times it so too).
inline oracle::SampleOptions clipTargetSampling() {
  oracle::SampleOptions so;
  so.uniformPoints = 200;
  so.stopWhenAllFail = true;  // only pass() is read: the same verdicts
  return so;
}

// The five operations on a pair as the clip targets clip them, phases 1 and 2 once (clipping.h:
// each answer is clip()'s, bit for bit): the answers given, each ClipFailure and non-finite answer
// added to outcome's findings, and outcome.refused on InvalidInput. With `written`, also each
// answer as written (the OGC layout's rings), a refused or invalid layout a finding; only those
// whose boundary mod 2 is not the answer's own, segment for segment (most are its rings
// reordered, reoriented and regrouped: the same interior exactly, judged with the rings).
inline std::vector<std::pair<Op, Region>> clipFive(const Pair& p, Variant variant, ClipOutcome& outcome,
                                                   std::vector<std::pair<Op, Region>>* written = nullptr) {
  using Kind = ClipFinding::Kind;
  std::vector<std::pair<Op, Region>> answers;
  std::optional<Clipping> clipping;
  try {
    clipping.emplace(p.subject, p.clip, optionsOf(variant));
  } catch (const InvalidInput&) {
    outcome.refused = true;
    return answers;
  } catch (const ClipFailure& e) {  // phase 1 gave up: clip() fails so for every operation
    for (Op op : kAllOps) outcome.findings.push_back({op, Kind::ClipFailure, std::string("ClipFailure: ") + e.what()});
    return answers;
  }
  for (Op op : kAllOps) {
    try {
      answers.emplace_back(op, clipping->result(op));
    } catch (const ClipFailure& e) {
      outcome.findings.push_back({op, Kind::ClipFailure, std::string("ClipFailure: ") + e.what()});
      continue;
    }
    const bool finite = std::all_of(answers.back().second.begin(), answers.back().second.end(), [](const Ring& ring) {
      return std::all_of(ring.begin(), ring.end(), [](const Point& q) { return std::isfinite(q.x) && std::isfinite(q.y); });
    });
    if (!finite) outcome.findings.push_back({op, Kind::NonFinite, "non-finite output"});
    if (!written) continue;
    try {
      const std::vector<PolygonWithHoles> polygons = clipping->polygons(op);
      if (const auto invalid = ogcInvalidity(polygons)) {
        outcome.findings.push_back({op, Kind::Layout, "written answer not valid OGC: " + *invalid});
      }
      Region asWritten = toRegion(polygons);
      if (!oracle::sameBoundaryModTwo(answers.back().second, asWritten)) written->emplace_back(op, std::move(asWritten));
    } catch (const LayoutRefusal& e) {
      outcome.findings.push_back({op, Kind::Layout, std::string("layout refused: ") + e.what()});
    }
  }
  return answers;
}

// The judges the clip targets run on the answers clipFive gave, each finding added to outcome's:
// the cheap invariants, then the boundary certificate (exact variant) and, unless it proves all
// five answers, the sampling oracle on the five at once.
// `which` prefixes each finding's message ("written answer: " for the answers as written).
inline void judgeFive(const Pair& p, Variant variant, const std::vector<std::pair<Op, Region>>& answers, ClipOutcome& outcome,
                      const std::string& which = "") {
  using Kind = ClipFinding::Kind;
  const JudgeHeap heap;  // the clips ran outside it
  const oracle::InvariantJudge invariants(p.subject, p.clip);
  for (const auto& [op, r] : answers) {
    const auto violations = invariants.violations(op, r);
    if (!violations.empty()) outcome.findings.push_back({op, Kind::Invariant, which + "invariant: " + violations.front()});
  }
  std::vector<std::pair<Op, const Region*>> judged;
  for (const auto& [op, r] : answers) judged.emplace_back(op, &r);
  // The exact variant's five answers, proved right up to the rounding of their crossings, need no
  // sampling: the sampling oracle passes every answer so proved (boundary_certificate.h). It
  // proves the exact variant's five answers on 98 % of its grown corpus, the other variants' on
  // 28-31 %, where it costs more than the sampling it saves (./harness judge-cost).
  if (variant == Variant::Exact) {
    const std::vector<bool> certified = oracle::certifiedAnswers(p.subject, p.clip, judged);
    if (std::all_of(certified.begin(), certified.end(), [](bool c) { return c; })) return;
  }
  // The five answers at once: each at every point a check of it alone would judge, or at one in
  // the same face, and at the points of the others (sampling_oracle.h).
  const auto verdicts = oracle::SamplingJudge(p.subject, p.clip, clipTargetSampling()).check(judged);
  for (std::size_t i = 0; i < answers.size(); ++i) {
    if (!verdicts[i].pass()) outcome.findings.push_back({answers[i].first, Kind::Sampling, which + "sampling oracle disagrees"});
  }
}

// All five operations on a pair, each answer through the judges the targets run (judgeFive). The
// clip targets trap or record what this finds; tests/golden/judge_verdicts_test.cpp pins it on
// committed inputs, so that a faster judge is shown to find the same.
inline ClipOutcome clipAndJudge(const Pair& p, Variant variant) {
  ClipOutcome outcome;
  std::vector<std::pair<Op, Region>> written;
  const std::vector<std::pair<Op, Region>> answers =
      clipFive(p, variant, outcome, variant == Variant::Exact ? &written : nullptr);
  if (answers.empty()) return outcome;
#ifdef GHCLIP_FUZZ_UNJUDGED
  return outcome;  // the ceiling: what an execution costs before any judge (fuzz/CMakeLists.txt)
#endif
  judgeFive(p, variant, answers, outcome);
  if (!written.empty()) judgeFive(p, variant, written, outcome, "written answer: ");
  return outcome;
}

// The body of a clip target: for the exact variant every finding traps; for naive and sweep it
// is recorded (fuzz/findings.h), and only crashes, hangs and non-finite output stop the campaign.
inline int clipTarget(const char* target, Variant variant, const std::uint8_t* data, std::size_t size) {
  const Pair p = clipPair(data, size);
  const ClipOutcome outcome = clipAndJudge(p, variant);
  if (outcome.findings.empty()) return 0;
  RecordedOperands operands(p.subject, p.clip);  // as its findings name them
  for (const ClipFinding& f : outcome.findings) {
    if (variant == Variant::Exact || f.trapsAlways()) trap(f.what, p.subject, p.clip, f.op);
    record(target, f.what, operands, f.op, data, size);
  }
  return 0;
}

}  // namespace gh::fuzz
