// The boundary certificate: a proof, where one is cheap to find, that an answer is right up to the
// rounding of its crossings, so that the sampling oracle need not look for a counterexample.
//
// An even-odd region is fixed by its boundary taken mod 2: a point's side is the parity of the
// edges a ray from it crosses, so rings whose edges cover every point of the plane the same number
// of times mod 2 bound the same interior. The certificate builds the boundary of op(S, C)
// exactly: every edge of S and of C is cut where it crosses the other operand, and a piece is kept
// where op differs on its two sides (an edge of S separates "in S" from "not in S" at one side of
// C: the parity of C along the piece, one ray test per ring and a flip at each crossing). C is
// translated by the symbolic (eps, eps^2) first, so that every contact of S and C (a shared vertex,
// a vertex on an edge, an overlap) is a proper crossing or none, decided exactly; as eps -> 0 the
// pieces tend to a boundary of op(S, C) (the limit's interior is op(S, C)'s wherever that is
// defined, and a boundary mod 2 is unique). A crossing at a double point (a vertex of S or C, a
// grid point) is that point. A crossing inside both edges stands for a vertex of the answers that
// lies in both edges' boxes and within 2 ulps of both lines (of the crossing's magnitude, bounded
// by both edges'), which is how a faithful rounding of it lies: the one such vertex; among several
// (crossings a few ulps apart), the one nearest it, or the one in the crossings' order; with none,
// a symbolic end no answer has (an even number of such crossings at one point, which the answers
// pass straight through, is not cut at). An answer is certified when its edges and these pieces
// cover every point equally mod 2, up to slivers within the rounding, decided exactly: equal
// segments cancel; what cancels on its lines goes (every end met an even number of times there);
// and what is left, with no symbolic end, must be a cycle whose fan of triangles from one of its
// vertices lies, triangle by triangle, within 2 ulps of one edge of S or C and inside its box.
//
// What a certificate proves: the answer's interior differs from op(S, C)'s only within 2 ulps of
// edges of S or C and inside their boxes (between a piece and the same piece with rounded ends,
// and in those slivers), where the sampling oracle skips every point (its delta there is 8 ulps of
// the largest crossing on the edge: sampling_oracle.h). So the sampling oracle passes every
// certified answer, and a caller may skip it for those
// (JudgeVerdicts.TheSamplingOraclePassesEveryCertifiedAnswer checks it on the pinned fuzz
// inputs). No certificate proves nothing: a wrong answer gets none, and so may a right one whose
// boundary the certificate does not follow (crossings rounded in a way it does not match); the
// caller samples those. Problems at extreme magnitudes are certified at a comfortable scale
// (judging_scale.h), exactly as the sampling oracle judges them.
#pragma once

#include <utility>
#include <vector>

#include "ghclip/operation.h"
#include "ghclip/region.h"

namespace gh::oracle {

// Per answer (op, answer) for S and C, whether it is certified. Regions with a non-finite
// coordinate get no certificate.
std::vector<bool> certifiedAnswers(const Region& subject, const Region& clip,
                                   const std::vector<std::pair<Op, const Region*>>& answers);

}  // namespace gh::oracle
