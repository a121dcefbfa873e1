#include "ghwork/generators.h"

#include "ghclip/errors.h"
#include "ghclip/validate.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

namespace gh::work {
namespace {

using Rng = std::mt19937_64;
constexpr double kPi = 3.14159265358979323846;

double uniform(Rng& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}
int uniformInt(Rng& rng, int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }

Ring rect(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// Star-shaped around c, hence simple: angle k is 2 pi (k + 0.8 u) / n with u uniform in [0, 1),
// so consecutive angles are less than pi apart for n >= 4 (and every triangle is simple);
// random radii in [rMin, rMax].
Ring starRing(std::size_t n, Point c, double rMin, double rMax, Rng& rng) {
  std::vector<double> angles(std::max<std::size_t>(n, 3));
  const double step = 2 * kPi / static_cast<double>(angles.size());
  for (std::size_t k = 0; k < angles.size(); ++k) angles[k] = step * (static_cast<double>(k) + 0.8 * uniform(rng, 0, 1));
  Ring ring;
  for (double a : angles) {
    const double r = uniform(rng, rMin, rMax);
    ring.push_back({c.x + r * std::cos(a), c.y + r * std::sin(a)});
  }
  return ring;
}

double cross(Point o, Point a, Point b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

bool properlyCross(Point a, Point b, Point c, Point d) {
  const double d1 = cross(a, b, c), d2 = cross(a, b, d), d3 = cross(c, d, a), d4 = cross(c, d, b);
  return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

// Random points made simple by 2-opt: reversing the path between two crossing edges removes
// the crossing and shortens the tour, so this terminates (bounded anyway).
Ring twoOptRing(std::size_t n, Rng& rng) {
  Ring ring(std::max<std::size_t>(n, 3));
  for (Point& p : ring) p = {uniform(rng, 0, 1), uniform(rng, 0, 1)};
  const std::size_t m = ring.size();
  for (int pass = 0; pass < 1000; ++pass) {
    bool changed = false;
    for (std::size_t i = 0; i < m; ++i) {
      for (std::size_t j = i + 2; j < m; ++j) {
        if (i == 0 && j == m - 1) continue;
        if (properlyCross(ring[i], ring[i + 1], ring[j], ring[(j + 1) % m])) {
          std::reverse(ring.begin() + static_cast<long>(i) + 1, ring.begin() + static_cast<long>(j) + 1);
          changed = true;
        }
      }
    }
    if (!changed) break;
  }
  return ring;
}

Ring simpleRing(std::size_t n, Rng& rng, bool star) {
  return star ? starRing(n, {0.5, 0.5}, 0.15, 0.5, rng) : twoOptRing(n, rng);
}

Ring circleRing(std::size_t n, Point c, double r, double noise, Rng& rng) {
  Ring ring(std::max<std::size_t>(n, 3));
  const double phase = uniform(rng, 0, 2 * kPi);
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const double a = phase + 2 * kPi * static_cast<double>(k) / static_cast<double>(ring.size());
    const double rr = r * (1 + noise * uniform(rng, -1, 1));
    ring[k] = {c.x + rr * std::cos(a), c.y + rr * std::sin(a)};
  }
  return ring;
}

// Fractal outline in polar form: r(a) = 1 + sum of octaves of decreasing amplitude (total < 0.6),
// so it is star-shaped around c and therefore simple, yet rough at every scale like a coastline.
Ring coastlineRing(std::size_t n, Point c, double scale, Rng& rng) {
  constexpr int kOctaves = 12;
  double amp[kOctaves], phase[kOctaves];
  double a = 0.25;
  for (int k = 0; k < kOctaves; ++k, a *= 0.55) amp[k] = a * uniform(rng, 0.5, 1), phase[k] = uniform(rng, 0, 2 * kPi);
  Ring ring(std::max<std::size_t>(n, 3));
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const double t = 2 * kPi * static_cast<double>(i) / static_cast<double>(ring.size());
    double r = 1;
    for (int k = 0; k < kOctaves; ++k) r += amp[k] * std::sin(std::ldexp(1.0, k) * t + phase[k]);
    ring[i] = {c.x + scale * r * std::cos(t), c.y + scale * r * std::sin(t)};
  }
  return ring;
}

// A square shell [0,1]^2 with holes: small star rings in distinct cells of a 3x3 layout.
Region holesRegion(std::size_t n, Point offset, Rng& rng) {
  Region region{rect(offset.x, offset.y, offset.x + 1, offset.y + 1)};
  std::vector<int> cells{0, 1, 2, 3, 4, 5, 6, 7, 8};
  std::shuffle(cells.begin(), cells.end(), rng);
  const int holes = uniformInt(rng, 2, 5);
  const std::size_t perHole = std::max<std::size_t>(3, n / static_cast<std::size_t>(holes + 1));
  for (int h = 0; h < holes; ++h) {
    const Point c{offset.x + (cells[h] % 3 + 0.5) / 3, offset.y + (cells[h] / 3 + 0.5) / 3};
    region.push_back(starRing(perHole, c, 0.05, 0.15, rng));
  }
  return region;
}

bool hasThreeDistinct(const Ring& ring) {
  std::vector<std::pair<double, double>> d;
  for (const Point& p : ring) d.emplace_back(p.x, p.y);
  std::sort(d.begin(), d.end());
  return std::unique(d.begin(), d.end()) - d.begin() >= 3;
}

// A star ring snapped to the integer grid, without the repeated vertices snapping creates.
Ring gridStar(std::size_t n, Point c, double rMin, double rMax, Rng& rng) {
  Ring snapped;
  for (Point p : starRing(n, c, rMin, rMax, rng)) {
    p = {std::round(p.x), std::round(p.y)};
    if (snapped.empty() || snapped.back() != p) snapped.push_back(p);
  }
  while (snapped.size() > 1 && snapped.back() == snapped.front()) snapped.pop_back();
  if (!hasThreeDistinct(snapped)) snapped = {{c.x - 1, c.y - 1}, {c.x + 1, c.y - 1}, {c.x, c.y + 1}};
  return snapped;
}

// K triangles sharing the origin, the pieces of a pie: (0,0), then two consecutive points of a
// regular K-gon of radius r, turned by `turn`. Every piece has two edges through the origin.
Region pie(std::size_t k, double r, double turn) {
  Region out;
  for (std::size_t i = 0; i < k; ++i) {
    const double a = turn + 2 * kPi * static_cast<double>(i) / static_cast<double>(k);
    const double b = turn + 2 * kPi * static_cast<double>(i + 1) / static_cast<double>(k);
    out.push_back({{0, 0}, {r * std::cos(a), r * std::sin(a)}, {r * std::cos(b), r * std::sin(b)}});
  }
  return out;
}

// K petals sharing the origin: kites (0,0), a shoulder at radius r, the tip at radius R, the other
// shoulder, each petal 0.8 of its sector wide, turned by `turn`.
Region flower(std::size_t k, double r, double tipRadius, double turn) {
  Region out;
  const double half = 0.4 * 2 * kPi / static_cast<double>(k);
  for (std::size_t i = 0; i < k; ++i) {
    const double a = turn + 2 * kPi * static_cast<double>(i) / static_cast<double>(k);
    out.push_back({{0, 0},
                   {r * std::cos(a - half), r * std::sin(a - half)},
                   {tipRadius * std::cos(a), tipRadius * std::sin(a)},
                   {r * std::cos(a + half), r * std::sin(a + half)}});
  }
  return out;
}

// About n vertices of islands in a g x g layout of unit cells: each island (a star ring) holds a
// lake, and the lake an islet, so rings nest three deep: islands inside lakes inside islands.
Region archipelago(std::size_t n, Point offset, Rng& rng) {
  const std::size_t groups = std::max<std::size_t>(1, n / 44);
  const auto g = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(groups))));
  Region out;
  for (std::size_t k = 0; k < groups; ++k) {
    const Point c{offset.x + static_cast<double>(k % g) + 0.5, offset.y + static_cast<double>(k / g) + 0.5};
    out.push_back(starRing(24, c, 0.3, 0.48, rng));
    out.push_back(starRing(12, c, 0.14, 0.24, rng));
    out.push_back(starRing(8, c, 0.04, 0.1, rng));
  }
  return out;
}

