#include "ghoracle/exact_orientation.h"

#include "filtered_orientation.h"
#include "rational_orientation.h"

#include <gmp.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>

namespace gh::oracle {
namespace {

// Knuth's two-sum: s + e == a + b exactly, s the rounded sum (no overflow; exact with gradual
// underflow too).
void twoSum(double a, double b, double& s, double& e) {
  s = a + b;
  const double bv = s - a, av = s - bv;
  e = (a - av) + (b - bv);
}

// a - b as a double when that is exact (the two-sum error is zero), else nothing.
bool exactDifference(double a, double b, double& d) {
  double error;
  twoSum(a, -b, d, error);
  return std::isfinite(d) && error == 0;
}

// x * y as a double when that is exact: not overflowed, far from the subnormals (where the fma's
// error would itself be rounded), and the fma's error zero. A zero product is exact only when a
// factor is zero (an underflow also gives zero).
bool exactProduct(double x, double y, double& p) {
  p = x * y;
  if (x == 0 || y == 0) return true;
  return std::isfinite(p) && std::abs(p) > 0x1p-900 && std::fma(x, y, -p) == 0;
}

// A sum of doubles kept exactly as a non-overlapping expansion (Shewchuk, "Adaptive precision
// floating-point arithmetic and fast robust geometric predicates", 1997): components in
// increasing magnitude, zeros left out, so that the sum's sign is its largest component's.
class Expansion {
 public:
  // Grow-Expansion with zero elimination: the expansion stays non-overlapping and increasing for
  // any double added (no overflow).
  void add(double b) {
    double q = b;
    int m = 0;
    for (int i = 0; i < n_; ++i) {
      double sum, error;
      twoSum(q, c_[i], sum, error);
      if (error != 0) c_[m++] = error;
      q = sum;
    }
    if (q != 0) c_[m++] = q;
    n_ = m;
  }
  // x * y exactly, by the fma's error (exact where the caller's range guarantees it).
  void addProduct(double x, double y) {
    if (x == 0 || y == 0) return;
    const double p = x * y;
    add(std::fma(x, y, -p));
    add(p);
  }
  int sign() const { return n_ == 0 ? 0 : c_[n_ - 1] > 0 ? 1 : -1; }

 private:
  double c_[17];  // at most one component per double added: 16 for a determinant, 1 bound
  int n_ = 0;
};

// Whether the expansion stage below is exact for these coordinates: each 0 or of magnitude in
// [2^-480, 2^500]. Then a difference's two parts are at most 2^501 and multiples of 2^-532 (the
// lowest place of the smaller operand), the products of parts at most 2^1002 and multiples of
// 2^-1064, so every fma error is a representable double (exact), nothing overflows, and a
// product rounded into the subnormals has no error at all (it is a multiple of 2^-1064 within
// half of 2^-1074 of a double).
bool inExpansionRange(std::initializer_list<double> xs) {
  for (double x : xs) {
    const double m = std::abs(x);
    if (x != 0 && !(m >= 0x1p-480 && m <= 0x1p500)) return false;
  }
  return true;
}

// (b - a) x (p - a) as an exact expansion: each difference as its rounded value and two-sum error,
// then the sixteen products of their parts, each with its fma error.
Expansion determinantExpansion(Point a, Point b, Point p) {
  double d[4], e[4];
  twoSum(b.x, -a.x, d[0], e[0]);  // bx - ax
  twoSum(p.y, -a.y, d[1], e[1]);  // py - ay
  twoSum(b.y, -a.y, d[2], e[2]);  // by - ay
  twoSum(p.x, -a.x, d[3], e[3]);  // px - ax
  Expansion det;
  for (double l : {d[0], e[0]}) {
    for (double r : {d[1], e[1]}) det.addProduct(l, r);
  }
  for (double l : {d[2], e[2]}) {
    for (double r : {d[3], e[3]}) det.addProduct(-l, r);
  }
  return det;
}

// Each non-zero double is m 2^(e - 53) with m an integer of at most 53 bits: the smallest such
// e - 53 among xs, the place of their lowest bit (0 when all are 0).
int lowestPlace(std::initializer_list<double> xs) {
  int lowest = 0;
  bool any = false;
  for (double x : xs) {
    if (x == 0) continue;
    int e = 0;
    std::frexp(x, &e);
    lowest = any ? std::min(lowest, e - 53) : e - 53, any = true;
  }
  return lowest;
}

// x 2^-lowest, an integer when lowest is at most x's lowest place, into out.
void setOverPowerOfTwo(mpz_t out, double x, int lowest) {
  int e = 0;
  mpz_set_d(out, std::ldexp(std::frexp(x, &e), 53));  // an integer; 0 for 0
  if (x != 0) mpz_mul_2exp(out, out, static_cast<mp_bitcnt_t>(e - 53 - lowest));
}

// The GMP stage: the six coordinates as integers over their smallest power of two (no fractions,
// no gcd), in numbers kept from call to call so that a call allocates nothing once they have
// grown to the problem's size.
class IntegerOrientation {
 public:
  IntegerOrientation() {
    for (mpz_t& z : v_) mpz_init2(z, 128);
  }
  ~IntegerOrientation() {
    for (mpz_t& z : v_) mpz_clear(z);
  }
  IntegerOrientation(const IntegerOrientation&) = delete;
  IntegerOrientation& operator=(const IntegerOrientation&) = delete;

