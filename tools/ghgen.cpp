// ghgen: write a subject/clip pair of any workload, to look at it or feed it to ghclip.
// Exit codes: 0 done, 2 bad usage.
#include <CLI/CLI.hpp>
#include <iostream>
#include <sstream>

#include "ghio/formats.h"
#include "ghio/svg.h"
#include "ghwork/generators.h"
#include "tool_main.h"

namespace {

std::string workloadHelp() {
  std::ostringstream s;
  s << "Write a subject/clip pair of a workload: by default two lines, the subject's WKT then\n"
       "the clip's (GeoJSON on request: a FeatureCollection of two features named subject and\n"
       "clip). Deterministic by seed.\nWorkloads:";
  for (const auto& n : gh::work::workloadNames()) s << ' ' << n;
  s << "\nNear-degenerate variants, as a suffix (e.g. simple+far):";
  for (const auto& v : gh::work::variantSuffixes()) s << " +" << v;
  return s.str();
}

int run(int argc, char** argv) {
  CLI::App app{workloadHelp(), "ghgen"};
  std::string workload, svgPath, outPath = "-", formatName = "wkt";
  std::size_t n = 10;
  std::uint64_t seed = 1;
  app.add_option("WORKLOAD", workload, "workload name, optionally with +variant")->required();
  app.add_option("--n", n, "vertices per operand (about)")->capture_default_str();
  app.add_option("--seed", seed, "seed")->capture_default_str();
  app.add_option("--svg", svgPath, "also draw the pair to this SVG file");
  app.add_option("-o,--output", outPath, "output file ('-' = stdout)")->capture_default_str();
  app.add_option("--format", formatName, "wkt | geojson")->capture_default_str();
  std::string subjectPath, clipPath;
  app.add_option("--subject", subjectPath, "also write the subject alone to this file (ghclip's SUBJECT)");
  app.add_option("--clip", clipPath, "also write the clip alone to this file (ghclip's CLIP)");
  if (const auto exitCode = gh::tools::parseCommandLine(app, "ghgen", argc, argv)) return *exitCode;
  if (formatName != "wkt" && formatName != "geojson") {
    return gh::tools::usageError("ghgen", "unknown --format '" + formatName + "'");
  }
  if (n < 3 || n > 10'000'000) return gh::tools::usageError("ghgen", "--n must be in 3..10^7");
  gh::work::Workload w;
  try {
    w = gh::work::generate(workload, n, seed);
  } catch (const std::invalid_argument& e) {
    return gh::tools::usageError("ghgen", e.what());
  }
  std::string text;
  if (formatName == "wkt") {
    text = gh::io::writeWkt(w.subject) + "\n" + gh::io::writeWkt(w.clip);
  } else {
    text = gh::io::writeGeoJsonPair(w.subject, w.clip);
  }
  gh::io::OutputFiles files;
  files.add(outPath, text);
  const auto format = formatName == "geojson" ? gh::io::Format::GeoJson : gh::io::Format::Wkt;
  if (!subjectPath.empty()) files.add(subjectPath, gh::io::write(w.subject, format));
  if (!clipPath.empty()) files.add(clipPath, gh::io::write(w.clip, format));
  if (!svgPath.empty()) {
    files.add(svgPath, gh::io::svgPicture({{&w.subject, "#c6dbef", "#2171b5", "subject"},
                                           {&w.clip, "#fcbba1", "#cb181d", "clip"}},
                                          workload + " n=" + std::to_string(n) + " seed=" + std::to_string(seed)));
  }
  files.commit();
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return gh::tools::guardedMain("ghgen", argc, argv, run); }
