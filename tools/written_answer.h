// The answer as the tools write it, in one place: ghclip's output, and what the test that judges
// every written answer reads back (tests/tools/written_answers_test.cpp), so that the test judges
// what a user gets.
//
// --layout ogc: the library's polygons (ghclip/ogc_layout.h), from the operand edges the answer runs
// along; a snap-rounded layout (features finer than the doubles) is judged by the exact oracle as
// written before it is returned (requireWithinRounding). --layout rings: the clip's rings.
#pragma once

#include <string>
#include <vector>

#include "ghclip/clipping.h"
#include "ghclip/ogc_layout.h"
#include "ghclip/polygons_with_holes.h"
#include "ghclip/stats.h"
#include "ghio/formats.h"

namespace gh::tools {

struct WrittenAnswer {
  std::string text;                         // the bytes written
  std::vector<PolygonWithHoles> polygons;   // --layout ogc
  Region rings;                             // --layout rings; for ogc the polygons' rings (pictures)
  Stats stats;
  LayoutStats layout;    // --layout ogc
  double formatSeconds = 0;  // the text made from the answer (a snap-rounded layout's judging too)
};

// Throws what Clipping::polygons and result throw, and LayoutRefusal when a snap-rounded layout
// fails the exact oracle.
WrittenAnswer writtenAnswer(Clipping& clipping, const Region& subject, const Region& clip, Op op, io::Format format,
                            io::Layout layout);
// The same for rings computed elsewhere (a peer's answer), which know nothing of their lines.
WrittenAnswer writtenAnswer(Region rings, const Region& subject, const Region& clip, Op op, io::Format format,
                            io::Layout layout);

}  // namespace gh::tools
