// Pins what the clip targets' judges find (fuzz/clip_target.h: clipAndJudge) on committed fuzz
// inputs, for every variant: a judge made faster must find the same on each of them ("no check
// weakened", issue 19), and one that finds more or less says so in this file's diff.
//   judge_verdicts_tests --write FILE [DIR...]   writes the pins as this code computes them, for
//       the inputs already pinned, every seed and regression input of the clip targets, and the
//       fuzz inputs in each DIR (a grown corpus), each input once.
// Each line: the input in hex, then per variant (naive, sweep, exact) the five operations'
// findings in kAllOps order, "." for none, else a letter per finding in the order found:
// F ClipFailure, N non-finite output, I an invariant violated, S the sampling oracle disagrees;
// "refused" when the input is invalid (InvalidInput).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "clip_target.h"
#include "judge_pins.h"

namespace gh::fuzz {
namespace {

namespace fs = std::filesystem;
using Bytes = std::vector<std::uint8_t>;

constexpr Variant kVariants[] = {Variant::Naive, Variant::Sweep, Variant::Exact};
const char* const kTargets[] = {"fuzz_clip_naive", "fuzz_clip_sweep", "fuzz_clip_exact"};

// The findings of one variant on one input, as pinned.
std::string verdictOf(const Bytes& input, Variant variant) {
  const ClipOutcome outcome = clipAndJudge(clipPair(input.data(), input.size()), variant);
  if (outcome.refused) return "refused";
  std::string out;
  for (Op op : kAllOps) {
    std::string letters;
    for (const ClipFinding& f : outcome.findings) {
      if (f.op != op) continue;
      switch (f.kind) {
        case ClipFinding::Kind::ClipFailure: letters += 'F'; break;
        case ClipFinding::Kind::NonFinite: letters += 'N'; break;
        case ClipFinding::Kind::Invariant: letters += 'I'; break;
        case ClipFinding::Kind::Sampling: letters += 'S'; break;
        case ClipFinding::Kind::Layout: letters += 'L'; break;
      }
    }
    if (!out.empty()) out += ',';
    out += letters.empty() ? "." : letters;
  }
  return out;
}

std::string verdictsOf(const Bytes& input) {
  std::string out;
  for (Variant v : kVariants) out += " | " + verdictOf(input, v);
  return out;
}

std::vector<JudgePin> readPins() { return readJudgePins(GHCLIP_JUDGE_VERDICTS_FILE); }

Bytes readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return Bytes(std::istreambuf_iterator<char>(in), {});
}

// Every seed and regression input of the clip targets, in a fixed order.
std::vector<Bytes> committedInputs() {
  std::vector<fs::path> files;
  for (const char* target : kTargets) {
    for (const fs::path& dir : {fs::path(GHCLIP_SOURCE_DIR) / "fuzz" / (std::string(target) + "_seed_corpus"),
                                fs::path(GHCLIP_SOURCE_DIR) / "tests" / "regressions" / "fuzz" / target}) {
      if (!fs::is_directory(dir)) continue;
      for (const auto& entry : fs::directory_iterator(dir)) files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  std::vector<Bytes> inputs;
  for (const fs::path& f : files) inputs.push_back(readFile(f));
  return inputs;
}

TEST(JudgeVerdicts, EverySeedAndRegressionInputIsPinned) {
  std::set<std::string> pinned;
  for (const JudgePin& pin : readPins()) pinned.insert(pin.hex);
  const std::vector<Bytes> inputs = committedInputs();
  ASSERT_FALSE(inputs.empty());
  for (const Bytes& input : inputs) {
    EXPECT_TRUE(pinned.count(hexOf(input))) << "a seed or regression input of a clip target is not pinned in "
                                            << GHCLIP_JUDGE_VERDICTS_FILE << " (judge_verdicts_tests --write): "
                                            << hexOf(input).substr(0, 64);
  }
}

TEST(JudgeVerdicts, EachVariantFindsWhatIsPinned) {
  const std::vector<JudgePin> pins = readPins();
  ASSERT_GE(pins.size(), 1000u) << "pins at " << GHCLIP_JUDGE_VERDICTS_FILE;
  std::size_t differ = 0, findings = 0;
  for (const JudgePin& pin : pins) {
    const std::string now = verdictsOf(bytesOfHex(pin.hex));
    findings += static_cast<std::size_t>(std::count_if(now.begin(), now.end(), [](char c) { return c >= 'A' && c <= 'Z'; }));
    if (now == pin.verdicts) continue;
    if (++differ <= 10) {
      ADD_FAILURE() << "input " << pin.hex.substr(0, 48) << "...: pinned" << pin.verdicts << ", found now" << now;
    }
  }
  EXPECT_EQ(differ, 0u) << "of " << pins.size() << " inputs";
  // The pins are worth something only if the naive and sweep variants' answers fail on many of
  // them: a judge that found nothing would differ there.
  EXPECT_GE(findings, pins.size()) << "findings over all inputs and variants";
}

// The boundary certificate lets the exact target skip the sampling oracle for answers it proves
// right (boundary_certificate.h): on every pinned input and every variant's answers (the naive
// and sweep variants' are wrong on most), the sampling oracle, as the clip targets run it but
// never stopping early, passes every answer the certificate proves. And it proves the exact
// variant's five answers on most pinned inputs, or the exact target would be sampling again.
TEST(JudgeVerdicts, TheSamplingOraclePassesEveryCertifiedAnswer) {
  const std::vector<JudgePin> pins = readPins();
  ASSERT_GE(pins.size(), 1000u);
  oracle::SampleOptions full = clipTargetSampling();
  full.stopWhenAllFail = false;
  std::size_t certified = 0, refuted = 0, exactExecutions = 0, exactProved = 0;
  for (const JudgePin& pin : pins) {
    const Bytes input = bytesOfHex(pin.hex);
    const Pair p = clipPair(input.data(), input.size());
    for (Variant variant : kVariants) {
      ClipOutcome outcome;
      const std::vector<std::pair<Op, Region>> answers = clipFive(p, variant, outcome);
      if (answers.empty()) continue;
      std::vector<std::pair<Op, const Region*>> judged;
      for (const auto& [op, r] : answers) judged.emplace_back(op, &r);
      const std::vector<bool> proved = oracle::certifiedAnswers(p.subject, p.clip, judged);
      if (variant == Variant::Exact && answers.size() == std::size(kAllOps)) {
        ++exactExecutions;
        exactProved += std::all_of(proved.begin(), proved.end(), [](bool b) { return b; });
      }
      if (std::none_of(proved.begin(), proved.end(), [](bool b) { return b; })) continue;
      const auto verdicts = oracle::SamplingJudge(p.subject, p.clip, full).check(judged);
      for (std::size_t i = 0; i < answers.size(); ++i) {
        if (!proved[i]) continue;
        ++certified;
        if (verdicts[i].pass()) continue;
        if (++refuted <= 10) ADD_FAILURE() << "certified, yet the sampling oracle disagrees: " << name(answers[i].first) << ", input " << pin.hex.substr(0, 48) << "...";
      }
    }
  }
  std::cout << certified << " answers certified, " << refuted << " refuted; the exact variant's five on " << exactProved
            << " of " << exactExecutions << " executions\n";
  EXPECT_EQ(refuted, 0u) << "of " << certified << " certified answers";
  EXPECT_GE(certified, pins.size()) << "answers certified over all inputs and variants";
  EXPECT_GE(exactProved * 10, exactExecutions * 9) << exactProved << " of " << exactExecutions << " exact executions certified";
}

int write(const std::string& file, const std::vector<std::string>& dirs) {
  std::vector<std::string> order;
  std::set<std::string> seen;
  auto add = [&](const Bytes& input) {
    const std::string hex = hexOf(input);
    if (seen.insert(hex).second) order.push_back(hex);
  };
  for (const JudgePin& pin : readPins()) add(bytesOfHex(pin.hex));
  for (const Bytes& input : committedInputs()) add(input);
  for (const std::string& dir : dirs) {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(dir)) files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    for (const fs::path& f : files) add(readFile(f));
  }
  const std::string partial = file + ".partial";  // renamed over file once whole
  std::ofstream out(partial);
  out << "# Pins of tests/golden/judge_verdicts_test.cpp (what each line means: its first comment).\n"
         "# <input in hex> | <naive> | <sweep> | <exact>, each the five operations' findings in kAllOps order.\n"
         "# Inputs: the clip targets' seeds and regressions, and corpora grown by the targets (the commits\n"
         "# that added them say which). Written by judge_verdicts_tests --write; never edited by hand.\n";
  for (const std::string& hex : order) out << hex << verdictsOf(bytesOfHex(hex)) << '\n';
  out.close();
  std::error_code renamed;
  if (out) fs::rename(partial, file, renamed);
  if (!out || renamed) {
    std::cerr << "judge_verdicts_tests: cannot write " << file << '\n';
    fs::remove(partial, renamed);
    return 2;
  }
  std::cout << order.size() << " inputs pinned in " << file << '\n';
  return 0;
}

}  // namespace
}  // namespace gh::fuzz

int main(int argc, char** argv) {
  if (argc >= 3 && std::string(argv[1]) == "--write") {
    return gh::fuzz::write(argv[2], std::vector<std::string>(argv + 3, argv + argc));
  }
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
