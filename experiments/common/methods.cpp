#include "methods.h"

#include "ghclip/clip.h"
#include "ghpeers/peer.h"

namespace gh::experiments {

std::vector<Method> allMethods() {
  std::vector<Method> out;
  for (Variant v : {Variant::Naive, Variant::Sweep, Variant::Exact}) {
    out.push_back({std::string(name(v)), false, [v](const Region& s, const Region& c, Op op) {
                     Options o = optionsOf(v);
                     return gh::clip(s, c, op, o);
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
