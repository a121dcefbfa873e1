// Replays every stored counterexample (tests/regressions/properties/<variant>/: shrunk
// counterexamples of the property suite, copied there from a run's output, and hand-added cases)
// through its property. A case whose (variant, property, family)
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
  for (const auto& e : fs::recursive_directory_iterator(GHCLIP_REGRESSIONS)) {
    if (e.path().extension() == ".wkt") out.push_back(e.path());
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