  int sign(Point a, Point b, Point p) {
    determinant(a, b, p);
    const int order = mpz_cmp(v_[6], v_[7]);
    return order > 0 ? 1 : order < 0 ? -1 : 0;
  }

  // Whether |(b - a) x (p - a)| <= bound: the determinant is (v6 - v7) * 2^(2 lowest), the bound
  // m * 2^(e - 53) with m an integer; each side is shifted up to the other's exponent.
  bool atMost(Point a, Point b, Point p, double bound) {
    const int lowest = determinant(a, b, p);
    mpz_sub(v_[6], v_[6], v_[7]);
    mpz_abs(v_[6], v_[6]);
    int e = 0;
    mpz_set_d(v_[8], std::ldexp(std::frexp(bound, &e), 53));  // 0 for 0
    const long shift = 2L * lowest - (e - 53);
    if (shift >= 0) {
      mpz_mul_2exp(v_[6], v_[6], static_cast<mp_bitcnt_t>(shift));
    } else {
      mpz_mul_2exp(v_[8], v_[8], static_cast<mp_bitcnt_t>(-shift));
    }
    return mpz_cmp(v_[6], v_[8]) <= 0;
  }

 private:
  // (bx - ax) * (py - ay) in v6 and (by - ay) * (px - ax) in v7, both over 2^(2 lowest); returns
  // lowest.
  int determinant(Point a, Point b, Point p) {
    const double c[6] = {a.x, a.y, b.x, b.y, p.x, p.y};
    const int lowest = lowestPlace({a.x, a.y, b.x, b.y, p.x, p.y});
    for (int i = 0; i < 6; ++i) setOverPowerOfTwo(v_[i], c[i], lowest);
    // (bx - ax) * (py - ay) - (by - ay) * (px - ax)
    mpz_sub(v_[2], v_[2], v_[0]);  // bx - ax
    mpz_sub(v_[5], v_[5], v_[1]);  // py - ay
    mpz_sub(v_[3], v_[3], v_[1]);  // by - ay
    mpz_sub(v_[4], v_[4], v_[0]);  // px - ax
    mpz_mul(v_[6], v_[2], v_[5]);
    mpz_mul(v_[7], v_[3], v_[4]);
    return lowest;
  }

  mpz_t v_[9];
};

IntegerOrientation& integerStage() {
  static thread_local IntegerOrientation integer;
  return integer;
}

// orientationOfRational's integers: a and b times 2^s (s at least the places below their lowest
// bits), then the sign of (Bx - Ax) (ny 2^s - Ay dy) dx - (By - Ay) (nx 2^s - Ax dx) dy, which is
// (b - a) x (p - a) times 2^2s dx dy > 0 for p = (nx / dx, ny / dy) in lowest terms.
class RationalSide {
 public:
  RationalSide() {
    for (mpz_t& z : v_) mpz_init(z);
  }
  ~RationalSide() {
    for (mpz_t& z : v_) mpz_clear(z);
  }
  RationalSide(const RationalSide&) = delete;
  RationalSide& operator=(const RationalSide&) = delete;

