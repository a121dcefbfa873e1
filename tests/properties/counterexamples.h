// Counterexample files: a failing property's shrunk case, written as WKT with a header, and an
// SVG beside it; replayed under ctest as regression cases.
//
//   # property: oracle_passes
//   # family: grid
//   # variant: naive
//   # op: union
//   # bitset: 3 101001110 011000111     (bitset family only: k, subject bits, clip bits)
//   # violation: exact oracle: error area ...
//   MULTIPOLYGON(...)                    subject
//   MULTIPOLYGON(...)                    clip
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "generators.h"
#include "property_case.h"

namespace gh::props {

struct Counterexample {
  std::string property, family, variant, violation;
  PropertyCase input;
  std::optional<BitsetCase> bitset;
};

// Where counterexamples are written: $GHCLIP_COUNTEREXAMPLES, else ./counterexamples.
std::filesystem::path counterexampleDir();

// Writes <dir>/<variant>/<property>-<family>-<hash>.wkt and .svg; returns the .wkt path.
std::filesystem::path writeCounterexample(const Counterexample& c);

Counterexample readCounterexample(const std::filesystem::path& file);

// tests/properties/expected_failures.txt: "variant property family | reason" per line.
struct ExpectedFailure {
  std::string variant, property, family, reason;
};
std::vector<ExpectedFailure> expectedFailures(const std::filesystem::path& file);
const ExpectedFailure* findExpected(const std::vector<ExpectedFailure>& list, const std::string& variant,
                                    const std::string& property, const std::string& family);

}  // namespace gh::props
