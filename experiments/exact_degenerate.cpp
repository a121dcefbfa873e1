// The exact variant on degenerate input, beside the naive variant: integer-grid n-gons and every
// named degenerate family, all five operations, judged by the exact oracle; and bitset-grid cases
// whose answers must equal the bitwise answer with error area exactly 0.
// Writes OUT_DIR/exact-degenerate.md; with --shard K/M, the raw tallies of a part of the seeds as
// OUT_DIR/exact-degenerate-shard-K-of-M.json, which --merge turns into the same report.
//   exact_degenerate OUT_DIR [CASES] [--shard K/M | --merge FILES...]
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include "common/provenance.h"
#include "common/shard.h"
#include "ghclip/clip.h"
#include "ghclip/errors.h"
#include "ghio/formats.h"
#include "ghio/output_files.h"
#include "ghoracle/exact_oracle.h"
#include "ghwork/generators.h"
#include "tool_main.h"

namespace fs = std::filesystem;
using namespace gh;

namespace {

// Where a case comes in one run's order (seed, then operation): what decides which of two
// equally bad cases a merge of shards reports, as one run would have.
long orderOf(long seed, std::size_t opIndex) { return seed * 5 + static_cast<long>(opIndex); }

struct Tally {
  long checks = 0, fails = 0, clipFailures = 0, zeroError = 0;
  double worstRelative = 0;
  std::string worstCase;  // the input and operation of the worst relative error
  long worstOrder = 0;
  unsigned long long filterFailures = 0, predicateCalls = 0;
  std::string firstFailure;
  long firstOrder = 0;

  void merge(const Tally& o) {
    checks += o.checks, fails += o.fails, clipFailures += o.clipFailures, zeroError += o.zeroError;
    filterFailures += o.filterFailures, predicateCalls += o.predicateCalls;
    if (!o.worstCase.empty() && (o.worstRelative > worstRelative || (o.worstRelative == worstRelative && (worstCase.empty() || o.worstOrder < worstOrder)))) {
      worstRelative = o.worstRelative, worstCase = o.worstCase, worstOrder = o.worstOrder;
    }
    if (!o.firstFailure.empty() && (firstFailure.empty() || o.firstOrder < firstOrder)) {
      firstFailure = o.firstFailure, firstOrder = o.firstOrder;
    }
  }
};
void to_json(nlohmann::json& j, const Tally& t) {
  j = {{"checks", t.checks}, {"fails", t.fails}, {"clip_failures", t.clipFailures}, {"zero_error", t.zeroError},
       {"worst_relative", t.worstRelative}, {"worst_case", t.worstCase}, {"worst_order", t.worstOrder},
       {"filter_failures", t.filterFailures}, {"predicate_calls", t.predicateCalls},
       {"first_failure", t.firstFailure}, {"first_order", t.firstOrder}};
}
void from_json(const nlohmann::json& j, Tally& t) {
  j.at("checks").get_to(t.checks), j.at("fails").get_to(t.fails), j.at("clip_failures").get_to(t.clipFailures);
  j.at("zero_error").get_to(t.zeroError), j.at("worst_relative").get_to(t.worstRelative);
  j.at("worst_case").get_to(t.worstCase), j.at("worst_order").get_to(t.worstOrder);
  j.at("filter_failures").get_to(t.filterFailures), j.at("predicate_calls").get_to(t.predicateCalls);
  j.at("first_failure").get_to(t.firstFailure), j.at("first_order").get_to(t.firstOrder);
}

// The named degenerate families, bitset grids, and the grid class at the ends of the double range
// (scaled by 2^-997 and to ~2^497, moved by 1e9) and mixed magnitudes.
const char* kFamilies[] = {"grid", "identical", "shared-edge", "touching-vertex", "nested-touching", "sliver",
                           "sub-boundary", "bitset-grid", "grid+tiny", "grid+huge", "grid+far", "mixed-magnitude"};

using Tallies = std::map<std::string, std::map<Variant, Tally>>;  // [family][variant]

void study(Tallies& tallies, long perFamily, const experiments::Shard& shard, const std::vector<Variant>& variants) {
  for (const std::string family : kFamilies) {
    for (long i = 0; i < perFamily; ++i) {
      const auto seed = static_cast<std::uint64_t>(i + 1);
      if (!shard.takes(i + 1)) continue;
      const std::size_t n = family == "bitset-grid" ? 8 + static_cast<std::size_t>(i % 40)
                                                    : 3 + static_cast<std::size_t>(i % 10);
      const work::Workload w = work::generate(family, n, seed);
      const work::BitsetGrid bits = family == "bitset-grid" ? work::bitsetGrid(n, seed) : work::BitsetGrid{};
      for (Variant v : variants) {
        Tally& t = tallies[family][v];
        // The five answers first, then judged: together in one arrangement, except bitset grids,
        // whose answers are compared with the bitwise answer of each operation.
        std::vector<oracle::Answer> answers;
        std::vector<bool> failed;
        for (Op op : kAllOps) {
          Stats stats;
          Region r;
          try {
            Options o = optionsOf(v);
            r = clip(w.subject, w.clip, op, o, &stats);
            failed.push_back(false);
          } catch (const ClipFailure& e) {
            failed.push_back(true);
          }
          t.filterFailures += stats.filterFailures;
          t.predicateCalls += stats.candidatePairs;
          answers.push_back({op, std::move(r)});
        }
        std::vector<oracle::ExactVerdict> verdicts;
        if (family == "bitset-grid") {
          for (const oracle::Answer& a : answers) {
            std::vector<bool> cells(bits.subject.size());
            for (std::size_t k = 0; k < cells.size(); ++k) cells[k] = apply(a.op, bits.subject[k], bits.clip[k]);
            verdicts.push_back(oracle::exactCheck(work::cellsRegion(bits, cells), {}, Op::Union, a.result, {false, false, true}));
          }
        } else {
          verdicts = oracle::exactCheckAll(w.subject, w.clip, answers, {false, false, true});
        }
        for (std::size_t opIndex = 0; opIndex < answers.size(); ++opIndex) {
          const Op op = answers[opIndex].op;
          ++t.checks;
          if (failed[opIndex]) {
            ++t.clipFailures, ++t.fails;
            continue;
          }
          const oracle::ExactVerdict& verdict = verdicts[opIndex];
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
              t.worstOrder = orderOf(i + 1, opIndex);
            }
            if (t.firstFailure.empty()) {
              t.firstFailure = std::string(name(op)) + " of `" + io::writeWkt(w.subject) + "` and `" + io::writeWkt(w.clip) + "`";
              t.firstOrder = orderOf(i + 1, opIndex);
            }
          }
        }
      }
    }
  }
}

}  // namespace

