// libFuzzer target: the exact variant against Clipper 6.4.2 (Vatti, even-odd) on integer inputs.
// When their answers differ beyond rounding, the exact oracle says who is wrong: the exact
// variant traps, Clipper's failure is recorded as a finding about Clipper.
#include <fuzzer/FuzzedDataProvider.h>

#include <optional>
#include <utility>

#include "findings.h"
#include "judge_heap.h"
#include "new_problem_mutator.h"
#include "ghclip/clipping.h"
#include "ghclip/errors.h"
#include "ghoracle/exact_oracle.h"
#include "ghpeers/peer.h"
#include "ghoracle/tolerance.h"

namespace {

gh::Region integerRegion(FuzzedDataProvider& in) {
  gh::Region r;
  const int rings = in.ConsumeIntegralInRange<int>(1, 2);
  for (int k = 0; k < rings; ++k) {
    gh::Ring ring;
    const int n = in.ConsumeIntegralInRange<int>(3, 10);
    const int range = in.ConsumeIntegralInRange<int>(1, 1000);
    for (int v = 0; v < n; ++v) {
      const double x = in.ConsumeIntegralInRange<int>(-range, range);
      const double y = in.ConsumeIntegralInRange<int>(-range, range);
      ring.push_back({x, y});
    }
    r.push_back(std::move(ring));
  }
  return r;
}

// This target's problem, S then C: what it judges and what the mutator compares.
std::pair<gh::Region, gh::Region> integerPair(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  gh::Region s = integerRegion(in);
  return {std::move(s), integerRegion(in)};
}
gh::fuzz::ProblemKey integerProblem(const std::uint8_t* data, std::size_t size) {
  const auto [s, c] = integerPair(data, size);
  return gh::fuzz::ProblemKey().add(s).add(c);
}

}  // namespace

GHCLIP_NEW_PROBLEM_MUTATOR(integerProblem)

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto [s, c] = integerPair(data, size);
  const gh::peers::Peer* vatti = gh::peers::findPeer("clipper6");
  std::vector<std::pair<gh::Region, gh::Region>> answers;  // (ours, Clipper's) per operation
  std::optional<gh::Clipping> clipping;  // phases 1 and 2 once for the five operations
  try {
    clipping.emplace(s, c, gh::optionsOf(gh::Variant::Exact));
  } catch (const gh::InvalidInput&) {
    return 0;  // refused: Clipper is not asked about input we refuse
  }
  for (gh::Op op : gh::kAllOps) {
    gh::Region ours = clipping->result(op);
    gh::Region theirs;
    try {
      theirs = vatti->clip(s, c, op);
    } catch (const std::exception& e) {  // Clipper gave up on input we accept: a finding about Clipper
      gh::fuzz::record("fuzz_diff_vatti", std::string("Clipper 6.4.2 failed: ") + e.what(), s, c, op, data, size);
      return 0;
    }
    answers.emplace_back(std::move(ours), std::move(theirs));
  }
  // Each pair may differ by the two answers' rounding allowances, decided exactly.
  std::vector<double> allowed;
  for (const auto& [ours, theirs] : answers) {
    allowed.push_back(gh::oracle::roundingAllowance(s, c, ours) + gh::oracle::roundingAllowance(s, c, theirs));
  }
  std::vector<bool> within;
  try {
    const gh::fuzz::JudgeHeap heap;
    // Most pairs by a bound in doubles; the others in one arrangement.
    within = gh::oracle::symmetricDifferencesWithin(answers, allowed);
  } catch (const gh::oracle::CannotJudge& e) {
    gh::fuzz::record("fuzz_diff_vatti", std::string("cannot judge: ") + e.what(), s, c, gh::kAllOps[0], data, size);
    return 0;
  }
  for (std::size_t i = 0; i < answers.size(); ++i) {
    const gh::Op op = gh::kAllOps[i];
    const auto& [ours, theirs] = answers[i];
    if (within[i]) continue;
    try {
      const gh::fuzz::JudgeHeap heap;
      if (!gh::oracle::exactCheck(s, c, op, ours, {false, false, false}).pass) {
        gh::fuzz::trap("exact variant wrong where Clipper 6.4.2 differs", s, c, op);
      }
    } catch (const gh::oracle::CannotJudge& e) {
      gh::fuzz::record("fuzz_diff_vatti", std::string("cannot judge: ") + e.what(), s, c, op, data, size);
      continue;
    }
    gh::fuzz::record("fuzz_diff_vatti", "Clipper 6.4.2 wrong (exact variant right)", s, c, op, data, size);
  }
  return 0;
}
