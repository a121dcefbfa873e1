// Workload generators, deterministic by seed, in one place for tests, fuzzers and experiments.
//
//   random       the paper's (Section 6): n vertices uniform in the unit square, joined in order
//   simple       simple polygons: star-shaped by angle (even seeds) or random points untangled by
//                2-opt (odd seeds)
//   grid         n vertices on the integer grid 0..8 joined in order: shared vertices,
//                vertex-on-edge, collinear overlaps and identical rings are frequent
//   identical, shared-edge, touching-vertex, nested-touching, sliver, sub-boundary
//                the named degenerate families (integer coordinates)
//   bitset-grid  unions of unit cells of a random bitset on a k x k grid (one ring per cell; the
//                even-odd rule cancels the shared edges): the exact answer of every operation is
//                the bitwise AND / OR / AND-NOT / XOR of the bitsets
//   circles      two perturbed circles of n vertices crossing twice (realistic)
//   coastline    two star-shaped fractal outlines of n vertices (realistic)
//   holes        a shell with several hole rings, against another one
//   pie          n triangles sharing the origin (a pie chart) against the pie turned by pi / n: many
//                edges through one point
//   flower       n kite-shaped petals sharing the origin against another flower, turned
//   archipelago  islands holding lakes holding islets, about n vertices in n / 15 rings, against
//                another archipelago shifted by less than a cell: many rings, few crossings
//   mixed-magnitude  a triangle of size 2^10..2^480 with an edge through the origin, holding a
//                star hole of size 2^-300..1 just above it, against a star of that small size
//                crossing the edge and the hole (valid polygons)
// A suffix picks a near-degenerate variant of any workload:
//   +ulp   every coordinate moved by one ulp up or down
//   +tiny  scaled by 2^-997 (about 1e-300)      +huge  scaled by a power of two to about 1e150
//   +far   translated by (1e9, 1e9)
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ghclip/region.h"

namespace gh::work {

struct Workload {
  Region subject;
  Region clip;
};

// All base workload names, and all variant suffixes.
const std::vector<std::string>& workloadNames();
const std::vector<std::string>& variantSuffixes();

// Generates "NAME" or "NAME+SUFFIX" with about n vertices per operand (at least what the shape
// needs). Throws std::invalid_argument for an unknown name, and for a suffix that collapses a ring
// of the workload (mixed-magnitude's small star near 1e-300 or at 1e9: below the doubles there).
Workload generate(const std::string& name, std::size_t n, std::uint64_t seed);

// The bitset behind a bitset-grid workload, for its exact answer.
struct BitsetGrid {
  int size = 0;                  // k: cells are [i, i+1] x [j, j+1], 0 <= i, j < k
  std::vector<bool> subject, clip;  // cell (i, j) at index j * k + i
};
BitsetGrid bitsetGrid(std::size_t n, std::uint64_t seed);
Region cellsRegion(const BitsetGrid& grid, const std::vector<bool>& cells);

// The paper's random ring, and an integer-grid ring (building blocks, also used directly).
Ring randomRing(std::size_t n, std::uint64_t seed);
Ring gridRing(std::size_t n, int gridSize, std::uint64_t seed);

}  // namespace gh::work
