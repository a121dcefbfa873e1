// libFuzzer target: the exact variant on fuzzed region pairs (see clip_target.h).
#include "clip_target.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return gh::fuzz::clipTarget("fuzz_clip_exact", gh::Variant::Exact, data, size);
}

GHCLIP_NEW_PROBLEM_MUTATOR(gh::fuzz::clipProblem)
