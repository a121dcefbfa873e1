#include "predicates/crossing_order.h"

#include <cmath>
#include <optional>

#include "predicates/difference_products.h"
#include "predicates/filtered_predicate.h"
#include "predicates/integer_stage.h"
#include "predicates/orientation.h"

namespace gh::detail {
namespace {

// F0 exactly in doubles: the ten differences it is made of, scaled up together when small (F0 is
// homogeneous in them, of degree 4), the four cross products as expansions, and their products
// summed exactly (difference_products.h). Empty when a product is too small to be made exact, a
// difference exceeds 2^240 (the degree-4 terms could overflow), or the expansions are long enough
// to need more than kTerms terms: GMP decides those.
std::optional<Sign> f0InDoubles(Point a1, Point a2, Point m1, Point m2, Point n1, Point n2) {
  TwoTerm d[10] = {twoDiff(m2.x, m1.x), twoDiff(m2.y, m1.y), twoDiff(n2.x, n1.x), twoDiff(n2.y, n1.y),
                   twoDiff(a1.x, a2.x), twoDiff(a1.y, a2.y), twoDiff(a1.x, m1.x), twoDiff(a1.y, m1.y),
                   twoDiff(a1.x, n1.x), twoDiff(a1.y, n1.y)};
  scaleUpTogether(d, 10);
  for (const TwoTerm& t : d) {
    if (!(std::abs(t.hi) <= 0x1p240)) return std::nullopt;
  }
  const auto& [mx, my, nx, ny, ax, ay, amx, amy, anx, any] = d;
  double aM[16], dN[16], aN[16], dM[16];
  const auto lengthAM = crossExpansion(mx, my, amx, amy, aM), lengthDN = crossExpansion(nx, ny, ax, ay, dN);
  const auto lengthAN = crossExpansion(nx, ny, anx, any, aN), lengthDM = crossExpansion(mx, my, ax, ay, dM);
  if (!lengthAM || !lengthDN || !lengthAN || !lengthDM) return std::nullopt;
  constexpr std::size_t kTerms = 256;
  if (2 * (*lengthAM * *lengthDN + *lengthAN * *lengthDM) > kTerms) return std::nullopt;
  double terms[kTerms];
  std::size_t n = 0;
  for (std::size_t i = 0; i < *lengthAM; ++i) {
    for (std::size_t j = 0; j < *lengthDN; ++j) {
      if (!appendProduct(aM[i], dN[j], 1.0, terms, n)) return std::nullopt;
    }
  }
  for (std::size_t i = 0; i < *lengthAN; ++i) {
    for (std::size_t j = 0; j < *lengthDM; ++j) {
      if (!appendProduct(aN[i], dM[j], -1.0, terms, n)) return std::nullopt;
    }
  }
  const std::size_t m = exactSum(terms, n, terms);
  return m == 0 ? Sign::Zero : signOf(terms[m - 1]);
}

}  // namespace

Sign crossingOrderTerm(Point a1, Point a2, Point m1, Point m2, Point n1, Point n2, ExactCounters& counters) {
  // Homogeneous in differences of the coordinates: points near 1e-300 or 1e150 are scaled first
  // (difference_products.h), so that the filter decides there as at 1.
  scaleTowardsUnit(&a1, &a2, &m1, &m2, &n1, &n2);
  return filteredPredicate(
      [&](auto numbers) {
        using N = typename decltype(numbers)::Number;
        auto cross = [](const N& ux, const N& uy, const N& vx, const N& vy) -> N { return ux * vy - uy * vx; };
        const N mx = N(m2.x) - N(m1.x), my = N(m2.y) - N(m1.y);
        const N nx = N(n2.x) - N(n1.x), ny = N(n2.y) - N(n1.y);
        const N ax = N(a1.x) - N(a2.x), ay = N(a1.y) - N(a2.y);
        const N aM = cross(mx, my, N(a1.x) - N(m1.x), N(a1.y) - N(m1.y));
        const N aN = cross(nx, ny, N(a1.x) - N(n1.x), N(a1.y) - N(n1.y));
        const N value = aM * cross(nx, ny, ax, ay) - aN * cross(mx, my, ax, ay);
        return numbers.sign(value);
      },
      [&] { return f0InDoubles(a1, a2, m1, m2, n1, n2); }, [&] { return integerOrderTerm(a1, a2, m1, m2, n1, n2); },
      counters);
}

int orderOfCrossings(Point a1, Point a2, Point m1, Point m2, Point n1, Point n2, ExactCounters& counters) {
  const Sign f0 = crossingOrderTerm(a1, a2, m1, m2, n1, n2, counters);
  if (f0 == Sign::Zero) return 0;
  // sign(t_M - t_N) = sign(F0) sign(D_M) sign(D_N), D_M = cross(m2 - m1, a1 - a2).
  return static_cast<int>(f0) * static_cast<int>(crossSign(m1, m2, a2, a1, counters)) *
         static_cast<int>(crossSign(n1, n2, a2, a1, counters));
}

}  // namespace gh::detail
