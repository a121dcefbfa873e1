// Clips every example listed in experiments/examples/examples.txt and writes, per example, the
// result as GIS tools read it (WKT, the OGC layout ghclip writes by default), its raw rings
// (.rings.wkt, for even-odd readers), a picture (SVG) and its statistics, plus an index README.md.
//   run_examples EXAMPLES_DIR OUT_DIR
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "common/provenance.h"
#include "ghclip/clip.h"
#include "ghclip/measure.h"
#include "ghio/formats.h"
#include "ghio/svg.h"
#include "stats_json.h"
#include "tool_main.h"

namespace fs = std::filesystem;

// The examples show what a user gets: the library's default, named.
const gh::Variant kVariant = gh::Variant::Exact;

int run(int argc, char** argv) {
  if (argc != 3) return gh::tools::usageError("run_examples", "usage: run_examples EXAMPLES_DIR OUT_DIR");
  const fs::path in = argv[1], out = argv[2];
  fs::create_directories(out);
  std::ifstream list(in / "examples.txt");
  if (!list) return gh::tools::usageError("run_examples", (in / "examples.txt").string() + ": cannot open");

  std::ostringstream table;
  table << "| example | operation | subject | clip | result area (even-odd) | rings | intersections | "
           "picture |\n|---|---|---|---|---|---|---|---|\n";
  std::string line;
  nlohmann::json all = nlohmann::json::array();
  while (std::getline(list, line)) {
    std::istringstream words(line);
    std::string name, opName, subjectFile, clipFile;
    if (!(words >> name) || name[0] == '#') continue;
    if (!(words >> opName >> subjectFile >> clipFile)) {
      throw gh::tools::BadInput("examples.txt: incomplete line '" + line + "'");
    }
    const auto op = gh::parseOp(opName);
    if (!op) throw gh::tools::BadInput("examples.txt: unknown operation '" + opName + "'");
    const gh::Region subject = gh::tools::readRegion((in / subjectFile).string());
    const gh::Region clip = gh::tools::readRegion((in / clipFile).string());
    gh::Stats stats;
    const gh::Region result = gh::clip(subject, clip, *op, gh::optionsOf(kVariant), &stats);
    const double area = gh::evenOddArea(result);
    gh::io::writeText((out / (name + ".wkt")).string(), gh::io::write(result, gh::io::Format::Wkt, gh::io::Layout::Ogc));
    gh::io::writeText((out / (name + ".rings.wkt")).string(), gh::io::write(result, gh::io::Format::Wkt, gh::io::Layout::Rings));
    std::ostringstream title;
    title << subjectFile << " " << opName << " " << clipFile << " (" << gh::name(kVariant) << "): area " << area;
    gh::io::writeText((out / (name + ".svg")).string(),
                      gh::io::svgPicture({{&subject, "#c6dbef", "#2171b5", "subject " + subjectFile},
                                          {&clip, "#fcbba1", "#cb181d", "clip " + clipFile},
                                          {&result, "#2ca02c", "#145214", "result", 0.6}},
                                         title.str()));
    nlohmann::json j = gh::tools::statsJson(stats);
    j["example"] = name;
    j["op"] = opName;
    j["result_area"] = area;
    all.push_back(j);
    table << "| " << name << " | " << opName << " | " << subjectFile << " | " << clipFile << " | "
          << area << " | " << result.size() << " | " << stats.intersections << " | [svg](" << name
          << ".svg) |\n";
  }
  gh::io::writeText((out / "stats.json").string(), all.dump(2));
  const auto prov = gh::experiments::provenance(argc, argv);
  gh::io::writeText((out / "README.md").string(),
                    "# Examples\n\nEvery example in `experiments/examples/examples.txt`, clipped by "
                    "the " + std::string(gh::name(kVariant)) + " variant (the library's default). Areas are even-odd areas of the "
                    "result. `<example>.wkt` is the answer as GIS tools read it (the OGC layout `ghclip` writes "
                    "by default: polygons with holes that GEOS calls valid), `<example>.rings.wkt` its raw rings "
                    "(`--layout rings`: only an even-odd reader reads those right).\n\n" +
                        gh::experiments::markdown(prov) + "\n" + table.str());
  std::cout << "wrote " << all.size() << " examples to " << out.string() << "\n";
  return 0;
}

int main(int argc, char** argv) { return gh::tools::guardedMain("run_examples", argc, argv, run); }
