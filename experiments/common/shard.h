// Studies split over M processes or machines: shard K of M takes the seeds s with
// (s - 1) mod M = K - 1, writes its raw counts as JSON, and a merge of all M files writes the
// report one run would have written.
#pragma once

#include <optional>
#include <string>

namespace gh::experiments {

struct Shard {
  int k = 1, m = 1;
  bool takes(long seed) const { return (seed - 1) % m == k - 1; }
  std::string fileSuffix() const { return "shard-" + std::to_string(k) + "-of-" + std::to_string(m) + ".json"; }
};

// "K/M" with 1 <= K <= M, or nullopt.
std::optional<Shard> parseShard(const std::string& text);

}  // namespace gh::experiments
