// The exact arrangement oracle: the judge every claim of this project rests on.
//
// One CGAL arrangement (exact rational arithmetic: doubles convert exactly) of every segment of
// the subject S, the clip C and a candidate result R; each arrangement edge knows how many S, C
// and R segments run along it (overlaps count with multiplicity). Parities propagate from the
// unbounded face: crossing an edge toggles a region's parity by the count of its segments there.
// A face is wrong when parity_R != op(parity_S, parity_C); the error area is the exact total area
// of the wrong faces.
//
// What a correct double answer may get wrong: its constructed vertices. Each vertex of the
// arrangement of S and C that is not a double (a crossing) must be rounded, and a correct answer
// rounds it faithfully (each coordinate to one of the two doubles around it; `constructionUlps`
// widens that). A candidate's edges run along the lines of S and C between such vertices and
// may pass straight over some (Greiner-Hormann's rings pass through the operands'
// self-crossings, peers drop collinear vertices), so each maximal straight line of S and C gets
// a *rounding zone*: the convex hull of the rounding boxes of all vertices on it. Boxes are
// computed from each vertex's own magnitude, so a unit square next to 1e15 coordinates is judged
// at the unit square's resolution. A wrong face inside the zones is rounding; a wrong face
// outside them (anywhere at all, at any magnitude) fails the answer. Input vertices get no box,
// so a moved input vertex, a dropped ring or a confused operation fails whatever its size. The
// verdict is therefore topological and exact: no area is compared with a tolerance.
//
// No CGAL in this header: the oracle is one translation unit.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "ghclip/lined_rings.h"
#include "ghclip/operation.h"
#include "ghclip/region.h"

namespace gh::oracle {

// The judge could not decide (a CGAL failure or out of memory): tools exit 3, studies count it
// apart. Never a pass, never a fail.
class CannotJudge : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ExactVerdict {
  bool pass = false;            // no wrong face outside the rounding zones (exact, topological)
  double expectedArea = 0;      // area of op(S, C): midpoint of a certified interval
  double resultArea = 0;        // even-odd area of R, likewise
  double subjectArea = 0;       // even-odd areas of the operands, likewise
  double clipArea = 0;
  double boxArea = 0;           // area of the bounding box of S and C
  double areaUncertainty = 0;   // width of those intervals (the true values lie within)
  double errorArea = 0;         // area of the symmetric difference of R and op(S, C)
  double beyondRoundingArea = 0;  // the part of it outside the rounding zones (0 iff pass)
  std::string errorAreaExact;   // the exact rational "p/q" of errorArea (with exactErrorArea)
  std::string beyondRoundingAreaExact;  // likewise
  std::optional<Point> witness;  // inside the largest wrong face beyond rounding (or, when
                                 // the answer passes with rounding, the largest wrong face)
  Region expected;              // boundary of op(S, C), points rounded to double
  Region wrong;                 // boundary of the wrong faces, for pictures
  std::size_t faces = 0, vertices = 0, edges = 0;
  std::size_t zones = 0;        // rounding zones it took to excuse the wrong faces
  double seconds = 0;

  double relative = 0;          // see relativeError()
  double relativeBeyond = 0;    // see relativeBeyondRounding()
  // errorArea relative to the largest of the operands', expected and result areas (a scale that
  // stays meaningful when the expected answer is empty), or to the bounding box of S and C when
  // all of those vanish (operands of zero area).
  double relativeError() const;
  // beyondRoundingArea on the same scale (both decided where no area underflows: at 1e-200
  // coordinates the areas themselves may print as 0, these do not).
  double relativeBeyondRounding() const;
};

struct ExactOptions {
  bool wantExpectedRings = true;
  bool wantWrongRings = true;
  // Sum the wrong faces in exact rationals (errorAreaExact, beyondRoundingAreaExact). Without it
  // the areas are midpoints of certified intervals; the verdict is exact either way.
  bool exactErrorArea = true;
  // The expected, result and operand areas summed in exact rationals too, each rounded once
  // (what the tools print); without it they are midpoints of certified intervals.
  bool exactAreas = false;
  // How far a constructed vertex may be from its exact crossing: 1 = a faithful rounding (each
  // coordinate one of the two doubles around the exact one); k > 1 widens that by k - 1 ulps of
  // the coordinate itself on each side.
  int constructionUlps = 1;
};

// Judges R as an answer to op(S, C). Non-finite coordinates throw gh::InvalidInput; rings of
// fewer than 3 distinct vertices are ignored (they bound nothing). Throws CannotJudge when the
// arrangement cannot be built.
ExactVerdict exactCheck(const Region& subject, const Region& clip, Op op, const Region& result,
                        const ExactOptions& options = {});

// Several answers for the same S and C (the five operations, or several clippers' answers),
// judged in one arrangement of S, C and all of them: the arrangement of S and C, the costly part,
// is built once. Each verdict is the one exactCheck gives for that answer alone (the faces are
// cut finer by the other answers' edges, the wrong region and the zones are the same). At most
// 30 answers.
struct Answer {
  Op op;
  Region result;
};
std::vector<ExactVerdict> exactCheckAll(const Region& subject, const Region& clip, const std::vector<Answer>& answers,
                                        const ExactOptions& options = {});

// For each pair (a, b), the even-odd area of their symmetric difference, all pairs in one
// arrangement of the segments that a and b do not share: what exactCheck(a, {}, Op::Union, b)
// calls errorArea. Within 1e-9 of it, relatively: the midpoint of a certified interval where
// that is so tight, else the exact area rounded (a sliver's interval can be wider than itself).
// At most 15 pairs.
std::vector<double> symmetricDifferenceAreas(const std::vector<std::pair<Region, Region>>& pairs);

// For each pair (a, b), whether the area of their symmetric difference is at most limits[i],
// decided exactly (certified intervals first; exact arithmetic only where an interval holds the
// limit). At most 15 pairs; a NaN limit is refused (std::invalid_argument).
std::vector<bool> symmetricDifferencesWithin(const std::vector<std::pair<Region, Region>>& pairs,
                                             const std::vector<double>& limits);

// The exact answer's boundary rings (points rounded to double: a faithful rounding).
Region exactAnswer(const Region& subject, const Region& clip, Op op);

// The same boundary as rings that know their lines (ghclip/lined_rings.h): every edge on a segment
// of S or C, every corner an input double or the crossing of its two edges' lines (rounded to the
// nearest double), for the OGC layout (ghclip/ogc_layout.h): what ghcheck --expected writes.
LinedRings exactAnswerLines(const Region& subject, const Region& clip, Op op);

// The exact even-odd area of a region, as a rational "p/q", and its rounding to double.
struct ExactArea {
  std::string rational;
  double value = 0;
};
ExactArea exactArea(const Region& region);

// Whether two regions have exactly the same even-odd area.
bool sameExactArea(const Region& a, const Region& b);

}  // namespace gh::oracle
