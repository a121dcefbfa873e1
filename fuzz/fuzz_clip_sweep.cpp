// libFuzzer target: the sweep variant on fuzzed region pairs (see clip_target.h).
#include "clip_target.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return gh::fuzz::clipTarget("fuzz_clip_sweep", gh::Variant::Sweep, data, size);
}

GHCLIP_NEW_PROBLEM_MUTATOR(gh::fuzz::clipProblem)
