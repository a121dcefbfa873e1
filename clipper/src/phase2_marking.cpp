#include "phase2_marking.h"

namespace gh::detail {

void markEntryExit(VertexGraph& g) {
  for (const auto* rings : {&g.subjectRings, &g.clipRings}) {
    for (const RingInfo& ring : *rings) {
      if (ring.head == kNone) continue;
      // Entry when starting outside, then alternately exit and entry along the ring.
      bool status = !ring.startsInside;
      for (std::uint32_t n = ring.head; n < ring.endNode; ++n, status = !status) g.node(n).setEntry(status);
    }
  }
}

}  // namespace gh::detail
