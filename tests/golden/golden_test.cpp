// Pins every variant's crossings and answers to golden data (golden_cases.h says what and why).
//   golden_tests --write FILE   writes the data as this code computes it instead of testing
// (only for a deliberate change: then mark each changed line with its reason, see the file).
#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>
#include <fstream>
#include <map>
#include <sstream>

#include "arithmetic/exact_arithmetic.h"
#include "arithmetic/paper_arithmetic.h"
#include "ghclip/clip.h"
#include "ghclip/errors.h"
#include "ghwork/generators.h"
#include "golden_cases.h"
#include "paper_perturbation.h"
#include "phase1_intersections.h"
#include "search/all_pairs_search.h"
#include "search/search_choice.h"
#include "search/sweep_search.h"

namespace gh::golden {
namespace {

using namespace detail;

// Phase 1 as gh::clip runs it for the variant (the same search choice).
Phase1Result phase1(Variant v, const Region& s, const Region& c, Stats& stats) {
  Operand S(s, false), C(c, false);
  ExactCounters counters;
  if (v == Variant::Exact) {
    const ExactArithmetic exact(counters);
    if (sweepPays(S, C)) return findIntersections(std::move(S), std::move(C), SweepSearch{}, exact, stats);
    return findIntersections(std::move(S), std::move(C), AllPairsSearch{}, exact, stats);
  }
  const PaperArithmetic paper(counters);
  if (v == Variant::Sweep) return findIntersectionsPerturbed(std::move(S), std::move(C), SweepSearch{}, paper, stats);
  return findIntersectionsPerturbed(std::move(S), std::move(C), AllPairsSearch{}, paper, stats);
}

// "<count> <fingerprint>" of the crossings in order along the subject, then along the clip, and
// the number of perturbed vertices.
std::string crossingsLine(Variant v, const work::Workload& w) {
  try {
    Stats stats;
    const Phase1Result r = phase1(v, w.subject, w.clip, stats);
    Fingerprint f;
    for (std::size_t i = 0; i < r.crossingCount(); ++i) {
      f.add(std::uint64_t{r.subjectEdge(i)}), f.add(std::uint64_t{r.clipEdge(i)}), f.add(r.point(i));
    }
    for (std::size_t j = 0; j < r.crossingCount(); ++j) {
      const std::uint32_t id = r.clipOrder(j);
      f.add(std::uint64_t{r.clipEdge(id)}), f.add(std::uint64_t{r.subjectEdge(id)});
    }
    std::ostringstream s;
    s << r.crossingCount() << " " << std::hex << f.value() << std::dec << " perturbations=" << stats.perturbations;
    return s.str();
  } catch (const ClipFailure&) {
    return "failed";
  } catch (const InvalidInput&) {
    return "invalid";
  }
}

std::string answerLine(Variant v, const work::Workload& w, Op op) {
  try {
    const Region r = clip(w.subject, w.clip, op, optionsOf(v));
    std::ostringstream s;
    s << r.size() << " " << std::hex << fingerprint(r);
    return s.str();
  } catch (const ClipFailure&) {
    return "failed";
  } catch (const InvalidInput&) {
    return "invalid";
  }
}

constexpr Variant kVariants[] = {Variant::Naive, Variant::Sweep, Variant::Exact};

// Every line of one case: "<variant> <workload> <n> <seed> <what> <value>".
std::vector<std::pair<std::string, std::string>> linesOf(const Case& c) {
  std::vector<std::pair<std::string, std::string>> out;
  const work::Workload w = work::generate(c.workload, c.n, c.seed);
  for (Variant v : kVariants) {
    const std::string k = key(std::string(name(v)), c);
    out.push_back({k + " crossings", crossingsLine(v, w)});
    for (Op op : c.ops) out.push_back({k + " " + std::string(name(op)), answerLine(v, w, op)});
  }
  return out;
}

// The golden file: "<key> <what> | <value>[ | <reason for a deliberate change>]".
std::map<std::string, std::string> readGolden() {
  std::ifstream in(GHCLIP_GOLDEN_FILE);
  std::map<std::string, std::string> out;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const auto bar = line.find(" | ");
    if (bar == std::string::npos) continue;
    const auto reason = line.find(" | ", bar + 3);
    out[line.substr(0, bar)] = line.substr(bar + 3, reason == std::string::npos ? std::string::npos : reason - bar - 3);
  }
  return out;
}

// Cases grouped so that ctest runs the groups in parallel.
std::vector<Case> group(const std::string& name) {
  std::vector<Case> out;
  for (const Case& c : cases()) {
    const std::string g = c.workload == "random" ? "random_" + std::to_string(c.n) : c.n == 200 ? "realistic" : "degenerate";
    if (g == name) out.push_back(c);
  }
  return out;
}

class Golden : public ::testing::TestWithParam<std::string> {};

TEST_P(Golden, CrossingsAndAnswersAsPinned) {
  static const auto golden = readGolden();
  ASSERT_FALSE(golden.empty()) << "no golden data at " << GHCLIP_GOLDEN_FILE;
  int compared = 0;
  for (const Case& c : group(GetParam())) {
    for (const auto& [k, value] : linesOf(c)) {
      const auto it = golden.find(k);
      ASSERT_NE(it, golden.end()) << "no golden line for " << k;
      EXPECT_EQ(value, it->second) << k;
      ++compared;
    }
  }
  EXPECT_GT(compared, 0);
}

INSTANTIATE_TEST_SUITE_P(Pools, Golden,
                         ::testing::Values("random_10", "random_20", "random_50", "random_100", "random_200",
                                           "random_500", "random_1000", "random_2000", "degenerate", "realistic"));

int write(const char* path) {
  std::ofstream out(path);
  out << "# Golden data of tests/golden/golden_test.cpp: \"<variant> <workload> <n> <seed> <what> | <value>\",\n"
         "# <what> = crossings (count, fingerprint, perturbed vertices) or an operation (rings, fingerprint).\n"
         "# A third field \"| reason\" marks a deliberate change from the data first written (by the code before\n"
         "# issue 15), with the old value and the exact oracle's verdict on both answers.\n";
  for (const Case& c : cases()) {
    for (const auto& [k, value] : linesOf(c)) out << k << " | " << value << "\n";
  }
  out.close();
  if (!out) {
    std::cerr << "golden_tests: cannot write " << path << "\n";
    return 2;
  }
  return 0;
}

}  // namespace
}  // namespace gh::golden

int main(int argc, char** argv) {
  if (argc == 3 && std::string(argv[1]) == "--write") return gh::golden::write(argv[2]);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
