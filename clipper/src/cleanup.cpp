#include "cleanup.h"

#include "orientation.h"

namespace gh::detail {
namespace {

void dropRepeatedPoints(Ring& ring) {
  Ring kept;
  kept.reserve(ring.size());
  for (const Point& p : ring) {
    if (kept.empty() || kept.back() != p) kept.push_back(p);
  }
  while (kept.size() > 1 && kept.back() == kept.front()) kept.pop_back();
  ring.swap(kept);
}

bool allCollinear(const Ring& ring) {
  // ring[0] != ring[1] after dropRepeatedPoints, so they span a line.
  for (std::size_t i = 2; i < ring.size(); ++i) {
    if (orientation(ring[0], ring[1], ring[i]) != Sign::Zero) return false;
  }
  return true;
}

}  // namespace

Region cleanedUp(Region region) {
  Region out;
  out.reserve(region.size());
  for (Ring& ring : region) {
    dropRepeatedPoints(ring);
    if (ring.size() >= 3 && !allCollinear(ring)) out.push_back(std::move(ring));
  }
  return out;
}

}  // namespace gh::detail
