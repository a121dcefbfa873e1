// The everyday entry point: gh::clip(subject, clip, op).
//
//   gh::Region r = gh::clip(subject, clip, gh::Op::Intersection);          // exact arithmetic
//   gh::Options paper;
//   paper.arithmetic = gh::Arithmetic::Paper;                               // the paper's doubles
//   gh::Region p = gh::clip(subject, clip, gh::Op::Union, paper);
//   gh::Region n = gh::clip(subject, clip, gh::Op::Xor, gh::optionsOf(gh::Variant::Naive));
//
// Semantics: the even-odd interior of the result equals op(interior(subject), interior(clip))
// up to a set of measure zero and the rounding of constructed intersection points to doubles
// (see region.h for the even-odd rule over all rings). With the default exact arithmetic this
// holds for every valid input; the paper arithmetic moves degenerate vertices by 2^-42 of the
// largest coordinate and can give up (ClipFailure).
#pragma once

#include "ghclip/ogc_layout.h"
#include "ghclip/operation.h"
#include "ghclip/options.h"
#include "ghclip/region.h"
#include "ghclip/stats.h"

namespace gh {

// Throws InvalidInput for bad input and ClipFailure when the algorithm cannot finish (the paper
// arithmetic only). Fills *stats when given.
Region clip(const Region& subject, const Region& clip, Op op, const Options& options = {},
            Stats* stats = nullptr);

// The same answer as OGC polygons with holes (ogc_layout.h): what the tools write by default.
// Throws as clip() does, and LayoutRefusal where no faithful rounding keeps the pieces apart.
std::vector<PolygonWithHoles> clipPolygons(const Region& subject, const Region& clip, Op op, const Options& options = {},
                                           Stats* stats = nullptr, LayoutStats* layout = nullptr);

}  // namespace gh
