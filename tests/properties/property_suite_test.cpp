// The property suite: every (property, workload family) pair for every implemented variant,
// driven by RapidCheck (RC_PARAMS sets max_success and seed; ctest fixes the seed).
// A failure's shrunk counterexample is written with writeCounterexample(). A pair listed in
// expected_failures.txt is a known violation of that variant: its run reports what it found
// instead of failing, and the replay test insists that its stored counterexample still fails.
#include <gtest/gtest.h>
#include <rapidcheck.h>

#include "counterexamples.h"
#include "ghclip/clip.h"
#include "properties.h"

namespace gh::props {
namespace {

struct Param {
  Variant variant;
  std::string property, family;
};

void PrintTo(const Param& p, std::ostream* os) { *os << name(p.variant) << "/" << p.property << "/" << p.family; }

rc::Gen<PropertyCase> generatorFor(const std::string& family) {
  if (family == "random") return randomCase();
  if (family == "grid") return gridCase();
  return familyCase();
}

const std::vector<ExpectedFailure>& expected() {
  static const auto list = expectedFailures(GHCLIP_EXPECTED_FAILURES);
  return list;
}

// Runs RapidCheck on one property; returns the shrunk counterexample if it failed.
template <class Case, class Gen, class Check>
std::optional<std::pair<Case, std::string>> findCounterexample(const std::string& label, Gen gen, Check check) {
  std::optional<std::pair<Case, std::string>> last;
  const bool ok = rc::check(label, [&] {
    const Case c = *gen;
    const Violation v = check(c);
    // While RapidCheck shrinks, the last failing input it tries is the smallest it found.
    if (v) last = std::make_pair(c, *v);
    RC_ASSERT(!v);
  });
  if (ok) return std::nullopt;
  return last;
}

void report(const Param& p, const std::optional<Counterexample>& found) {
  const ExpectedFailure* known = findExpected(expected(), std::string(name(p.variant)), p.property, p.family);
  if (!found) {
    if (known) std::cout << "[expected failure not hit in this run] " << known->reason << "\n";
    return;
  }
  const auto file = writeCounterexample(*found);
  if (known) {
    std::cout << "[expected failure] " << known->reason << "\n  counterexample: " << file.string() << "\n";
  } else {
    ADD_FAILURE() << p.property << " (" << p.family << ") fails for " << name(p.variant) << ": "
                  << found->violation << "\n  shrunk counterexample: " << file.string();
  }
}

class PropertySuite : public testing::TestWithParam<Param> {};

TEST_P(PropertySuite, Holds) {
  const Param p = GetParam();
  const PropertySpec* spec = findSpec(p.property, p.family);
  ASSERT_NE(spec, nullptr);
  const auto found = findCounterexample<PropertyCase>(
      p.property + "/" + p.family + "/" + std::string(name(p.variant)), generatorFor(p.family),
      [&](const PropertyCase& c) { return spec->check(c, p.variant); });
  std::optional<Counterexample> ce;
  if (found) ce = Counterexample{p.property, p.family, std::string(name(p.variant)), found->second, found->first, {}};
  report(p, ce);
}

class BitsetSuite : public testing::TestWithParam<Variant> {};

TEST_P(BitsetSuite, ResultsEqualTheBitwiseAnswerExactly) {
  const Variant v = GetParam();
  const auto found = findCounterexample<BitsetCase>(
      "bitset_exact/" + std::string(name(v)), bitsetCase(), [&](const BitsetCase& c) { return bitsetExact(c, v); });
  std::optional<Counterexample> ce;
  if (found) {
    ce = Counterexample{"bitset_exact", "bitset", std::string(name(v)), found->second, found->first.asCase(),
                        found->first};
  }
  report({v, "bitset_exact", "bitset"}, ce);
}

std::vector<Variant> variants() {
  std::vector<Variant> out;
  for (Variant v : {Variant::Naive, Variant::Sweep, Variant::Exact}) {
    out.push_back(v);
  }
  return out;
}

std::vector<Param> params() {
  std::vector<Param> out;
  for (Variant v : variants()) {
    for (const PropertySpec& s : suite()) out.push_back({v, s.name, s.family});
  }
  return out;
}

std::string paramName(const testing::TestParamInfo<Param>& info) {
  return std::string(name(info.param.variant)) + "_" + info.param.property + "_" + info.param.family;
}

INSTANTIATE_TEST_SUITE_P(Properties, PropertySuite, testing::ValuesIn(params()), paramName);
INSTANTIATE_TEST_SUITE_P(Properties, BitsetSuite, testing::ValuesIn(variants()),
                         [](const testing::TestParamInfo<Variant>& i) { return std::string(name(i.param)); });

}  // namespace
}  // namespace gh::props