  int sign(Point a, Point b, const mpq_t px, const mpq_t py) {
    const int lowest = std::min(0, lowestPlace({a.x, a.y, b.x, b.y})), s = -lowest;  // p's numerators shift by s >= 0
    setOverPowerOfTwo(v_[0], a.x, lowest), setOverPowerOfTwo(v_[1], a.y, lowest);
    setOverPowerOfTwo(v_[2], b.x, lowest), setOverPowerOfTwo(v_[3], b.y, lowest);
    product(v_[4], py, v_[1], v_[2], v_[0], px, s);  // (ny 2^s - Ay dy) (Bx - Ax) dx
    product(v_[6], px, v_[0], v_[3], v_[1], py, s);  // (nx 2^s - Ax dx) (By - Ay) dy
    const int order = mpz_cmp(v_[4], v_[6]);
    return order > 0 ? 1 : order < 0 ? -1 : 0;
  }

 private:
  // (n 2^s - A d) (B' - A') e into out, for q = n / d and r's denominator e (v_[5] is scratch).
  void product(mpz_t out, const mpq_t q, const mpz_t A, const mpz_t Bprime, const mpz_t Aprime, const mpq_t r, int s) {
    mpz_mul_2exp(out, mpq_numref(q), static_cast<mp_bitcnt_t>(s));
    mpz_mul(v_[5], A, mpq_denref(q));
    mpz_sub(out, out, v_[5]);
    mpz_sub(v_[5], Bprime, Aprime);
    mpz_mul(out, out, v_[5]);
    mpz_mul(out, out, mpq_denref(r));
  }

  mpz_t v_[7];
};

}  // namespace

// Out of line (filtered_orientation.h): the filter that decides nearly every call stays small.
int orientationBeyondFilter(Point a, Point b, Point p) {
  // Where the filter cannot decide, the points are usually collinear on a coarse grid: the
  // differences and products are then exact doubles, and the sign is their comparison.
  double bx, py, by, px, el, er;
  if (exactDifference(b.x, a.x, bx) && exactDifference(p.y, a.y, py) && exactDifference(b.y, a.y, by) &&
      exactDifference(p.x, a.x, px) && exactProduct(bx, py, el) && exactProduct(by, px, er)) {
    return el > er ? 1 : el < er ? -1 : 0;
  }
  // Near a coarse grid (ulps off it, 2^-k off it): exact expansions of doubles, with no GMP and
  // nothing allocated, where the coordinates' range keeps them exact.
  if (inExpansionRange({a.x, a.y, b.x, b.y, p.x, p.y})) return determinantExpansion(a, b, p).sign();
  return integerStage().sign(a, b, p);
}

bool crossAtMost(Point a, Point b, Point p, double bound) {
  // Collinear or nearly collinear grid points: the differences, the products and their
  // difference are exact doubles.
  double bx, py, by, px, el, er, det;
  if (exactDifference(b.x, a.x, bx) && exactDifference(p.y, a.y, py) && exactDifference(b.y, a.y, by) &&
      exactDifference(p.x, a.x, px) && exactProduct(bx, py, el) && exactProduct(by, px, er) &&
      exactDifference(el, er, det)) {
    return std::abs(det) <= bound;
  }
  if (inExpansionRange({a.x, a.y, b.x, b.y, p.x, p.y})) {
    if (bound > 0x1p1008) return true;  // |det| <= 16 2^1002: and bound +- det cannot overflow
    // |det| <= bound iff det - bound <= 0 and det + bound >= 0.
    Expansion below = determinantExpansion(a, b, p), above = below;
    below.add(-bound), above.add(bound);
    return below.sign() <= 0 && above.sign() >= 0;
  }
  return integerStage().atMost(a, b, p, bound);
}

int orientation(Point a, Point b, Point p) { return filteredOrientation(a, b, p); }

int orientationOfRational(Point a, Point b, const mpq_t px, const mpq_t py) {
  static thread_local RationalSide side;
  return side.sign(a, b, px, py);
}

}  // namespace gh::oracle
