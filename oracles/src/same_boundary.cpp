#include "ghoracle/same_boundary.h"

#include <algorithm>
#include <tuple>
#include <vector>

namespace gh::oracle {
namespace {

using Segment = std::pair<Point, Point>;

bool before(Point p, Point q) { return std::tie(p.x, p.y) < std::tie(q.x, q.y); }

// Every edge of the region as an undirected segment (its ends in lexicographic order), those
// present an even number of times cancelled, sorted.
std::vector<Segment> edgesModTwo(const Region& r) {
  std::vector<Segment> all;
  for (const Ring& ring : r) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      Point p = ring[i], q = ring[(i + 1) % ring.size()];
      if (p == q) continue;
      if (before(q, p)) std::swap(p, q);
      all.emplace_back(p, q);
    }
  }
  const auto less = [](const Segment& s, const Segment& t) {
    return std::tie(s.first.x, s.first.y, s.second.x, s.second.y) < std::tie(t.first.x, t.first.y, t.second.x, t.second.y);
  };
  std::sort(all.begin(), all.end(), less);
  std::vector<Segment> odd;
  for (std::size_t i = 0, j; i < all.size(); i = j) {
    for (j = i + 1; j < all.size() && all[j] == all[i]; ++j) {
    }
    if ((j - i) % 2 == 1) odd.push_back(all[i]);
  }
  return odd;
}

}  // namespace

bool sameBoundaryModTwo(const Region& a, const Region& b) { return edgesModTwo(a) == edgesModTwo(b); }

}  // namespace gh::oracle
