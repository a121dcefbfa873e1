// The property suite as plain functions: each returns a description of the violation, or
// nothing when the property holds. RapidCheck drives them (property_suite_test.cpp) and the
// regression test replays stored counterexamples through the same functions.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "generators.h"
#include "ghclip/operation.h"
#include "ghclip/options.h"
#include "property_case.h"

namespace gh::props {

using Violation = std::optional<std::string>;
using Property = std::function<Violation(const PropertyCase&, Variant)>;

struct PropertySpec {
  std::string name;     // e.g. "oracle_passes"
  std::string family;   // random | grid | family | bitset (the generator it runs on)
  Property check;
};

// Every (property, family) pair of the suite.
const std::vector<PropertySpec>& suite();
const PropertySpec* findSpec(const std::string& name, const std::string& family);

// The bitset answer check, which needs the bitsets themselves.
Violation bitsetExact(const BitsetCase& c, Variant variant);

}  // namespace gh::props
