// The exact arrangement oracle: the judge every claim of this project rests on.
//
// One CGAL arrangement (exact rational arithmetic: doubles convert exactly) of every segment of
// the subject S, the clip C and a candidate result R; each arrangement edge knows how many S, C
// and R segments run along it (overlaps count with multiplicity). Parities propagate from the
// unbounded face: crossing an edge toggles a region's parity by the count of its segments there.
// A face is wrong when parity_R != op(parity_S, parity_C); the error area is the exact total area
// of the wrong faces. No CGAL in this header: the oracle is one translation unit.
#pragma once

#include <optional>
#include <string>

#include "ghclip/operation.h"
#include "ghclip/region.h"

namespace gh::oracle {

struct ExactVerdict {
  bool pass = false;          // error area <= tolerance, certified (interval or exact)
  double expectedArea = 0;    // area of op(S, C), midpoint of a certified interval
  double resultArea = 0;      // even-odd area of R, likewise
  double subjectArea = 0;     // even-odd areas of the operands, likewise
  double clipArea = 0;
  double boxArea = 0;         // area of the bounding box of S and C
  double areaUncertainty = 0;  // width of those intervals (the true values lie within)
  double errorArea = 0;       // area of the symmetric difference (rounded exact value, or the
                              // midpoint of a certified interval without exactErrorArea)
  double tolerance = 0;       // see tolerance.h
  std::string errorAreaExact;  // the exact rational "p/q" (with exactErrorArea)
  std::optional<Point> witness;  // inside the largest wrong face (rounded to double)
  Region expected;            // boundary of op(S, C), points rounded to double
  Region wrong;               // boundary of the wrong faces, for pictures
  std::size_t faces = 0, vertices = 0, edges = 0;
  double seconds = 0;

  double relative = 0;         // see relativeError()
  // errorArea relative to the largest of the operands', expected and result areas (a scale that
  // stays meaningful when the expected answer is empty), or to the bounding box of S and C when
  // all of those vanish (operands of zero area).
  double relativeError() const;
};

struct ExactOptions {
  bool wantExpectedRings = true;
  bool wantWrongRings = true;
  // Sum the wrong faces in exact rationals even when intervals already decide the verdict
  // (every sliver at a rounded intersection point then needs its exact vertices: 5-10x slower).
  bool exactErrorArea = true;
};

// Judges R as an answer to op(S, C). Non-finite coordinates throw gh::InvalidInput; rings of
// fewer than 3 distinct vertices are ignored (they bound nothing).
ExactVerdict exactCheck(const Region& subject, const Region& clip, Op op, const Region& result,
                        const ExactOptions& options = {});

// The exact answer's boundary rings (points rounded to double).
Region exactAnswer(const Region& subject, const Region& clip, Op op);

}  // namespace gh::oracle
