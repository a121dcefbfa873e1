// How a generated file was made: every file in results/ starts with this.
#pragma once

#include <string>

namespace gh::experiments {

struct Provenance {
  std::string command;   // as given
  std::string commit;    // $GHCLIP_COMMIT (set by ./harness), else "unknown"
  std::string compiler;  // id and version, from CMake
  std::string flags;     // C++ flags of the Release build, from CMake
  std::string machine;   // CPU model, cores, memory, kernel
  std::string date;      // UTC, ISO 8601
};

Provenance provenance(int argc, char** argv);

// A Markdown block listing the provenance, for the top of a report.
std::string markdown(const Provenance& p);

}  // namespace gh::experiments
