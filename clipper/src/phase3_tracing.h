// Phase 3 of Greiner-Hormann (Figure 10): trace the result by walking from intersection vertex
// to intersection vertex, switching operands at each one, the entry flag choosing the direction.
// Union and the differences flip the flags of one or both operands (Figure 5); xor is the two
// differences traced one after the other. Rings that cross nothing are kept or dropped by the
// point-in-region test of their first vertex.
#pragma once

#include "ghclip/operation.h"
#include "flat_rings.h"
#include "ghclip/region.h"
#include "vertex_graph.h"

namespace gh::detail {

// Appends the answer's rings to `out`. Throws ClipFailure if a trace does not close within a
// bound of twice the node count, or reaches an intersection vertex a previous trace used
// (inconsistent entry/exit marks).
// With `lines`, also appends for every point the operand edge the answer's edge from it runs along
// (subject edges numbered first, then the clip's: traceLineOf), with kTracedCrossing set when the
// point is an intersection vertex: the answer's provenance, which the OGC layout nodes with.
void traceResult(VertexGraph& graph, Op op, FlatRings& out, unsigned threads = 1,
                 std::vector<std::uint32_t>* lines = nullptr);
inline constexpr std::uint32_t kTracedCrossing = 0x80000000u;

// The same as a Region (for tests).
Region traceResult(VertexGraph& graph, Op op);

}  // namespace gh::detail
