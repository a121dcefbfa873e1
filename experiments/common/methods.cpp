#include "methods.h"

#include "ghclip/clip.h"
#include "ghio/formats.h"
#include "ghpeers/peer.h"

namespace gh::experiments {

std::vector<Method> allMethods() {
  std::vector<Method> out;
  // Our variants' answers as ghclip writes them by default (docs/semantics.md, "What is written is
  // what is judged"): the OGC layout as WKT, read back.
  for (Variant v : {Variant::Naive, Variant::Sweep, Variant::Exact}) {
    out.push_back({std::string(name(v)), false, [v](const Region& s, const Region& c, Op op) {
                     return io::readWkt(io::writeWkt(gh::clipPolygons(s, c, op, optionsOf(v))));
                   }});
  }
  for (const peers::Peer* p : peers::allPeers()) {
    out.push_back({std::string(p->name()), p->validInputOnly(),
                   [p](const Region& s, const Region& c, Op op) { return p->clip(s, c, op); }});
  }
  return out;
}

std::string outcomeName(Outcome o) {
  switch (o) {
    case Outcome::Exact: return "exact";
    case Outcome::Rounding: return "rounding-level";
    case Outcome::BeyondRounding: return "beyond rounding (rel. <= 1e-6)";
    case Outcome::Gross: return "gross (rel. > 1e-6)";
    case Outcome::Refused: return "refused";
    case Outcome::Failed: return "failed";
    case Outcome::CannotJudge: return "cannot judge";
  }
  return "?";
}

}  // namespace gh::experiments
