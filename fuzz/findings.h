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

// Appends one line per finding to $GHCLIP_FUZZ_FINDINGS (if set): target, what, op, WKT, WKT,
// and the name of the fuzz input, which is saved under $GHCLIP_FUZZ_FINDINGS_INPUTS (if set) so
// that every finding can be replayed by its target and joins the campaign's corpus.
inline void record(const char* target, const std::string& what, const Region& s, const Region& c, Op op,
                   const std::uint8_t* data, std::size_t size) {
  const char* path = std::getenv("GHCLIP_FUZZ_FINDINGS");
  if (!path || !*path) return;
  // FNV-1a of the input names it (distinct inputs, distinct names, for any practical campaign).
  std::uint64_t h = 1469598103934665603ull;
  for (std::size_t i = 0; i < size; ++i) h = (h ^ data[i]) * 1099511628211ull;
  char input[32];
  std::snprintf(input, sizeof input, "input-%016llx", static_cast<unsigned long long>(h));
  if (const char* dir = std::getenv("GHCLIP_FUZZ_FINDINGS_INPUTS"); dir && *dir) {
    if (std::FILE* f = std::fopen((std::string(dir) + "/" + input).c_str(), "wb")) {
      std::fwrite(data, 1, size, f);
      std::fclose(f);
    }
  }
  if (std::FILE* f = std::fopen(path, "a")) {
    std::fprintf(f, "%s\t%s\t%s\t%s\t%s\t%s\n", target, what.c_str(), std::string(name(op)).c_str(),
                 io::writeWkt(s).c_str(), io::writeWkt(c).c_str(), input);
    std::fclose(f);
  }
}

}  // namespace gh::fuzz
