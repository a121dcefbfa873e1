// Several operations on one pair, with the work they share done once.
//
//   gh::Clipping pair(subject, clip);             // validation, phases 1 and 2
//   gh::Region both = pair.result(gh::Op::Intersection);
//   gh::Region either = pair.result(gh::Op::Union);  // phase 3 and clean-up only
//
// Phases 1 and 2 of the paper (the crossings, the ring starts and the entry/exit marks) do not
// depend on the operation: union and the differences only flip the marks' meaning when tracing
// (Section 4.3, Figure 5). result(op) is clip(subject, clip, op, options) bit for bit, whatever
// the order and number of calls.
#pragma once

#include <memory>

#include "ghclip/ogc_layout.h"
#include "ghclip/operation.h"
#include "ghclip/options.h"
#include "ghclip/region.h"
#include "ghclip/stats.h"

namespace gh {

class Clipping {
 public:
  // Throws InvalidInput for bad input, and ClipFailure when the paper arithmetic's perturbation
  // gives up (as clip() would for every operation).
  Clipping(const Region& subject, const Region& clip, const Options& options = {});
  ~Clipping();
  Clipping(Clipping&&) noexcept;
  Clipping& operator=(Clipping&&) noexcept;

  // Throws ClipFailure when tracing cannot finish (the paper arithmetic only). Fills *stats as
  // clip() would: the shared phases' counts and times, and this operation's phase 3.
  Region result(Op op, Stats* stats = nullptr);
  // The answer as polygons with holes (ogc_layout.h): from the traced rings and the operand edges
  // they run along, for the exact arithmetic; from result(op)'s rings for the paper's. Throws
  // LayoutRefusal where no faithful rounding keeps the pieces apart.
  std::vector<PolygonWithHoles> polygons(Op op, Stats* stats = nullptr, LayoutStats* layout = nullptr);

 private:
  struct Prepared;
  std::unique_ptr<Prepared> prepared_;
};

}  // namespace gh
