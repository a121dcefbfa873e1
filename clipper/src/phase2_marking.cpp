#include "phase2_marking.h"

namespace gh::detail {

void markEntryExit(VertexGraph& g) {
  for (const auto* rings : {&g.subjectRings, &g.clipRings}) {
    for (const RingInfo& ring : *rings) {
      if (ring.head == kNone) continue;
      bool status = !ring.startsInside;  // entry when starting outside
      std::uint32_t n = ring.head;
      do {
        g.nodes[n].entry = status;
        status = !status;
        n = g.nodes[n].next;
      } while (n != ring.head);
    }
  }
}

}  // namespace gh::detail
