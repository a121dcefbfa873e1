// A differential first look: every peer and our variants on the simple, holes and grid-snapped
// workloads, and Clipper and our variants also on the paper's random (self-intersecting)
// workload; all five operations; every answer judged by the exact oracle.
// Writes results/peers-first-look.md and the smallest failing case of each method (WKT + SVG).
//   peers_first_look OUT_DIR [CASES]
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <map>
#include <sstream>

#include "common/judge.h"
#include "common/provenance.h"
#include "ghclip/measure.h"
#include "ghio/formats.h"
#include "ghio/svg.h"
#include "ghwork/generators.h"
#include "tool_main.h"

namespace fs = std::filesystem;
using namespace gh;
using namespace gh::experiments;

namespace {

struct Workload {
  std::string name, description;
  std::size_t minN, maxN;
};

const Workload kWorkloads[] = {
    {"simple", "random simple polygons (star-shaped or 2-opt), n = 5..30", 5, 30},
    {"holes", "a square shell with 2-5 star holes against another, n = 20..60", 20, 60},
    {"grid", "random n-gons on the integer grid 0..8, n = 3..12 (degenerate contacts)", 3, 12},
    {"random", "the paper's random n-gons in the unit square, n = 4..24 (self-intersecting)", 4, 24},
};

struct Worst {
  bool any = false;
  std::size_t size = 0;
  std::string workload;
  int index = 0;
  Op op = Op::Intersection;
  Region s, c, r;
  Judged j;
};

}  // namespace

int run(int argc, char** argv) {
  if (argc < 2) return tools::usageError("peers_first_look", "usage: peers_first_look OUT_DIR [CASES]");
  const fs::path out = argv[1];
  const int cases = argc > 2 ? std::stoi(argv[2]) : 200;
  fs::create_directories(out / "peers-first-look");
  const std::vector<Method> methods = allMethods();

  // counts[workload][method][outcome]
  std::map<std::string, std::map<std::string, std::map<Outcome, int>>> counts;
  std::map<std::string, std::map<std::string, double>> worstRelative;
  std::map<std::string, Worst> smallestFailure;  // per method
  for (const Workload& w : kWorkloads) {
    for (int i = 0; i < cases; ++i) {
      const std::size_t n = w.minN + static_cast<std::size_t>(i) % (w.maxN - w.minN + 1);
      const work::Workload pair = work::generate(w.name, n, static_cast<std::uint64_t>(i + 1));
      for (Op op : kAllOps) {
        for (const Method& m : methods) {
          const Judged j = judge(m, pair.subject, pair.clip, op);
          ++counts[w.name][m.name][j.outcome];
          double& worst = worstRelative[w.name][m.name];
          if (j.outcome == Outcome::BeyondRounding || j.outcome == Outcome::Gross) worst = std::max(worst, j.relativeError);
          const bool failing = j.outcome == Outcome::BeyondRounding || j.outcome == Outcome::Gross ||
                               j.outcome == Outcome::Failed;
          const std::size_t size = vertexCount(pair.subject) + vertexCount(pair.clip);
          Worst& f = smallestFailure[m.name];
          if (failing && (!f.any || size < f.size || (size == f.size && j.relativeError > f.j.relativeError))) {
            f = {true, size, w.name, i + 1, op, pair.subject, pair.clip, j.result, j};
          }
        }
      }
    }
  }

  std::ostringstream md;
  md << "# Peers, first look: every method judged by the exact oracle\n\n"
     << markdown(provenance(argc, argv)) << "\n"
     << cases << " cases per workload (seeds 1.." << cases << "), each with all five operations:\n\n";
  for (const Workload& w : kWorkloads) md << "- **" << w.name << "**: " << w.description << "\n";
  md << "\nGEOS, Boost.Geometry and CGAL accept only valid simple polygons with holes: inputs "
        "without an exact OGC form (self-intersections, touching rings) are refused before they "
        "see them, and counted as refused. Clipper 6.4.2 and our variants take every input.\n\n"
     << "Outcomes: **exact** (error area 0), **rounding-level** (every wrong face inside the rounding "
        "zones of the exact answer: each constructed vertex may be either double around its exact "
        "crossing), **beyond rounding** (a wrong face outside them, relative error <= 1e-6), "
        "**gross** (relative error > 1e-6), **refused**, **failed** (threw), **cannot judge** (the "
        "oracle could not decide). Relative error = error area / largest of the operand, expected "
        "and result areas.\n\n";
  for (const Workload& w : kWorkloads) {
    md << "## " << w.name << "\n\n| method |";
    for (Outcome o : kOutcomes) md << " " << outcomeName(o) << " |";
    md << " worst relative error |\n|---|";
    for (std::size_t k = 0; k <= std::size(kOutcomes); ++k) md << "---|";
    md << "\n";
    for (const Method& m : methods) {
      md << "| " << m.name << " |";
      for (Outcome o : kOutcomes) md << " " << counts[w.name][m.name][o] << " |";
      md << " " << worstRelative[w.name][m.name] << " |\n";
    }
    md << "\n";
  }
  md << "## Smallest failing case of each method\n\n"
     << "Failing: beyond rounding, gross, or failed. A peer's failure is a finding about that peer.\n\n";
  for (const Method& m : methods) {
    const Worst& f = smallestFailure[m.name];
    if (!f.any) {
      md << "### " << m.name << "\n\nNo failing case.\n\n";
      continue;
    }
    const std::string id = m.name + "-" + f.workload + "-" + std::to_string(f.index) + "-" + std::string(name(f.op));
    const std::string base = "peers-first-look/" + id;
    std::ostringstream wkt;
    wkt << "# subject\n" << io::writeWkt(f.s) << "\n# clip\n" << io::writeWkt(f.c) << "\n# " << name(f.op)
        << " by " << m.name << "\n" << io::writeWkt(f.r) << "\n";
    io::writeText((out / (base + ".wkt")).string(), wkt.str());
    const auto v = oracle::exactCheck(f.s, f.c, f.op, f.r);
    std::vector<io::SvgMarker> marks;
    if (v.witness) marks.push_back({*v.witness, "#d00000", "witness"});
    io::writeText((out / (base + ".svg")).string(),
                  io::svgPicture({{&f.s, "#c6dbef", "#2171b5", "subject"},
                                  {&f.c, "#fcbba1", "#cb181d", "clip"},
                                  {&f.r, "#a1d99b", "#145214", m.name + " result"},
                                  {&v.wrong, "#ff0000", "#ff0000", "wrong faces (exact oracle)", 0.9}},
                                 id, marks));
    md << "### " << m.name << "\n\n" << f.workload << " seed " << f.index << ", " << name(f.op) << ", "
       << f.size << " input vertices: " << outcomeName(f.j.outcome);
    if (f.j.outcome == Outcome::Failed) {
      md << " (" << f.j.message << ")";
    } else {
      md << ", error area " << v.errorArea << " (relative " << v.relativeError() << "; outside the rounding zones "
         << v.beyondRoundingArea << ")";
    }
    md << ". [" << id << ".wkt](" << base << ".wkt)\n\n![" << id << "](" << base << ".svg)\n\n";
  }
  io::writeText((out / "peers-first-look.md").string(), md.str());
  std::cout << "wrote " << (out / "peers-first-look.md").string() << "\n";
  return 0;
}

int main(int argc, char** argv) { return tools::guardedMain("peers_first_look", argc, argv, run); }
