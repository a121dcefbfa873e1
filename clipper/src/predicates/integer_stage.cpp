#include "predicates/integer_stage.h"

#include <gmp.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace gh::detail {
namespace {

// Numbers v[0 .. kCount) kept for the thread: the coordinates first, then the intermediate terms.
class Integers {
 public:
  static constexpr std::size_t kCount = 24;
  Integers() {
    for (mpz_t& z : v_) mpz_init2(z, 256);
  }
  ~Integers() {
    for (mpz_t& z : v_) mpz_clear(z);
  }
  Integers(const Integers&) = delete;
  Integers& operator=(const Integers&) = delete;

  // v[i] = c[i] * 2^-lowest for the n coordinates c, lowest the smallest exponent of their
  // integer forms m * 2^(e - 53) (m an integer of at most 53 bits; zero adds no exponent).
  void load(const double* c, std::size_t n) {
    int lowest = 0;
    bool any = false;
    for (std::size_t i = 0; i < n; ++i) {
      if (c[i] == 0) continue;
      int e = 0;
      std::frexp(c[i], &e);
      lowest = any ? std::min(lowest, e - 53) : e - 53, any = true;
    }
    for (std::size_t i = 0; i < n; ++i) {
      int e = 0;
      mpz_set_d(v_[i], std::ldexp(std::frexp(c[i], &e), 53));  // an integer; 0 for 0
      if (c[i] != 0) mpz_mul_2exp(v_[i], v_[i], static_cast<mp_bitcnt_t>(e - 53 - lowest));
    }
  }
  mpz_t& operator[](std::size_t i) { return v_[i]; }

 private:
  mpz_t v_[kCount];
};

Integers& integers() {
  static thread_local Integers numbers;
  return numbers;
}

Sign compareIntegers(mpz_t& left, mpz_t& right) { return toSign(mpz_cmp(left, right)); }

}  // namespace

Sign integerCrossSign(Point a, Point b, Point c, Point d) {
  Integers& v = integers();
  const double coordinates[8] = {a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y};
  v.load(coordinates, 8);
  mpz_sub(v[8], v[2], v[0]);   // b.x - a.x
  mpz_sub(v[9], v[7], v[5]);   // d.y - c.y
  mpz_sub(v[10], v[3], v[1]);  // b.y - a.y
  mpz_sub(v[11], v[6], v[4]);  // d.x - c.x
  mpz_mul(v[12], v[8], v[9]);
  mpz_mul(v[13], v[10], v[11]);
  return compareIntegers(v[12], v[13]);
}

Sign integerOrderTerm(Point a1, Point a2, Point m1, Point m2, Point n1, Point n2) {
  Integers& v = integers();
  const double coordinates[12] = {a1.x, a1.y, a2.x, a2.y, m1.x, m1.y, m2.x, m2.y, n1.x, n1.y, n2.x, n2.y};
  v.load(coordinates, 12);
  enum { A1X, A1Y, A2X, A2Y, M1X, M1Y, M2X, M2Y, N1X, N1Y, N2X, N2Y, MX, MY, NX, NY, AX, AY, T0, T1, AM, AN, DM, DN };
  static_assert(DN < Integers::kCount);
  mpz_sub(v[MX], v[M2X], v[M1X]);
  mpz_sub(v[MY], v[M2Y], v[M1Y]);
  mpz_sub(v[NX], v[N2X], v[N1X]);
  mpz_sub(v[NY], v[N2Y], v[N1Y]);
  mpz_sub(v[AX], v[A1X], v[A2X]);
  mpz_sub(v[AY], v[A1Y], v[A2Y]);
  // A_M = mx (a1.y - m1.y) - my (a1.x - m1.x)
  mpz_sub(v[T0], v[A1Y], v[M1Y]);
  mpz_mul(v[AM], v[MX], v[T0]);
  mpz_sub(v[T0], v[A1X], v[M1X]);
  mpz_mul(v[T1], v[MY], v[T0]);
  mpz_sub(v[AM], v[AM], v[T1]);
  // A_N = nx (a1.y - n1.y) - ny (a1.x - n1.x)
  mpz_sub(v[T0], v[A1Y], v[N1Y]);
  mpz_mul(v[AN], v[NX], v[T0]);
  mpz_sub(v[T0], v[A1X], v[N1X]);
  mpz_mul(v[T1], v[NY], v[T0]);
  mpz_sub(v[AN], v[AN], v[T1]);
  // D_N = nx ay - ny ax, D_M = mx ay - my ax
  mpz_mul(v[DN], v[NX], v[AY]);
  mpz_mul(v[T0], v[NY], v[AX]);
  mpz_sub(v[DN], v[DN], v[T0]);
  mpz_mul(v[DM], v[MX], v[AY]);
  mpz_mul(v[T0], v[MY], v[AX]);
  mpz_sub(v[DM], v[DM], v[T0]);
  // A_M D_N against A_N D_M
  mpz_mul(v[T0], v[AM], v[DN]);
  mpz_mul(v[T1], v[AN], v[DM]);
  return compareIntegers(v[T0], v[T1]);
}

}  // namespace gh::detail
