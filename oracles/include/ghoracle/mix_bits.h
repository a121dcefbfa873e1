// splitmix64's finalizer: every bit of the input moves every bit of the output. The judges'
// hashes and sample phases derive from doubles' bit patterns, whose low bits are all zero for a
// coordinate with a short significand, so their bits go through this before they are used. The
// fuzz targets' problem keys (fuzz/new_problem_mutator.h) hash with it too.
#pragma once

#include <cstdint>

namespace gh::oracle {

inline std::uint64_t mixBits(std::uint64_t h) {
  h = (h ^ (h >> 30)) * 0xBF58476D1CE4E5B9ull;
  h = (h ^ (h >> 27)) * 0x94D049BB133111EBull;
  return h ^ (h >> 31);
}

}  // namespace gh::oracle
