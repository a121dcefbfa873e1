// Replays every stored counterexample (results/counterexamples/<variant>/ and the hand-added
// tests/properties/regressions/) through its property. A case whose (variant, property, family)
// is an expected failure must still fail: if it passes, the variant was fixed and the entry in
// expected_failures.txt must go. Any other case must pass: it is a fixed bug's regression test.
#include <gtest/gtest.h>

#include <filesystem>

#include "counterexamples.h"
#include "ghclip/clip.h"
#include "properties.h"

namespace gh::props {
namespace {
namespace fs = std::filesystem;

std::vector<fs::path> caseFiles() {
  std::vector<fs::path> out;
  for (const char* root : {GHCLIP_STORED_COUNTEREXAMPLES, GHCLIP_REGRESSIONS}) {
    if (!fs::exists(root)) continue;
    for (const auto& e : fs::recursive_directory_iterator(root)) {
      // The robustness study keeps its smallest failing cases beside these (robustness-*.wkt):
      // they are a record of what each method does, not property counterexamples.
      if (e.path().filename().string().rfind("robustness-", 0) == 0) continue;
      if (e.path().extension() == ".wkt") out.push_back(e.path());
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(StoredCounterexamples, ReplayAsRecorded) {
  const auto expected = expectedFailures(GHCLIP_EXPECTED_FAILURES);
  int replayed = 0;
  for (const fs::path& file : caseFiles()) {
    const Counterexample c = readCounterexample(file);
    const auto variant = parseVariant(c.variant);
    ASSERT_TRUE(variant.has_value()) << file;
    if (!isImplemented(*variant)) continue;
    Violation v;
    if (c.property == "bitset_exact") {
      ASSERT_TRUE(c.bitset.has_value()) << file;
      v = bitsetExact(*c.bitset, *variant);
    } else {
      const PropertySpec* spec = findSpec(c.property, c.family);
      ASSERT_NE(spec, nullptr) << file << ": unknown property " << c.property << "/" << c.family;
      v = spec->check(c.input, *variant);
    }
    const ExpectedFailure* known = findExpected(expected, c.variant, c.property, c.family);
    if (known) {
      EXPECT_TRUE(v.has_value()) << file << " now passes: remove '" << c.variant << " " << c.property << " "
                                 << c.family << "' from expected_failures.txt";
    } else {
      EXPECT_FALSE(v.has_value()) << file << ": " << v.value_or("");
    }
    ++replayed;
  }
  RecordProperty("replayed", replayed);
  std::cout << "replayed " << replayed << " stored counterexamples\n";
}

// Every expected failure has its counterexample on file.
TEST(StoredCounterexamples, EveryExpectedFailureHasOne) {
  const auto expected = expectedFailures(GHCLIP_EXPECTED_FAILURES);
  const auto files = caseFiles();
  for (const ExpectedFailure& e : expected) {
    if (!isImplemented(*parseVariant(e.variant))) continue;
    bool found = false;
    for (const fs::path& f : files) {
      const Counterexample c = readCounterexample(f);
      found |= c.variant == e.variant && c.property == e.property && c.family == e.family;
    }
    EXPECT_TRUE(found) << "no counterexample on file for expected failure " << e.variant << " " << e.property
                       << " " << e.family;
    EXPECT_FALSE(e.reason.empty()) << e.variant << " " << e.property << ": give a one-line reason";
  }
}

}  // namespace
}  // namespace gh::props
