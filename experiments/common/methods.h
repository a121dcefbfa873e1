// Everything experiments compare, behind one call: our variants and the peer libraries.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "ghclip/operation.h"
#include "ghclip/region.h"

namespace gh::experiments {

struct Method {
  std::string name;           // "naive", "sweep", "exact", "clipper6", "geos", "boost", "cgal"
  bool validInputOnly = false;  // GEOS, Boost and CGAL
  // Throws peers::PeerRefusal (input not accepted), gh::ClipFailure (gave up), or anything else.
  std::function<Region(const Region&, const Region&, Op)> clip;
};

// Our implemented variants first (their answers as written: the OGC layout as WKT, read back),
// then the peers (their answers as they give them).
std::vector<Method> allMethods();

// How one answer fared against the exact oracle.
enum class Outcome {
  Exact,           // error area exactly 0
  Rounding,        // 0 < error area, every wrong face within the rounding zones (a pass)
  BeyondRounding,  // a wrong face outside them, relative error <= 1e-6
  Gross,           // relative error > 1e-6
  Refused,         // the method does not accept this input
  Failed,          // it threw (ClipFailure or another exception)
  CannotJudge,     // the oracle could not decide (counted apart: neither right nor wrong)
};
inline constexpr Outcome kOutcomes[] = {Outcome::Exact,  Outcome::Rounding, Outcome::BeyondRounding,
                                        Outcome::Gross,  Outcome::Refused,  Outcome::Failed,
                                        Outcome::CannotJudge};
std::string outcomeName(Outcome o);

}  // namespace gh::experiments
