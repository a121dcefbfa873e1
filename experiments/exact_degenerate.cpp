// The exact variant on degenerate input, beside the naive variant: integer-grid n-gons and every
// named degenerate family, all five operations, judged by the exact oracle; and bitset-grid cases
// whose answers must equal the bitwise answer with error area exactly 0.
// Writes results/exact-degenerate.md.
//   exact_degenerate OUT_DIR [CASES]
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <map>
#include <sstream>

#include "common/provenance.h"
#include "ghclip/clip.h"
#include "ghclip/errors.h"
#include "ghio/formats.h"
#include "ghoracle/exact_oracle.h"
#include "ghwork/generators.h"
#include "tool_main.h"

namespace fs = std::filesystem;
using namespace gh;

namespace {

struct Tally {
  long checks = 0, fails = 0, clipFailures = 0, zeroError = 0;
  double worstRelative = 0;
  std::string worstCase;  // the input and operation of the worst relative error
  unsigned long long filterFailures = 0, predicateCalls = 0;
  std::string firstFailure;
};

const char* kFamilies[] = {"grid", "identical", "shared-edge", "touching-vertex",
                           "nested-touching", "sliver", "sub-boundary", "bitset-grid"};

}  // namespace

int run(int argc, char** argv) {
  if (argc < 2) return tools::usageError("exact_degenerate", "usage: exact_degenerate OUT_DIR [CASES]");
  const fs::path out = argv[1];
  const long cases = argc > 2 ? std::stol(argv[2]) : 10000;
  fs::create_directories(out);
  std::map<std::string, std::map<Variant, Tally>> tallies;
  const long perFamily = cases / static_cast<long>(std::size(kFamilies));
  for (const std::string family : kFamilies) {
    for (long i = 0; i < perFamily; ++i) {
      const std::size_t n = family == "bitset-grid" ? 8 + static_cast<std::size_t>(i % 40)
                                                    : 3 + static_cast<std::size_t>(i % 10);
      const auto seed = static_cast<std::uint64_t>(i + 1);
      const work::Workload w = work::generate(family, n, seed);
      const work::BitsetGrid bits = family == "bitset-grid" ? work::bitsetGrid(n, seed) : work::BitsetGrid{};
      for (Op op : kAllOps) {
        for (Variant v : {Variant::Naive, Variant::Exact}) {
          Tally& t = tallies[family][v];
          ++t.checks;
          Stats stats;
          Region r;
          try {
            Options o = optionsOf(v);
            r = clip(w.subject, w.clip, op, o, &stats);
          } catch (const ClipFailure& e) {
            ++t.clipFailures, ++t.fails;
            continue;
          }
          t.filterFailures += stats.filterFailures;
          t.predicateCalls += stats.candidatePairs;
          oracle::ExactVerdict verdict;
          if (family == "bitset-grid") {
            // The answer is known without any oracle: the cells of op(bits); compare exactly.
            std::vector<bool> cells(bits.subject.size());
            for (std::size_t k = 0; k < cells.size(); ++k) cells[k] = apply(op, bits.subject[k], bits.clip[k]);
            verdict = oracle::exactCheck(work::cellsRegion(bits, cells), {}, Op::Union, r, {false, false, true});
          } else {
            verdict = oracle::exactCheck(w.subject, w.clip, op, r, {false, false, true});
          }
          if (verdict.errorAreaExact == "0") ++t.zeroError;
          if (!verdict.pass) {
            ++t.fails;
            double relative = verdict.relativeError();
            if (family == "bitset-grid") {  // relative to the operands' cell counts, not the answer's
              double cellsS = 0, cellsC = 0;
              for (std::size_t k = 0; k < bits.subject.size(); ++k) cellsS += bits.subject[k], cellsC += bits.clip[k];
              relative = verdict.errorArea / std::max({1.0, cellsS, cellsC});
            }
            if (relative > t.worstRelative) {
              t.worstRelative = relative;
              t.worstCase = std::string(name(op)) + " of `" + io::writeWkt(w.subject) + "` and `" +
                            io::writeWkt(w.clip) + "` (seed " + std::to_string(seed) + ", n " + std::to_string(n) + ")";
            }
            if (t.firstFailure.empty()) {
              t.firstFailure = std::string(name(op)) + " of `" + io::writeWkt(w.subject) + "` and `" + io::writeWkt(w.clip) + "`";
            }
          }
        }
      }
    }
  }
  std::ostringstream md;
  md << "# The exact variant on degenerate input\n\n" << experiments::markdown(experiments::provenance(argc, argv))
     << "\n" << perFamily << " cases per family (seeds 1.." << perFamily << "), each with all five operations, "
     << "clipped by `exact` and by `naive`, every answer judged by the exact oracle (bitset-grid answers "
     << "against the bitwise answer). *fail* = a wrong face outside the rounding zones (or a ClipFailure); "
     << "*error 0* = error area exactly zero.\n\n"
     << "| family | checks | exact: fail | exact: error 0 | exact: filter failures per candidate pair | "
        "naive: fail | naive: ClipFailure | naive: error 0 | naive: worst relative error |\n"
     << "|---|---|---|---|---|---|---|---|---|\n";
  long exactFails = 0, total = 0;
  for (const std::string family : kFamilies) {
    const Tally& e = tallies[family][Variant::Exact];
    const Tally& nv = tallies[family][Variant::Naive];
    exactFails += e.fails;
    total += e.checks;
    md << "| " << family << " | " << e.checks << " | " << e.fails << " | " << e.zeroError << " | "
       << (e.predicateCalls ? static_cast<double>(e.filterFailures) / static_cast<double>(e.predicateCalls) : 0.0)
       << " | " << nv.fails << " | " << nv.clipFailures << " | " << nv.zeroError << " | " << nv.worstRelative << " |\n";
  }
  md << "\n**exact: " << exactFails << " failures in " << total << " checks.**\n";
  md << "\n## The naive variant's worst case per family\n\n";
  for (const std::string family : kFamilies) {
    const Tally& nv = tallies[family][Variant::Naive];
    if (!nv.worstCase.empty()) md << "- **" << family << "** (relative error " << nv.worstRelative << "): " << nv.worstCase << "\n";
  }
  for (const std::string family : kFamilies) {
    const Tally& e = tallies[family][Variant::Exact];
    if (!e.firstFailure.empty()) md << "\nFirst exact failure in " << family << ": " << e.firstFailure << "\n";
  }
  io::writeText((out / "exact-degenerate.md").string(), md.str());
  std::cout << "exact: " << exactFails << " failures in " << total << " checks\n";
  return exactFails == 0 ? 0 : tools::kExitFailed;
}

int main(int argc, char** argv) { return tools::guardedMain("exact_degenerate", argc, argv, run); }
