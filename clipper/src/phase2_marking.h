// Phase 2 of Greiner-Hormann (paper, Section 4.2, Figure 9): where does each ring start, inside or
// outside the other operand, and which intersection vertices are entries and which exits.
//
// The first vertex of every ring is located in the other operand by the arithmetic policy's
// even-odd point-in-region test (the library's one ray test, decided exactly, under Simulation of
// Simplicity for the exact policy). Rings that cross nothing are then kept or dropped whole by
// phase 3; on the others, the walk from the first vertex marks the intersection vertices
// alternately entry and exit.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "parallel.h"
#include "predicates/exact_counters.h"
#include "search/edge_slabs.h"
#include "vertex_graph.h"

namespace gh::detail {

// Sets RingInfo::startsInside of every ring of both operands. Many rings against many edges are
// located through slabs of the other operand's edges (search/edge_slabs.h), in pieces over
// `threads`; a few rings by a pass over all edges.
template <class Arithmetic>
void locateRingStarts(VertexGraph& graph, const Arithmetic& arithmetic, unsigned threads = 1) {
  auto locate = [&](std::vector<RingInfo>& rings, const Operand& own, const Operand& other, bool ownIsSubject) {
    const bool indexed = rings.size() > 8 && rings.size() * other.size() > (std::size_t{1} << 16);
    const std::unique_ptr<EdgeSlabs> slabs = indexed ? std::make_unique<EdgeSlabs>(other) : nullptr;
    const Pieces pieces = piecesFor(rings.size(), threads, 64);
    std::vector<ExactCounters> counters(pieces.pieces);
    runPieces(pieces, threads, [&](std::size_t p) {
      const Arithmetic local(counters[p]);
      for (std::size_t r = pieces.begin(p); r < pieces.end(p); ++r) {
        const Point v = own.vertices[rings[r].firstVertex];
        const std::uint32_t* edges = nullptr;
        std::size_t count = other.size();
        if (slabs) {
          const auto [first, last] = slabs->near(v.y);
          edges = first, count = static_cast<std::size_t>(last - first);
        }
        rings[r].startsInside = ownIsSubject ? local.subjectPointInsideClip(v, other, edges, count)
                                             : local.clipPointInsideSubject(v, other, edges, count);
      }
    });
    for (const ExactCounters& c : counters) arithmetic.counters() += c;
  };
  locate(graph.subjectRings, *graph.subject, *graph.clip, true);
  locate(graph.clipRings, *graph.clip, *graph.subject, false);
}

// Marks every intersection vertex entry (the piece after it lies inside the other operand) or
// exit, alternately along each ring from its located start.
void markEntryExit(VertexGraph& graph);

}  // namespace gh::detail
