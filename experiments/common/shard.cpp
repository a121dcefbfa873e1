#include "shard.h"

#include <sstream>

namespace gh::experiments {

std::optional<Shard> parseShard(const std::string& text) {
  Shard s;
  char slash = 0;
  std::istringstream in(text);
  if (!(in >> s.k >> slash >> s.m) || slash != '/' || !in.eof() || s.m < 1 || s.k < 1 || s.k > s.m) return std::nullopt;
  return s;
}

}  // namespace gh::experiments
