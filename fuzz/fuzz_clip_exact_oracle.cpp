// libFuzzer target: small fuzzed inputs, the exact variant judged by the exact CGAL oracle.
// Any answer with a wrong face beyond the rounding zones traps; a case the oracle cannot judge is
// recorded (counted apart), never a pass. The five answers are judged in one arrangement.
#include <optional>

#include "findings.h"
#include "fuzz_input.h"
#include "judge_heap.h"
#include "ghclip/clipping.h"
#include "ghclip/errors.h"
#include "ghoracle/exact_oracle.h"

namespace {

// This target's problems: up to 2 rings of up to 8 vertices each (the exact oracle is costly).
constexpr int kOracleRings = 2, kOracleVertices = 8;
gh::fuzz::Pair oraclePair(const std::uint8_t* data, std::size_t size) {
  return gh::fuzz::pair(data, size, kOracleRings, kOracleVertices);
}
gh::fuzz::ProblemKey oracleProblem(const std::uint8_t* data, std::size_t size) {
  return gh::fuzz::problemKey(data, size, kOracleRings, kOracleVertices);
}

}  // namespace

GHCLIP_NEW_PROBLEM_MUTATOR(oracleProblem)

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const gh::fuzz::Pair p = oraclePair(data, size);
  std::vector<gh::oracle::Answer> answers;
  std::optional<gh::Clipping> clipping;  // phases 1 and 2 once for the five operations
  try {
    clipping.emplace(p.subject, p.clip, gh::optionsOf(gh::Variant::Exact));
  } catch (const gh::InvalidInput&) {
    return 0;
  }
  for (gh::Op op : gh::kAllOps) {
    try {
      answers.push_back({op, clipping->result(op)});
    } catch (const gh::ClipFailure& e) {
      gh::fuzz::trap(std::string("ClipFailure: ") + e.what(), p.subject, p.clip, op);
    }
  }
#ifdef GHCLIP_FUZZ_UNJUDGED
  return 0;  // the ceiling: what an execution costs before the judge (fuzz/CMakeLists.txt)
#endif
  std::vector<gh::oracle::ExactVerdict> verdicts;
  try {
    const gh::fuzz::JudgeHeap heap;
    verdicts = gh::oracle::exactCheckAll(p.subject, p.clip, answers, {false, false, false});
  } catch (const gh::oracle::CannotJudge& e) {
    gh::fuzz::record("fuzz_clip_exact_oracle", std::string("cannot judge: ") + e.what(), p.subject, p.clip,
                     answers.front().op, data, size);
    return 0;
  }
  for (std::size_t i = 0; i < answers.size(); ++i) {
    const gh::oracle::ExactVerdict& v = verdicts[i];
    if (!v.pass) {
      gh::fuzz::trap("exact oracle: wrong faces beyond rounding, area " + std::to_string(v.beyondRoundingArea) +
                         " (error area " + std::to_string(v.errorArea) + ")",
                     p.subject, p.clip, answers[i].op);
    }
  }
  return 0;
}
