// The answer's rings as phase 3 traces them, with what the trace knows of every edge: the operand
// edge it runs along (phase3_tracing.h), as the OGC layout takes them (ghclip/lined_rings.h).
#pragma once

#include <cstdint>
#include <vector>

#include "flat_rings.h"
#include "ghclip/lined_rings.h"
#include "operand.h"
#include "predicates/exact_counters.h"

namespace gh::detail {

// traced and its lines as traceResult gives them. An intersection vertex is exact when it is an
// input vertex: the limit of the exact arithmetic's crossing of edges that meet at an endpoint
// (construction.h gives that vertex itself); otherwise it is the crossing of its two edges' lines.
LinedRings tracedLines(const FlatRings& traced, const std::vector<std::uint32_t>& lines, const Operand& subject,
                       const Operand& clip, ExactCounters& counters);

}  // namespace gh::detail
