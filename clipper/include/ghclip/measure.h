// Measurements of regions in floating point (the exact ones live in the oracles). evenOddArea and
// insideEvenOdd throw InvalidInput for a non-finite coordinate.
#pragma once

#include "ghclip/region.h"

namespace gh {

// Area of the even-odd interior of a region, whatever its rings do (self-intersections,
// overlapping rings, holes). Slab decomposition at every vertex and edge-edge crossing:
// O((V + X) * V) for V vertices and X crossings, so meant for tests and tools, not hot paths.
double evenOddArea(const Region& region);

// Signed shoelace area of one ring (counter-clockwise positive).
double signedArea(const Ring& ring);

// Even-odd point-in-region by ray crossing; a point on an edge gets an arbitrary answer.
bool insideEvenOdd(const Region& region, Point p);

// Total number of vertices.
std::size_t vertexCount(const Region& region);

}  // namespace gh
