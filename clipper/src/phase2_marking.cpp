#include "phase2_marking.h"

namespace gh::detail {

void markEntryExit(VertexGraph& g) {
  for (const auto* rings : {&g.subjectRings, &g.clipRings}) {
    for (const RingInfo& ring : *rings) {
      if (ring.head == kNone) continue;
      // Entry when starting outside, then alternately exit and entry along the ring.
      std::uint8_t status = ring.startsInside ? 0 : 1;
      for (std::uint32_t n = ring.head; n < ring.endNode; ++n, status ^= 1) g.node(n).entry = status;
    }
  }
}

}  // namespace gh::detail