// One large and one small feature in the same problem: a triangle of size 2^e (e in 10..480)
// whose first edge runs through the origin, holding a star hole of size 2^-f (f in 0..300) just
// above that edge; the clip is a star of size 2^-f that crosses the edge and overlaps the hole.
// A judge with one tolerance for the whole problem cannot see the small feature at all.
Workload mixedMagnitude(std::size_t n, Rng& rng) {
  const double big = std::ldexp(1.0, uniformInt(rng, 10, 480));
  const double small = std::ldexp(1.0, -uniformInt(rng, 0, 300));
  const double slope = uniformInt(rng, 1, 7) / 8.0, apex = uniformInt(rng, 0, 7) / 8.0;
  const Ring shell{{-big, -big * slope}, {big, big * slope}, {big * apex, big}};
  const Ring hole = starRing(std::max<std::size_t>(n / 2, 3), {0, 3 * small}, 0.5 * small, small, rng);
  const Ring clip = starRing(std::max<std::size_t>(n, 3), {0, 2 * small}, 1.5 * small, 2.5 * small, rng);
  return {{shell, hole}, {clip}};
}

Workload degenerateFamily(const std::string& name, std::size_t n, Rng& rng) {
  auto g = [&](int lo, int hi) { return static_cast<double>(uniformInt(rng, lo, hi)); };
  if (name == "identical") {
    // The same simple polygon twice, on the integer grid.
    const Ring r = gridStar(std::max<std::size_t>(n, 3), {4, 4}, 1, 4, rng);
    return {{r}, {r}};
  }
  if (name == "shared-edge") {
    // Two rectangles side by side; the shared edge partly overlaps.
    const double x = g(2, 5), y0 = g(0, 2), y1 = g(4, 7);
    return {{rect(g(0, 1), y0, x, y1)}, {rect(x, g(0, 3), g(6, 8), g(4, 8))}};
  }
  if (name == "touching-vertex") {
    // A rectangle and a triangle whose only common point is the rectangle's corner (x, y).
    const double x = g(2, 5), y = g(2, 5);
    return {{rect(g(0, 1), g(0, 1), x, y)}, {{{x, y}, {x + g(2, 3), y + 1}, {x + 1, y + g(2, 3)}}}};
  }
  if (name == "nested-touching") {
    // C inside S, sharing part of S's bottom edge and touching its right edge at a vertex.
    return {{rect(0, 0, 8, 8)}, {{{g(1, 3), 0}, {g(5, 7), 0}, {8, g(1, 4)}, {g(2, 6), g(5, 7)}}}};
  }
  if (name == "sliver") {
    // Overlap of width 2^-20 along a long edge.
    const double w = std::ldexp(1.0, -20);
    const double x = g(2, 6);
    return {{rect(0, 0, x, 8)}, {rect(x - w, g(0, 2), 8, g(6, 8))}};
  }
  if (name == "sub-boundary") {
    // C's vertices are every other vertex of S: its edges are chords of S.
    const Ring s = gridStar(std::max<std::size_t>(2 * n, 6), {4, 4}, 2, 4, rng);
    Ring c;
    for (std::size_t i = 0; i < s.size(); i += 2) c.push_back(s[i]);
    if (!hasThreeDistinct(c)) c = s;
    return {{s}, {c}};
  }
  throw std::invalid_argument("unknown workload '" + name + "'");
}

