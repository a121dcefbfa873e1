#include "sos_predicates.h"

#include <gmpxx.h>

#include "approx.h"

namespace gh::detail::sos {
namespace {

// First non-zero of s0, s1, s2 (the eps expansion).
int leading(int s0, int s1, int s2) { return s0 != 0 ? s0 : s1 != 0 ? s1 : s2; }

// Order of the crossings of line L (a1 -> a2) with lines M (m1, m2) and N (n1, n2) along L. The
// parameter along L at the crossing with M expands as
//   t_M = (A_M + bSign * my * eps + cSign * mx * eps^2) / D_M,
//   A_M = cross(m2 - m1, a1 - m1), D_M = cross(m2 - m1, a1 - a2), (mx, my) = m2 - m1,
// so (t_M - t_N) D_M D_N = F0 + bSign F1 eps + cSign F2 eps^2 with
//   F0 = A_M D_N - A_N D_M,  F1 = my D_N - ny D_M,  F2 = mx D_N - nx D_M.
template <class N>
struct Terms {
  N f0, f1, f2, dM, dN;
};

template <class N>
Terms<N> terms(Point a1, Point a2, Point m1, Point m2, Point n1, Point n2) {
  // The explicit return type matters: with gmpxx, `auto` would return an expression template
  // that refers to this lambda's parameters after they are gone.
  auto cross = [](const N& ux, const N& uy, const N& vx, const N& vy) -> N { return ux * vy - uy * vx; };
  const N mx = N(m2.x) - N(m1.x), my = N(m2.y) - N(m1.y);
  const N nx = N(n2.x) - N(n1.x), ny = N(n2.y) - N(n1.y);
  const N ax = N(a1.x) - N(a2.x), ay = N(a1.y) - N(a2.y);
  const N aM = cross(mx, my, N(a1.x) - N(m1.x), N(a1.y) - N(m1.y));
  const N aN = cross(nx, ny, N(a1.x) - N(n1.x), N(a1.y) - N(n1.y));
  const N dM = cross(mx, my, ax, ay), dN = cross(nx, ny, ax, ay);
  Terms<N> t;
  t.f0 = aM * dN - aN * dM;
  t.f1 = my * dN - ny * dM;
  t.f2 = mx * dN - nx * dM;
  t.dM = dM;
  t.dN = dN;
  return t;
}

int signOf(const mpq_class& q) { return sgn(q); }

// sign(t_M - t_N) with the expansion's sign conventions: bSign, cSign multiply the B and C terms.
int compare(Point a1, Point a2, Point m1, Point m2, Point n1, Point n2, int bSign, int cSign) {
  const Terms<Approx> t = terms<Approx>(a1, a2, m1, m2, n1, n2);
  int s0 = certainSign(t.f0), s1 = certainSign(t.f1), s2 = certainSign(t.f2);
  int sm = certainSign(t.dM), sn = certainSign(t.dN);
  if (s0 == 2 || sm == 2 || sn == 2 || (s0 == 0 && (s1 == 2 || (s1 == 0 && s2 == 2)))) {
    ++exactFallbacks();
    const Terms<mpq_class> x = terms<mpq_class>(a1, a2, m1, m2, n1, n2);
    s0 = signOf(x.f0), s1 = signOf(x.f1), s2 = signOf(x.f2), sm = signOf(x.dM), sn = signOf(x.dN);
  }
  // t_M - t_N = (F0 + bSign F1 eps + cSign F2 eps^2) / (D_M D_N)
  const int lead = leading(s0, bSign * s1, cSign * s2);
  return lead * sm * sn;
}

}  // namespace

Sign clipEdgeSide(Point q1, Point q2, Point p) { return clipEdgeSide(orientation(q1, q2, p), q1, q2); }

Sign subjectEdgeSide(Point p1, Point p2, Point q) { return subjectEdgeSide(orientation(p1, p2, q), p1, p2); }

bool cross(Point p1, Point p2, Point q1, Point q2) {
  if (clipEdgeSide(q1, q2, p1) == clipEdgeSide(q1, q2, p2)) return false;
  return subjectEdgeSide(p1, p2, q1) != subjectEdgeSide(p1, p2, q2);
}

int compareAlongSubject(Point p1, Point p2, Point q1, Point q2, Point r1, Point r2) {
  // Parameter along p of the crossing with clip edge q: (O(q1,q2,p1) + dy_q eps - dx_q eps^2) / D_q
  // with D_q = O(q1,q2,p1) - O(q1,q2,p2) = cross(q2 - q1, p1 - p2): B = +dy, C = -dx.
  return compare(p1, p2, q1, q2, r1, r2, +1, -1);
}

int compareAlongClip(Point q1, Point q2, Point p1, Point p2, Point s1, Point s2) {
  // Parameter along q of the crossing with subject edge p: (O(p1,p2,q1) - dy_p eps + dx_p eps^2)
  // / D_p with D_p = cross(p2 - p1, q1 - q2). O(p1,p2,q1) = cross(p2 - p1, q1 - p1) is the same
  // cross product shape as along the subject edge, with the roles of the lines swapped: B = -dy,
  // C = +dx.
  return compare(q1, q2, p1, p2, s1, s2, -1, +1);
}

bool subjectPointInsideClip(Point p, const Point* v, const std::uint32_t* next, std::size_t n) {
  // Translated clip: q.y + eps^2 > p.y  <=>  q.y >= p.y.
  bool inside = false;
  for (std::size_t e = 0; e < n; ++e) {
    const Point a = v[e], b = v[next[e]];
    const bool aAbove = a.y >= p.y, bAbove = b.y >= p.y;
    if (aAbove == bAbove) continue;
    // The ray to +x crosses edge ab iff p lies on the left of the upward-directed edge.
    const Sign side = clipEdgeSide(a, b, p);
    if (bAbove ? side == Sign::Positive : side == Sign::Negative) inside = !inside;
  }
  return inside;
}

bool clipPointInsideSubject(Point q, const Point* v, const std::uint32_t* next, std::size_t n) {
  // Translated point: p.y > q.y + eps^2  <=>  p.y > q.y.
  bool inside = false;
  for (std::size_t e = 0; e < n; ++e) {
    const Point a = v[e], b = v[next[e]];
    const bool aAbove = a.y > q.y, bAbove = b.y > q.y;
    if (aAbove == bAbove) continue;
    const Sign side = subjectEdgeSide(a, b, q);
    if (bAbove ? side == Sign::Positive : side == Sign::Negative) inside = !inside;
  }
  return inside;
}

}  // namespace gh::detail::sos
