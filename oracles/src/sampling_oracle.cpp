#include "ghoracle/sampling_oracle.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <random>

#include "ghoracle/tolerance.h"
#include "judging_scale.h"

namespace gh::oracle {
namespace {

struct Box {
  double minX = std::numeric_limits<double>::infinity(), minY = minX;
  double maxX = -std::numeric_limits<double>::infinity(), maxY = maxX;
  void grow(const Region& r) {
    for (const Ring& ring : r) {
      for (const Point& p : ring) {
        minX = std::min(minX, p.x), maxX = std::max(maxX, p.x);
        minY = std::min(minY, p.y), maxY = std::max(maxY, p.y);
      }
    }
  }
};

// Parity of edge crossings of a rightward ray from p, and whether p is within delta of an edge.
struct Probe {
  bool inside = false;
  bool nearEdge = false;
};

Probe probe(const Region& region, Point p, double delta) {
  Probe out;
  const double delta2 = delta * delta;
  for (const Ring& ring : region) {
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
      const Point& a = ring[i];
      const Point& b = ring[(i + 1) % n];
      if ((a.y > p.y) != (b.y > p.y)) {
        const double x = a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x);
        if (p.x < x) out.inside = !out.inside;
      }
      if (!out.nearEdge) {
        // Cheap reject by bounding box, then the exact-enough segment distance.
        if (p.x < std::min(a.x, b.x) - delta || p.x > std::max(a.x, b.x) + delta ||
            p.y < std::min(a.y, b.y) - delta || p.y > std::max(a.y, b.y) + delta) {
          continue;
        }
        const double dx = b.x - a.x, dy = b.y - a.y;
        const double len2 = dx * dx + dy * dy;
        double t = len2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 0;
        t = std::clamp(t, 0.0, 1.0);
        const double ex = a.x + t * dx - p.x, ey = a.y + t * dy - p.y;
        if (ex * ex + ey * ey <= delta2) out.nearEdge = true;
      }
    }
  }
  return out;
}

// The check proper, on a problem at a comfortable scale (judging_scale.h); minDelta is the
// original problem's rounding resolution at this scale.
SampleVerdict sample(const Region& subject, const Region& clip, Op op, const Region& result,
                     const SampleOptions& options, double minDelta) {
  const auto start = std::chrono::steady_clock::now();
  SampleVerdict v;
  Box box;
  box.grow(subject), box.grow(clip), box.grow(result);
  if (!(box.minX <= box.maxX)) return v;  // everything empty: nothing to check
  // Halves first: the extent of coordinates near 2^500 must not overflow.
  const double extent = std::max({(box.maxX / 2 - box.minX / 2) * 2, (box.maxY / 2 - box.minY / 2) * 2,
                                  std::numeric_limits<double>::min()});
  // Rounding in the crossing tests scales with the coordinates' magnitude, not only the extent:
  // far from the origin (1e9 + a unit square) the second term dominates.
  const double magnitude = std::max({std::abs(box.minX), std::abs(box.maxX), std::abs(box.minY), std::abs(box.maxY)});
  v.delta = std::max(std::ldexp(extent, -32) + std::ldexp(magnitude, -44), minDelta);

  auto check = [&](Point p) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return;
    const Probe s = probe(subject, p, v.delta);
    const Probe c = probe(clip, p, v.delta);
    const Probe r = probe(result, p, v.delta);
    if (s.nearEdge || c.nearEdge || r.nearEdge) {
      ++v.skipped;
      return;
    }
    ++v.checked;
    if (r.inside != apply(op, s.inside, c.inside)) {
      if (!v.mismatched) v.firstMismatch = p;
      ++v.mismatched;
    }
  };

  std::mt19937_64 rng(options.seed);
  std::uniform_real_distribution<double> ux(box.minX, box.maxX), uy(box.minY, box.maxY);
  for (std::size_t i = 0; i < options.uniformPoints; ++i) check({ux(rng), uy(rng)});
  if (options.nearVertices) {
    std::uniform_real_distribution<double> turn(0, 2 * std::acos(-1.0));
    for (const Region* region : {&subject, &clip, &result}) {
      for (const Ring& ring : *region) {
        for (const Point& q : ring) {
          const double phase = turn(rng);
          for (int e : {8, 14, 20, 26}) {
            const double radius = std::ldexp(extent, -e);
            for (int k = 0; k < 8; ++k) {
              const double a = phase + k * std::acos(-1.0) / 4;
              check({q.x + radius * std::cos(a), q.y + radius * std::sin(a)});
            }
          }
        }
      }
    }
  }
  v.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return v;
}

}  // namespace

SampleVerdict sampleCheck(const Region& subject, const Region& clip, Op op, const Region& result,
                          const SampleOptions& options) {
  const int k = judgingExponent(subject, clip, result);
  if (k == 0) return sample(subject, clip, op, result, options, 0);
  // Scaled from subnormal coordinates, the rounding grid of the original becomes coarse: a point
  // closer to an edge than a correct answer's rounding may move it is not judged.
  const double resolution = std::ldexp(constructionDisplacement(subject, clip, result), k);
  SampleVerdict v = sample(scaledBy(subject, k), scaledBy(clip, k), op, scaledBy(result, k), options, resolution);
  v.delta = std::ldexp(v.delta, -k);
  if (v.firstMismatch) v.firstMismatch = scaledBy(*v.firstMismatch, -k);
  return v;
}

}  // namespace gh::oracle
