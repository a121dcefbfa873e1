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

#include "vertex_graph.h"

namespace gh::detail {

// Sets RingInfo::startsInside of every ring of both operands.
template <class Arithmetic>
void locateRingStarts(VertexGraph& graph, const Arithmetic& arithmetic) {
  for (RingInfo& ring : graph.subjectRings) {
    ring.startsInside = arithmetic.subjectVertexInsideClip(*graph.subject, ring.firstVertex, *graph.clip);
  }
  for (RingInfo& ring : graph.clipRings) {
    ring.startsInside = arithmetic.clipVertexInsideSubject(*graph.clip, ring.firstVertex, *graph.subject);
  }
}

// Marks every intersection vertex entry (the piece after it lies inside the other operand) or
// exit, alternately along each ring from its located start.
void markEntryExit(VertexGraph& graph);

}  // namespace gh::detail
