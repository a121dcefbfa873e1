// A certified upper bound, in doubles, on the area of the symmetric difference of two regions
// that differ only near some of their vertices, as two answers to one problem do: what the
// differential fuzz target asks of almost every pair, without an arrangement.
#pragma once

#include <optional>

#include "ghclip/region.h"

namespace gh::oracle {

// An upper bound on the even-odd area of a XOR b (see the .cpp for why it holds), or nothing
// where a product overflows.
// Both regions normalized as the exact oracle does (rings with fewer than 3 distinct vertices
// dropped); a non-finite coordinate throws InvalidInput.
std::optional<double> symmetricDifferenceBound(const Region& a, const Region& b);

}  // namespace gh::oracle
