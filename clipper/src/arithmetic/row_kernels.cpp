#include "arithmetic/row_kernels.h"

#include <immintrin.h>

#include <limits>

namespace gh::detail {

EdgeArrays::EdgeArrays(const Operand& op) {
  const std::size_t m = op.size();
  x1.resize(m), y1.resize(m), x2.resize(m), y2.resize(m);
  for (std::uint32_t e = 0; e < m; ++e) {
    const Point a = op.from(e), b = op.to(e);
    x1[e] = a.x, y1[e] = a.y, x2[e] = b.x, y2[e] = b.y;
  }
}

bool rowKernelsAvailable() {
#if defined(__x86_64__) || defined(__i386__)
  static const bool available = __builtin_cpu_supports("avx2");
  return available;
#else
  return false;
#endif
}

#if defined(__x86_64__) || defined(__i386__)
namespace {

using V = __m256d;

[[gnu::target("avx2")]] inline V splat(double d) { return _mm256_set1_pd(d); }
[[gnu::target("avx2")]] inline V load(const std::vector<double>& a, std::size_t i) { return _mm256_loadu_pd(a.data() + i); }
[[gnu::target("avx2")]] inline int mask(V v) { return _mm256_movemask_pd(v); }
[[gnu::target("avx2")]] inline V lt(V a, V b) { return _mm256_cmp_pd(a, b, _CMP_LT_OQ); }
[[gnu::target("avx2")]] inline V le(V a, V b) { return _mm256_cmp_pd(a, b, _CMP_LE_OQ); }
[[gnu::target("avx2")]] inline V gt(V a, V b) { return _mm256_cmp_pd(a, b, _CMP_GT_OQ); }

// (a - b) * (c - d) - (e - f) * (g - h), as the scalar expressions evaluate it.
[[gnu::target("avx2")]] inline V crossTerm(V a, V b, V c, V d, V e, V f, V g, V h) {
  return _mm256_sub_pd(_mm256_mul_pd(_mm256_sub_pd(a, b), _mm256_sub_pd(c, d)),
                       _mm256_mul_pd(_mm256_sub_pd(e, f), _mm256_sub_pd(g, h)));
}

// Where the orientation determinant left - right certainly has a sign, as orientation.h decides
// it with Shewchuk's stage-A bound and certainSign's margin: positive / negative lanes.
[[gnu::target("avx2")]] inline void certainSides(V left, V right, V& positive, V& negative) {
  const V absMask = _mm256_castsi256_pd(_mm256_set1_epi64x(0x7fffffffffffffffLL));
  const V value = _mm256_sub_pd(left, right);
  const V sum = _mm256_add_pd(_mm256_and_pd(left, absMask), _mm256_and_pd(right, absMask));
  const V safe = _mm256_and_pd(gt(sum, splat(0x1p-900)), lt(sum, splat(0x1p900)));
  const V bound = _mm256_mul_pd(_mm256_mul_pd(splat((3.0 + 16.0 * 0x1p-53) * 0x1p-53), sum), splat(1 + 0x1p-20));
  positive = _mm256_and_pd(safe, gt(value, bound));
  negative = _mm256_and_pd(safe, gt(_mm256_sub_pd(_mm256_setzero_pd(), value), bound));
}

}  // namespace

[[gnu::target("avx2")]] void paperRow(double p1x, double p1y, double p2x, double p2y, const EdgeArrays& clip,
                                      void (*crossing)(void*, std::uint32_t, double, double, double, double),
                                      void (*special)(void*, std::uint32_t), void* context) {
  const std::size_t m = clip.size(), vectorEnd = m & ~std::size_t{3};
  const V P1x = splat(p1x), P1y = splat(p1y), P2x = splat(p2x), P2y = splat(p2y);
  const V pMaxX = splat(std::max(p1x, p2x)), pMinX = splat(std::min(p1x, p2x));
  const V pMaxY = splat(std::max(p1y, p2y)), pMinY = splat(std::min(p1y, p2y));
  const V zero = _mm256_setzero_pd();
  alignas(32) double aS[4], aC[4], px[4], py[4];
  for (std::size_t i = 0; i < vectorEnd; i += 4) {
    const V Q1x = load(clip.x1, i), Q1y = load(clip.y1, i), Q2x = load(clip.x2, i), Q2y = load(clip.y2, i);
    // The paper's early out: disjoint boxes.
    const V apart = _mm256_or_pd(
        _mm256_or_pd(lt(pMaxX, _mm256_min_pd(Q1x, Q2x)), lt(_mm256_max_pd(Q1x, Q2x), pMinX)),
        _mm256_or_pd(lt(pMaxY, _mm256_min_pd(Q1y, Q2y)), lt(_mm256_max_pd(Q1y, Q2y), pMinY)));
    int live = ~mask(apart) & 0xf;
    if (!live) continue;
    // Window-edge coordinates: (p - q1) x (q2 - q1) as (p.x - q1.x)(q2.y - q1.y) - (p.y - q1.y)(q2.x - q1.x).
    const V wP1 = crossTerm(P1x, Q1x, Q2y, Q1y, P1y, Q1y, Q2x, Q1x);
    const V wP2 = crossTerm(P2x, Q1x, Q2y, Q1y, P2y, Q1y, Q2x, Q1x);
    const V wQ1 = crossTerm(Q1x, P1x, P2y, P1y, Q1y, P1y, P2x, P1x);
    const V wQ2 = crossTerm(Q2x, P1x, P2y, P1y, Q2y, P1y, P2x, P1x);
    // Any zero: a degenerate contact (or a pair the scalar test rejects while looking at it).
    const int zeros = mask(_mm256_or_pd(_mm256_or_pd(_mm256_cmp_pd(wP1, zero, _CMP_EQ_OQ), _mm256_cmp_pd(wP2, zero, _CMP_EQ_OQ)),
                                        _mm256_or_pd(_mm256_cmp_pd(wQ1, zero, _CMP_EQ_OQ), _mm256_cmp_pd(wQ2, zero, _CMP_EQ_OQ))));
    // Opposite strict signs on both edges: a proper crossing.
    const V oppositeP = _mm256_or_pd(_mm256_and_pd(gt(wP1, zero), lt(wP2, zero)), _mm256_and_pd(lt(wP1, zero), gt(wP2, zero)));
    const V oppositeQ = _mm256_or_pd(_mm256_and_pd(gt(wQ1, zero), lt(wQ2, zero)), _mm256_and_pd(lt(wQ1, zero), gt(wQ2, zero)));
    const int crossings = mask(_mm256_and_pd(oppositeP, oppositeQ)) & live & ~zeros;
    const int specials = zeros & live;
    if (crossings) {
      const V alphaS = _mm256_div_pd(wP1, _mm256_sub_pd(wP1, wP2));
      const V alphaC = _mm256_div_pd(wQ1, _mm256_sub_pd(wQ1, wQ2));
      _mm256_store_pd(aS, alphaS);
      _mm256_store_pd(aC, alphaC);
      _mm256_store_pd(px, _mm256_add_pd(P1x, _mm256_mul_pd(alphaS, _mm256_sub_pd(P2x, P1x))));
      _mm256_store_pd(py, _mm256_add_pd(P1y, _mm256_mul_pd(alphaS, _mm256_sub_pd(P2y, P1y))));
    }
    for (int lane = 0; lane < 4; ++lane) {
      const auto ce = static_cast<std::uint32_t>(i + lane);
      if (specials >> lane & 1) {
        special(context, ce);
      } else if (crossings >> lane & 1) {
        crossing(context, ce, aS[lane], aC[lane], px[lane], py[lane]);
      }
    }
  }
  for (std::size_t i = vectorEnd; i < m; ++i) special(context, static_cast<std::uint32_t>(i));
}

[[gnu::target("avx2")]] void exactRowCandidates(double p1x, double p1y, double p2x, double p2y, const EdgeArrays& clip,
                                                void (*candidate)(void*, std::uint32_t), void* context) {
  const std::size_t m = clip.size(), vectorEnd = m & ~std::size_t{3};
  const V P1x = splat(p1x), P1y = splat(p1y), P2x = splat(p2x), P2y = splat(p2y);
  const V pMaxX = splat(std::max(p1x, p2x)), pMinX = splat(std::min(p1x, p2x));
  const V pMaxY = splat(std::max(p1y, p2y)), pMinY = splat(std::min(p1y, p2y));
  for (std::size_t i = 0; i < vectorEnd; i += 4) {
    const V Q1x = load(clip.x1, i), Q1y = load(clip.y1, i), Q2x = load(clip.x2, i), Q2y = load(clip.y2, i);
    // The exact arithmetic's boxes (the clip translated by (eps, eps^2)): apart when p's high side
    // ties q's low side too.
    const V apart = _mm256_or_pd(
        _mm256_or_pd(le(pMaxX, _mm256_min_pd(Q1x, Q2x)), lt(_mm256_max_pd(Q1x, Q2x), pMinX)),
        _mm256_or_pd(le(pMaxY, _mm256_min_pd(Q1y, Q2y)), lt(_mm256_max_pd(Q1y, Q2y), pMinY)));
    int live = ~mask(apart) & 0xf;
    if (!live) continue;
    // orientationDeterminant(q1, q2, p): (q2.x - q1.x)(p.y - q1.y) - (q2.y - q1.y)(p.x - q1.x).
    V pos1, neg1, pos2, neg2;
    certainSides(_mm256_mul_pd(_mm256_sub_pd(Q2x, Q1x), _mm256_sub_pd(P1y, Q1y)),
         _mm256_mul_pd(_mm256_sub_pd(Q2y, Q1y), _mm256_sub_pd(P1x, Q1x)), pos1, neg1);
    certainSides(_mm256_mul_pd(_mm256_sub_pd(Q2x, Q1x), _mm256_sub_pd(P2y, Q1y)),
         _mm256_mul_pd(_mm256_sub_pd(Q2y, Q1y), _mm256_sub_pd(P2x, Q1x)), pos2, neg2);
    live &= ~mask(_mm256_or_pd(_mm256_and_pd(pos1, pos2), _mm256_and_pd(neg1, neg2)));
    if (!live) continue;
    // orientationDeterminant(p1, p2, q).
    certainSides(_mm256_mul_pd(_mm256_sub_pd(P2x, P1x), _mm256_sub_pd(Q1y, P1y)),
         _mm256_mul_pd(_mm256_sub_pd(P2y, P1y), _mm256_sub_pd(Q1x, P1x)), pos1, neg1);
    certainSides(_mm256_mul_pd(_mm256_sub_pd(P2x, P1x), _mm256_sub_pd(Q2y, P1y)),
         _mm256_mul_pd(_mm256_sub_pd(P2y, P1y), _mm256_sub_pd(Q2x, P1x)), pos2, neg2);
    live &= ~mask(_mm256_or_pd(_mm256_and_pd(pos1, pos2), _mm256_and_pd(neg1, neg2)));
    for (int lane = 0; lane < 4; ++lane) {
      if (live >> lane & 1) candidate(context, static_cast<std::uint32_t>(i + lane));
    }
  }
  for (std::size_t i = vectorEnd; i < m; ++i) candidate(context, static_cast<std::uint32_t>(i));
}

#else
void paperRow(double, double, double, double, const EdgeArrays&, void (*)(void*, std::uint32_t, double, double, double, double),
              void (*)(void*, std::uint32_t), void*) {}
void exactRowCandidates(double, double, double, double, const EdgeArrays&, void (*)(void*, std::uint32_t), void*) {}
#endif

}  // namespace gh::detail
