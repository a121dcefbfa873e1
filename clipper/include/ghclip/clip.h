// The everyday entry point: gh::clip(subject, clip, op).
//
//   gh::Region r = gh::clip(subject, clip, gh::Op::Intersection);
//
// Semantics: the even-odd interior of the result equals op(interior(subject), interior(clip))
// up to a set of measure zero and the rounding of constructed intersection points to doubles
// (see region.h for the even-odd rule over all rings).
#pragma once

#include "ghclip/operation.h"
#include "ghclip/region.h"
#include "ghclip/stats.h"

namespace gh {

// Which candidate search phase 1 uses; Default is the variant's own (naive: all pairs, as in the
// paper; sweep: the sweep; exact: the sweep when edges are short against the extent of the input,
// all pairs when nearly every pair would be reported anyway). Overriding it isolates the cost of
// the arithmetic policy in benchmarks.
enum class Search { Default, AllPairs, Sweep };

struct Options {
  Variant variant = Variant::Naive;
  Search search = Search::Default;
  // Drop rings with fewer than 3 distinct vertices instead of throwing InvalidInput.
  bool sanitize = false;
};

// Whether this build has the variant (the others throw std::invalid_argument from clip()).
bool isImplemented(Variant variant);

// Throws InvalidInput for bad input and ClipFailure when the algorithm cannot finish.
// Fills *stats when given.
Region clip(const Region& subject, const Region& clip, Op op, const Options& options = {},
            Stats* stats = nullptr);

}  // namespace gh
