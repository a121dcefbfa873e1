// Vocabulary types of ghclip: points, rings and regions.
//
// A Region is any number of closed rings. Its interior is the even-odd rule over all rings
// together: a point not on any edge is inside iff a ray from it crosses the region's edges an odd
// number of times (Greiner & Hormann 1998, Section 2, extended to several rings). Holes and
// multipolygons therefore need no structure of their own: a hole is just another ring.
#pragma once

#include <vector>

namespace gh {

struct Point {
  double x = 0;
  double y = 0;
};

inline bool operator==(const Point& a, const Point& b) { return a.x == b.x && a.y == b.y; }
inline bool operator!=(const Point& a, const Point& b) { return !(a == b); }

// A closed polygon; the closing edge from the last vertex back to the first is implied.
// Any orientation; it may self-intersect, touch itself and repeat vertices.
using Ring = std::vector<Point>;

// Any number of rings, interior by the even-odd rule over all of them.
using Region = std::vector<Ring>;

}  // namespace gh