int run(int argc, char** argv) {
  CLI::App app{"The exact variant on degenerate input beside the naive variant, judged by the exact oracle."};
  std::string outDir, shardText;
  long cases = 10000;
  std::vector<std::string> mergeFiles;
  app.add_option("OUT_DIR", outDir, "directory for exact-degenerate.md (or a shard's JSON)")->required();
  app.add_option("CASES", cases, "cases in all, shared by the families (default 10000)")->check(CLI::PositiveNumber);
  app.add_option("--shard", shardText, "K/M: only seeds s with (s - 1) mod M = K - 1; write OUT_DIR/exact-degenerate-shard-K-of-M.json");
  app.add_option("--merge", mergeFiles, "shard JSON files: write the report of all of them together")->excludes("--shard");
  bool exactOnly = false;
  app.add_flag("--exact-only", exactOnly, "clip with the exact variant only (the naive columns stay empty)");
  if (const auto exitCode = tools::parseCommandLine(app, "exact_degenerate", argc, argv)) return *exitCode;
  const std::vector<Variant> variants = exactOnly ? std::vector<Variant>{Variant::Exact} : std::vector<Variant>{Variant::Naive, Variant::Exact};
  experiments::Shard shard;
  if (!shardText.empty()) {
    const auto parsed = experiments::parseShard(shardText);
    if (!parsed) return tools::usageError("exact_degenerate", "--shard wants K/M with 1 <= K <= M, got '" + shardText + "'");
    shard = *parsed;
  }
  const fs::path out = outDir;
  fs::create_directories(out);
  Tallies tallies;
  long perFamily = cases / static_cast<long>(std::size(kFamilies));
  if (!mergeFiles.empty()) {
    std::set<int> seen;
    int of = 0;
    long perFamilyOfAll = -1;
    for (const std::string& file : mergeFiles) {
      try {
        const nlohmann::json j = nlohmann::json::parse(io::readText(file));
        const int k = j.at("shard").get<int>(), m = j.at("shards").get<int>();
        const long each = j.at("cases_per_family").get<long>();
        if (perFamilyOfAll >= 0 && (each != perFamilyOfAll || m != of)) {
          throw tools::BadInput(file + ": a shard of another study");
        }
        if (!seen.insert(k).second) throw tools::BadInput(file + ": shard " + std::to_string(k) + " given twice");
        perFamilyOfAll = each, of = m;
        for (const nlohmann::json& t : j.at("tallies")) {
          const std::string family = t.at("family").get<std::string>();
          const std::string variant = t.at("variant").get<std::string>();
          const auto v = parseVariant(variant);
          if (!v || std::none_of(std::begin(kFamilies), std::end(kFamilies), [&](const char* f) { return family == f; })) {
            throw tools::BadInput(file + ": unknown family or variant");
          }
          tallies[family][*v].merge(t.at("tally").get<Tally>());
        }
      } catch (const nlohmann::json::exception& e) {
        throw tools::BadInput(file + ": not an exact-degenerate shard (" + e.what() + ")");
      }
    }
    if (static_cast<int>(seen.size()) != of) {
      throw tools::BadInput("--merge: " + std::to_string(seen.size()) + " of " + std::to_string(of) + " shards given");
    }
    perFamily = perFamilyOfAll;
  } else {
    study(tallies, perFamily, shard, variants);
  }
  long exactFails = 0, total = 0;
  for (const std::string family : kFamilies) {
    exactFails += tallies[family][Variant::Exact].fails;
    total += tallies[family][Variant::Exact].checks;
  }
  if (!shardText.empty()) {
    nlohmann::json j{{"shard", shard.k}, {"shards", shard.m}, {"cases_per_family", perFamily}, {"tallies", nlohmann::json::array()}};
    for (const auto& [family, byVariant] : tallies) {
      for (const auto& [v, t] : byVariant) j["tallies"].push_back({{"family", family}, {"variant", std::string(name(v))}, {"tally", t}});
    }
    const fs::path file = out / ("exact-degenerate-" + shard.fileSuffix());
    io::writeText(file.string(), j.dump(1));
    std::cout << "wrote " << file.string() << "; exact: " << exactFails << " failures in " << total << " checks\n";
    return exactFails == 0 ? 0 : tools::kExitFailed;
  }
  bool withNaive = false;
  for (const auto& [family, byVariant] : tallies) withNaive |= byVariant.count(Variant::Naive) && byVariant.at(Variant::Naive).checks > 0;
  std::ostringstream md;
  md << "# The exact variant on degenerate input\n\n" << experiments::markdown(experiments::provenance(argc, argv))
     << "\n" << perFamily << " cases per family (seeds 1.." << perFamily << "), each with all five operations, "
     << (withNaive ? "clipped by `exact` and by `naive`" : "clipped by `exact` (the naive variant not run: `--exact-only`)")
     << ", every answer judged by the exact oracle (bitset-grid answers "
     << "against the bitwise answer). *fail* = a wrong face outside the rounding zones (or a ClipFailure); "
     << "*error 0* = error area exactly zero.\n\n"
     << "| family | checks | exact: fail | exact: error 0 | exact: filter failures per candidate pair |"
     << (withNaive ? " naive: fail | naive: ClipFailure | naive: error 0 | naive: worst relative error |" : "") << "\n"
     << "|---|---|---|---|---|" << (withNaive ? "---|---|---|---|" : "") << "\n";
  for (const std::string family : kFamilies) {
    const Tally& e = tallies[family][Variant::Exact];
    const Tally& nv = tallies[family][Variant::Naive];
    md << "| " << family << " | " << e.checks << " | " << e.fails << " | " << e.zeroError << " | "
       << (e.predicateCalls ? static_cast<double>(e.filterFailures) / static_cast<double>(e.predicateCalls) : 0.0) << " |";
    if (withNaive) md << " " << nv.fails << " | " << nv.clipFailures << " | " << nv.zeroError << " | " << nv.worstRelative << " |";
    md << "\n";
  }
  md << "\n**exact: " << exactFails << " failures in " << total << " checks.**\n";
  if (withNaive) md << "\n## The naive variant's worst case per family\n\n";
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
