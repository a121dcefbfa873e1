#include "ghwork/generators.h"

#include <random>

namespace gh::work {

Ring randomRing(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Ring ring(n);
  for (Point& p : ring) p = {u(rng), u(rng)};
  return ring;
}

Ring gridRing(std::size_t n, int gridSize, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> u(0, gridSize);
  Ring ring;
  while (ring.size() < n) {
    const Point p{static_cast<double>(u(rng)), static_cast<double>(u(rng))};
    if (ring.empty() || ring.back() != p) ring.push_back(p);
  }
  if (ring.size() > 1 && ring.back() == ring.front()) ring.back().x += 1;  // keep n distinct ends
  return ring;
}

}  // namespace gh::work
