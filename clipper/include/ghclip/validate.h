// Input checking and normalisation, the first thing every clip does.
#pragma once

#include "ghclip/region.h"

namespace gh {

// Largest accepted |coordinate|: 2^500 (about 3.3e150). Products of coordinate differences,
// (2^501)^2 = 2^1002, and sums of a few such products stay finite in double arithmetic.
inline constexpr double kMaxCoordinate = 0x1p500;

enum class OnBadRing {
  Throw,  // a ring with fewer than 3 distinct vertices is bad input
  Drop,   // ...or is dropped silently (sanitize)
};

// Drops consecutive duplicate vertices (including a closing vertex equal to the first), then
// checks every ring. Throws InvalidInput naming the ring and vertex for a non-finite coordinate,
// a coordinate beyond kMaxCoordinate, or (with OnBadRing::Throw) a ring with fewer than 3
// distinct vertices. An empty region is valid: it is the empty set.
Region normalized(const Region& region, OnBadRing onBadRing = OnBadRing::Throw);

namespace detail {
// The pieces of normalized(), for code that validates while copying into its own layout.
// Throws InvalidInput naming ring r for a non-finite or too large coordinate.
void checkCoordinates(const Ring& ring, std::size_t r);
bool hasThreeDistinct(const Point* begin, const Point* end);
[[noreturn]] void throwTooFewVertices(std::size_t r);
}  // namespace detail

}  // namespace gh