Workload base(const std::string& name, std::size_t n, Rng& rng, std::uint64_t seed) {
  if (name == "random") return {{randomRing(n, seed * 2 + 1)}, {randomRing(n, seed * 2 + 2)}};
  if (name == "simple") {
    const bool star = seed % 2 == 0;
    Ring s = simpleRing(n, rng, star);
    return {{s}, {simpleRing(n, rng, star)}};
  }
  if (name == "grid") return {{gridRing(n, 8, seed * 2 + 1)}, {gridRing(n, 8, seed * 2 + 2)}};
  if (name == "bitset-grid") {
    const BitsetGrid b = bitsetGrid(n, seed);
    return {cellsRegion(b, b.subject), cellsRegion(b, b.clip)};
  }
  if (name == "circles") {
    // Radial noise of a fifth of the edge length: visibly perturbed, still crossing twice.
    const double noise = std::min(1e-3, 1.0 / static_cast<double>(std::max<std::size_t>(n, 3)));
    return {{circleRing(n, {0, 0}, 1, noise, rng)}, {circleRing(n, {0.31, 0.12}, 1, noise, rng)}};
  }
  if (name == "coastline") {
    return {{coastlineRing(n, {0, 0}, 1, rng)}, {coastlineRing(n, {0.6, 0.2}, 1, rng)}};
  }
  if (name == "holes") return {holesRegion(n, {0, 0}, rng), holesRegion(n, {0.37, 0.21}, rng)};
  if (name == "pie") {
    const std::size_t k = std::max<std::size_t>(n, 3);
    return {pie(k, 1, 0), pie(k, 1, kPi / static_cast<double>(k))};
  }
  if (name == "flower") {
    const std::size_t k = std::max<std::size_t>(n, 3);
    return {flower(k, 0.5, 1, 0), flower(k, 0.55, 0.95, 0.5 * kPi / static_cast<double>(k))};
  }
  if (name == "archipelago") return {archipelago(n, {0, 0}, rng), archipelago(n, {0.45, 0.3}, rng)};
  if (name == "mixed-magnitude") return mixedMagnitude(n, rng);
  return degenerateFamily(name, n, rng);
}

template <class F>
void forEachPoint(Workload& w, F f) {
  for (Region* r : {&w.subject, &w.clip}) {
    for (Ring& ring : *r) {
      for (Point& p : ring) f(p);
    }
  }
}

}  // namespace

const std::vector<std::string>& workloadNames() {
  static const std::vector<std::string> names{
      "random",        "simple",         "grid",        "identical",
      "shared-edge",   "touching-vertex", "nested-touching", "sliver",
      "sub-boundary",  "bitset-grid",    "circles",     "coastline",
      "holes",         "pie",            "flower",      "archipelago",
      "mixed-magnitude"};
  return names;
}

