#include "tool_main.h"

#include <iostream>

#include "ghclip/errors.h"
#include "ghclip/ogc_layout.h"
#include "ghio/formats.h"
#include "ghoracle/exact_oracle.h"

namespace gh::tools {
std::string oneLine(std::string text) {
  for (char& c : text) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  return text;
}

int usageError(const std::string& tool, const std::string& message) {
  std::cerr << tool << ": " << oneLine(message) << std::endl;
  return kExitBadInput;
}

std::optional<int> parseCommandLine(CLI::App& app, const char* tool, int argc, char** argv) {
  app.set_version_flag("--version", std::string(tool) + " " GHCLIP_VERSION);
  if (argc <= 1 && !app.get_options([](const CLI::Option* o) { return o->get_required(); }).empty()) {
    std::cerr << app.help();  // nothing given: the usage, as a usage error
    return kExitBadInput;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --version
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    return usageError(tool, e.what());
  }
  return std::nullopt;
}

Region readRegion(const std::string& path) {
  try {
    return io::readAuto(io::readText(path));
  } catch (const std::exception& e) {
    throw BadInput(path + ": " + e.what());
  }
}

Region readValidRegion(const std::string& path, OnBadRing onBadRing) {
  const Region region = readRegion(path);
  try {
    return normalized(region, onBadRing);
  } catch (const InvalidInput& e) {
    throw BadInput(path + ": " + e.what());
  }
}

void requireWithinRounding(const Region& subject, const Region& clip, Op op, const std::string& text) {
  const oracle::ExactVerdict v = oracle::exactCheck(subject, clip, op, io::readAuto(text), {false, false, false});
  if (!v.pass) {
    throw LayoutRefusal("the answer has features finer than the doubles, and its snap-rounded layout lies beyond the "
                        "rounding the exact oracle allows (relative error area " +
                        std::to_string(v.relativeBeyondRounding()) + ")");
  }
}

int guardedMain(const char* tool, int argc, char** argv, int (*run)(int, char**)) {
  try {
    return run(argc, argv);
  } catch (const BadInput& e) {
    return usageError(tool, e.what());
  } catch (const InvalidInput& e) {
    return usageError(tool, e.what());
  } catch (const io::WriteError& e) {
    return usageError(tool, e.what());
  } catch (const oracle::CannotJudge& e) {
    std::cerr << tool << ": cannot judge: " << oneLine(e.what()) << std::endl;
    return kExitCannotJudge;
  } catch (const ClipFailure& e) {
    std::cerr << tool << ": clipping failed: " << oneLine(e.what()) << std::endl;
    return kExitFailed;
  } catch (const LayoutRefusal& e) {
    std::cerr << tool << ": cannot lay the answer out as OGC polygons: " << oneLine(e.what())
              << "; --layout rings writes the raw rings" << std::endl;
    return kExitFailed;
  } catch (const std::exception& e) {
    std::cerr << tool << ": " << oneLine(e.what()) << std::endl;
    return kExitFailed;
  }
}

}  // namespace gh::tools
