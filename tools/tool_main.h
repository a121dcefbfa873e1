// What every ghclip tool shares: one-line errors with fixed exit codes, and reading regions.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <stdexcept>
#include <string>

#include "ghclip/operation.h"
#include "ghclip/region.h"
#include "ghclip/validate.h"

namespace gh::tools {

// Exit codes of every tool (the README has the table).
inline constexpr int kExitFailed = 1;       // the algorithm or check failed on valid input
inline constexpr int kExitBadInput = 2;     // bad input or usage
inline constexpr int kExitCannotJudge = 3;  // a judge could not decide (never pass, never fail)

// Bad input found by a tool; its message already names the file.
class BadInput : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A message on one line (line breaks become spaces), as every tool prints its errors.
std::string oneLine(std::string text);

// Prints "tool: message" (one line) on stderr and returns kExitBadInput.
int usageError(const std::string& tool, const std::string& message);

// Parses the command line into app. Empty when the tool should go on; else its exit code: 0
// after --help (CLI11 printed the usage), kExitBadInput with one line on stderr for a bad
// command line.
std::optional<int> parseCommandLine(CLI::App& app, const char* tool, int argc, char** argv);

// Reads a region from a file ("-" = stdin), WKT or GeoJSON; BadInput names the file.
Region readRegion(const std::string& path);
// ...and validated as the clip validates its operands (gh::normalized: finite coordinates of at
// most 2^500, rings of 3 distinct vertices unless onBadRing drops them), so every tool refuses
// the same input with exit 2, peers and judges included.
Region readValidRegion(const std::string& path, OnBadRing onBadRing = OnBadRing::Throw);

// A snap-rounded OGC layout (features finer than the doubles: ghclip/ogc_layout.h) bends pieces
// through other nodes' cells, which the judges' allowance need not cover: such an answer is judged
// by the exact oracle as written (`text`, read back) before any tool writes it. Throws LayoutRefusal
// (exit 1) when it fails, oracle::CannotJudge (exit 3) when the oracle cannot decide.
void requireWithinRounding(const Region& subject, const Region& clip, Op op, const std::string& text);

// Runs `run`, turning every exception into one line on stderr and an exit code:
// BadInput / gh::InvalidInput -> 2, gh::ClipFailure -> 1, oracle::CannotJudge -> 3
// ("cannot judge: <reason>"), anything else -> 1.
int guardedMain(const char* tool, int argc, char** argv, int (*run)(int, char**));

}  // namespace gh::tools