const std::vector<std::string>& variantSuffixes() {
  static const std::vector<std::string> suffixes{"ulp", "tiny", "huge", "far"};
  return suffixes;
}

Workload generate(const std::string& fullName, std::size_t n, std::uint64_t seed) {
  const auto plus = fullName.find('+');
  const std::string name = fullName.substr(0, plus);
  const std::string suffix = plus == std::string::npos ? "" : fullName.substr(plus + 1);
  Rng rng(seed * 0x9E3779B97F4A7C15ull + std::hash<std::string>()(name));
  Workload w = base(name, n, rng, seed);
  if (suffix.empty()) return w;
  if (suffix == "ulp") {
    forEachPoint(w, [&](Point& p) {
      for (double* c : {&p.x, &p.y}) {
        const double dir = rng() & 1 ? std::numeric_limits<double>::infinity()
                                     : -std::numeric_limits<double>::infinity();
        *c = std::nextafter(*c, dir);
      }
    });
  } else if (suffix == "tiny") {
    forEachPoint(w, [](Point& p) { p = {std::ldexp(p.x, -997), std::ldexp(p.y, -997)}; });
  } else if (suffix == "huge") {
    // A power of two that brings the largest coordinate to about 2^497 (1e150), below the
    // clipper's limit of 2^500.
    double m = 1;
    forEachPoint(w, [&m](Point& p) { m = std::max({m, std::abs(p.x), std::abs(p.y)}); });
    const int e = 497 - std::ilogb(m) - 1;
    forEachPoint(w, [e](Point& p) { p = {std::ldexp(p.x, e), std::ldexp(p.y, e)}; });
  } else if (suffix == "far") {
    forEachPoint(w, [](Point& p) { p = {p.x + 1e9, p.y + 1e9}; });
  } else {
    throw std::invalid_argument("unknown workload variant '+" + suffix + "'");
  }
  // A suffix can take a feature below the doubles (mixed-magnitude's star of size 2^-300, scaled
  // by 2^-997 or moved to 1e9): then there is no such workload, and saying so beats bad input.
  for (const Region* r : {&w.subject, &w.clip}) {
    try {
      normalized(*r, OnBadRing::Throw);
    } catch (const InvalidInput& e) {
      throw std::invalid_argument(fullName + " (n " + std::to_string(n) + ", seed " + std::to_string(seed) + "): the +" +
                                  suffix + " variant collapses a ring (" + e.what() + ")");
    }
  }
  return w;
}

BitsetGrid bitsetGrid(std::size_t n, std::uint64_t seed) {
  Rng rng(seed * 0x2545F4914F6CDD1Dull + 7);
  BitsetGrid b;
  // About n vertices per operand: half of k x k cells set, 4 corners each, so k ~ sqrt(n / 2).
  b.size = std::max(3, static_cast<int>(std::lround(std::sqrt(static_cast<double>(n) / 2))));
  const std::size_t cells = static_cast<std::size_t>(b.size) * static_cast<std::size_t>(b.size);
  b.subject.resize(cells);
  b.clip.resize(cells);
  for (std::size_t i = 0; i < cells; ++i) b.subject[i] = rng() & 1, b.clip[i] = rng() & 1;
  return b;
}

Region cellsRegion(const BitsetGrid& grid, const std::vector<bool>& cells) {
  Region region;
  for (int j = 0; j < grid.size; ++j) {
    for (int i = 0; i < grid.size; ++i) {
      if (cells[static_cast<std::size_t>(j * grid.size + i)]) region.push_back(rect(i, j, i + 1, j + 1));
    }
  }
  return region;
}

Ring randomRing(std::size_t n, std::uint64_t seed) {
  Rng rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Ring ring(std::max<std::size_t>(n, 3));
  for (Point& p : ring) p = {u(rng), u(rng)};
  return ring;
}

Ring gridRing(std::size_t n, int gridSize, std::uint64_t seed) {
  Rng rng(seed);
  std::uniform_int_distribution<int> u(0, gridSize);
  Ring ring;
  const std::size_t want = std::max<std::size_t>(n, 3);
  // Redraw until the ring has 3 distinct vertices (a handful of draws at most).
  for (int attempt = 0;; ++attempt) {
    ring.clear();
    while (ring.size() < want) {
      const Point p{static_cast<double>(u(rng)), static_cast<double>(u(rng))};
      if (ring.empty() || ring.back() != p) ring.push_back(p);
    }
    if (ring.back() == ring.front()) continue;
    std::vector<std::pair<double, double>> d;
    for (const Point& p : ring) d.emplace_back(p.x, p.y);
    std::sort(d.begin(), d.end());
    if (std::unique(d.begin(), d.end()) - d.begin() >= 3 || attempt > 100) break;
  }
  return ring;
}

}  // namespace gh::work
