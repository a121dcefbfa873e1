// How fuzz targets report: trap() for findings that must stop a campaign (crashes of the exact
// variant's contract); record() for findings that are counted and written out (the naive and
// sweep variants' known weaknesses, a peer's disagreement), so a campaign goes on.
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "ghclip/operation.h"
#include "ghio/formats.h"

namespace gh::fuzz {

[[noreturn]] inline void trap(const std::string& what, const Region& s, const Region& c, Op op) {
  std::fprintf(stderr, "FINDING (trap): %s\n  op %s\n  subject %s\n  clip    %s\n", what.c_str(),
               std::string(name(op)).c_str(), io::writeWkt(s).c_str(), io::writeWkt(c).c_str());
  std::abort();
}

// Appends one line per finding to $GHCLIP_FUZZ_FINDINGS (if set): target, what, op, WKT, WKT.
inline void record(const char* target, const std::string& what, const Region& s, const Region& c, Op op) {
  static std::uint64_t count = 0;
  ++count;
  const char* path = std::getenv("GHCLIP_FUZZ_FINDINGS");
  if (!path || !*path) return;
  if (std::FILE* f = std::fopen(path, "a")) {
    std::fprintf(f, "%s\t%s\t%s\t%s\t%s\n", target, what.c_str(), std::string(name(op)).c_str(),
                 io::writeWkt(s).c_str(), io::writeWkt(c).c_str());
    std::fclose(f);
  }
}

}  // namespace gh::fuzz
