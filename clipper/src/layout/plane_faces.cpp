#include "layout/plane_faces.h"

#include <algorithm>
#include <numeric>
#include <set>
#include <stdexcept>

#include "predicates/orientation.h"

namespace gh::detail {
namespace {

constexpr std::uint32_t kNone = 0xffffffffu;

bool lexLess(Point a, Point b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }

// Half-edge h of edge h / 2: even ones run from the edge's lexicographically smaller end ("left")
// to its larger one, odd ones back.
class Faces {
 public:
  Faces(const PlaneGraph& g, ExactCounters& counters) : g_(g), counters_(counters) {}

  std::vector<PolygonWithHoles> run() {
    orderVertices();
    rotations();
    sweep();
    walks();
    return polygons();
  }

 private:
  std::uint32_t edgeCount() const { return static_cast<std::uint32_t>(g_.edges.size()); }
  std::uint32_t origin(std::uint32_t h) const { return h & 1 ? right_[h / 2] : left_[h / 2]; }
  std::uint32_t target(std::uint32_t h) const { return origin(h ^ 1); }
  Point at(std::uint32_t v) const { return g_.vertices[v]; }

  void orderVertices() {
    rank_.resize(g_.vertices.size());
    byRank_.resize(g_.vertices.size());
    std::iota(byRank_.begin(), byRank_.end(), 0u);
    std::stable_sort(byRank_.begin(), byRank_.end(), [&](std::uint32_t a, std::uint32_t b) { return lexLess(at(a), at(b)); });
    for (std::uint32_t r = 0; r < byRank_.size(); ++r) rank_[byRank_[r]] = r;
    left_.resize(edgeCount()), right_.resize(edgeCount());
    for (std::uint32_t e = 0; e < edgeCount(); ++e) {
      auto [a, b] = g_.edges[e];
      if (rank_[b] < rank_[a]) std::swap(a, b);
      left_[e] = a, right_[e] = b;
    }
  }

  // The half-edges leaving each vertex in counter-clockwise order, from the direction of +x.
  void rotations() {
    start_.assign(g_.vertices.size() + 1, 0);
    for (std::uint32_t h = 0; h < 2 * edgeCount(); ++h) ++start_[origin(h) + 1];
    for (std::size_t v = 0; v < g_.vertices.size(); ++v) start_[v + 1] += start_[v];
    around_.resize(2 * std::size_t{edgeCount()});
    std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
    for (std::uint32_t h = 0; h < 2 * edgeCount(); ++h) around_[fill[origin(h)]++] = h;
    place_.resize(around_.size());
    for (std::uint32_t v = 0; v < g_.vertices.size(); ++v) {
      const Point o = at(v);
      // Upper half-plane (with +x) before the lower one (with -x); within one, counter-clockwise.
      auto half = [&](std::uint32_t h) {
        const Point t = at(target(h));
        return t.y > o.y || (t.y == o.y && t.x > o.x) ? 0 : 1;
      };
      std::sort(around_.begin() + start_[v], around_.begin() + start_[v + 1], [&](std::uint32_t a, std::uint32_t b) {
        const int ha = half(a), hb = half(b);
        if (ha != hb) return ha < hb;
        return orientation(o, at(target(a)), at(target(b)), counters_) == Sign::Positive;
      });
      if ((start_[v + 1] - start_[v]) % 2 != 0) throw std::logic_error("OGC layout: a vertex of odd degree");
      for (std::uint32_t i = start_[v]; i < start_[v + 1]; ++i) place_[around_[i]] = i;
    }
  }
  // The half-edges leaving origin(h) just counter-clockwise and clockwise of h.
  std::uint32_t ccwNext(std::uint32_t h) const {
    const std::uint32_t v = origin(h), i = place_[h] + 1;
    return around_[i == start_[v + 1] ? start_[v] : i];
  }
  std::uint32_t cwNext(std::uint32_t h) const {
    const std::uint32_t v = origin(h), i = place_[h];
    return around_[i == start_[v] ? start_[v + 1] - 1 : i - 1];
  }

  // Edges crossed by the sweep line, from bottom to top. Edges of a plane graph cross nowhere, so
  // their vertical order does not change while both are crossed: it is decided where the later
  // one starts. kProbe stands for the vertex being located.
  static constexpr std::uint32_t kProbe = kNone;
  struct Below {
    const Faces* f;
    bool operator()(std::uint32_t a, std::uint32_t b) const { return f->below(a, b); }
  };
  bool below(std::uint32_t a, std::uint32_t b) const {
    if (a == b) return false;
    if (a == kProbe) return orientation(at(left_[b]), at(right_[b]), probe_, counters_) == Sign::Negative;
    if (b == kProbe) return orientation(at(left_[a]), at(right_[a]), probe_, counters_) == Sign::Positive;
    if (left_[a] == left_[b]) {
      return orientation(at(left_[a]), at(right_[a]), at(right_[b]), counters_) == Sign::Positive;
    }
    if (rank_[left_[a]] > rank_[left_[b]]) {
      return orientation(at(left_[b]), at(right_[b]), at(left_[a]), counters_) == Sign::Negative;
    }
    return orientation(at(left_[a]), at(right_[a]), at(left_[b]), counters_) == Sign::Positive;
  }

  // Components of the graph, their leftmost vertices, which side of each edge the region is on
  // (inLeft_ per half-edge), and the edge just below each component's leftmost vertex.
  void sweep() {
    component_.assign(g_.vertices.size(), kNone);
    inLeft_.assign(2 * std::size_t{edgeCount()}, -1);
    std::set<std::uint32_t, Below> crossed(Below{this});
    std::vector<std::set<std::uint32_t, Below>::iterator> where(edgeCount());
    for (const std::uint32_t v : byRank_) {
      if (start_[v] == start_[v + 1]) continue;  // no edge: a node that rounded away
      for (std::uint32_t i = start_[v]; i < start_[v + 1]; ++i) {
        const std::uint32_t h = around_[i];
        if (h & 1) crossed.erase(where[h / 2]);  // the edge ends here
      }
      if (component_[v] == kNone) {
        probe_ = at(v);
        const auto above = crossed.upper_bound(kProbe);
        const std::uint32_t under = above == crossed.begin() ? kNone : *std::prev(above);
        orientComponent(v, under);
      }
      for (std::uint32_t i = start_[v]; i < start_[v + 1]; ++i) {
        const std::uint32_t h = around_[i];
        if (!(h & 1)) where[h / 2] = crossed.insert(h / 2).first;
      }
    }
  }

  // v is the leftmost vertex of a component not yet seen; `under` the edge just below it (or none).
  void orientComponent(std::uint32_t v, std::uint32_t under) {
    const std::uint32_t c = static_cast<std::uint32_t>(componentUnder_.size());
    // Just below v lies the face above `under`: inside iff `under`, from left to right, has the
    // region on its left (above it).
    const bool insideBelow = under != kNone && inLeft_[2 * under] == 1;
    componentUnder_.push_back(insideBelow ? 2 * under : kNone);
    // Every edge at v leaves it rightwards or straight up: the sector holding the downward
    // direction lies left of the highest of them, clockwise of which the region alternates.
    std::uint32_t highest = around_[start_[v]];
    for (std::uint32_t i = start_[v] + 1; i < start_[v + 1]; ++i) {
      const std::uint32_t h = around_[i];
      if (orientation(at(v), at(target(highest)), at(target(h)), counters_) == Sign::Positive) highest = h;
    }
    componentSeed_.push_back(highest);
    // Breadth first over the component: the other side of an edge, and the next edge around a
    // vertex, have the region on the other side.
    std::vector<std::uint32_t> queue{highest};
    auto set = [&](std::uint32_t h, bool value) {
      if (inLeft_[h] == -1) {
        inLeft_[h] = value;
        queue.push_back(h);
      } else if ((inLeft_[h] == 1) != value) {
        throw std::logic_error("OGC layout: the region's sides do not alternate around a vertex");
      }
    };
    inLeft_[highest] = insideBelow;
    component_[v] = c;
    for (std::size_t k = 0; k < queue.size(); ++k) {
      const std::uint32_t h = queue[k];
      const bool in = inLeft_[h] == 1;
      component_[target(h)] = c;
      set(h ^ 1, !in);
      set(ccwNext(h), !in);
    }
  }

  // The walks around the faces of the region: from a half-edge with the region on its left, on
  // to the half-edge leaving its target just clockwise of the way back.
  void walks() {
    walkOf_.assign(2 * std::size_t{edgeCount()}, kNone);
    for (std::uint32_t h0 = 0; h0 < 2 * edgeCount(); ++h0) {
      if (inLeft_[h0] != 1 || walkOf_[h0] != kNone) continue;
      const std::uint32_t w = static_cast<std::uint32_t>(walkStart_.size());
      walkStart_.push_back(static_cast<std::uint32_t>(walkHalfEdges_.size()));
      std::uint32_t h = h0;
      do {
        walkOf_[h] = w;
        walkHalfEdges_.push_back(h);
        h = cwNext(h ^ 1);
        if (inLeft_[h] != 1) throw std::logic_error("OGC layout: a face walk left the region");
      } while (h != h0);
    }
    walkStart_.push_back(static_cast<std::uint32_t>(walkHalfEdges_.size()));
  }

  // Each walk cut at the vertices it returns to into simple rings; counter-clockwise ones are
  // shells. A walk with a shell is a face's outer boundary, and its other rings are holes of that
  // shell touching it; a walk without one goes around a component from the outside, inside the
  // face of the walk of the edge just below that component's leftmost vertex.
  std::vector<PolygonWithHoles> polygons() {
    const std::size_t walkCount = walkStart_.size() - 1;
    std::vector<std::uint32_t> polygonOfWalk(walkCount, kNone);
    std::vector<std::vector<Ring>> holesOfWalk(walkCount);
    std::vector<PolygonWithHoles> out;
    std::vector<std::uint32_t> positionOf(g_.vertices.size(), kNone);
    std::vector<std::uint32_t> stack;
    for (std::uint32_t w = 0; w < walkCount; ++w) {
      stack.clear();
      std::vector<Ring> rings;
      auto cut = [&](std::size_t from) {
        Ring ring;
        for (std::size_t i = from; i < stack.size(); ++i) ring.push_back(at(stack[i])), positionOf[stack[i]] = kNone;
        stack.resize(from);
        rings.push_back(std::move(ring));
      };
      for (std::uint32_t i = walkStart_[w]; i < walkStart_[w + 1]; ++i) {
        const std::uint32_t v = origin(walkHalfEdges_[i]);
        if (positionOf[v] != kNone) cut(positionOf[v]);
        positionOf[v] = static_cast<std::uint32_t>(stack.size());
        stack.push_back(v);
      }
      cut(0);
      for (Ring& ring : rings) {
        if (counterClockwise(ring)) {
          if (polygonOfWalk[w] != kNone) throw std::logic_error("OGC layout: a face walk with two shells");
          polygonOfWalk[w] = static_cast<std::uint32_t>(out.size());
          out.push_back({std::move(ring), {}});
        } else {
          holesOfWalk[w].push_back(std::move(ring));
        }
      }
    }
    // Walks without a shell: the face they lie in, through the walk below each component.
    std::vector<std::uint32_t> polygonOfComponent(componentSeed_.size(), kNone);
    for (std::uint32_t c = 0; c < componentSeed_.size(); ++c) {
      const std::uint32_t under = componentUnder_[c];
      if (under == kNone) continue;
      const std::uint32_t w = walkOf_[under];
      // The walk below is a face's outer boundary, or the outside of an earlier component in the
      // same face (components are met from left to right, so that one is known).
      const std::uint32_t p = polygonOfWalk[w] != kNone ? polygonOfWalk[w] : polygonOfComponent[component_[origin(under)]];
      if (p == kNone) throw std::logic_error("OGC layout: a component in no face");
      polygonOfComponent[c] = p;
      const std::uint32_t inner = walkOf_[componentSeed_[c]];
      if (polygonOfWalk[inner] != kNone) throw std::logic_error("OGC layout: a component's outside walk has a shell");
      polygonOfWalk[inner] = p;
    }
    for (std::uint32_t w = 0; w < walkCount; ++w) {
      if (holesOfWalk[w].empty()) continue;
      if (polygonOfWalk[w] == kNone) throw std::logic_error("OGC layout: holes in no polygon");
      for (Ring& h : holesOfWalk[w]) out[polygonOfWalk[w]].holes.push_back(std::move(h));
    }
    return out;
  }

  // A simple ring's orientation, exactly: the turn at its lexicographically smallest vertex.
  bool counterClockwise(const Ring& ring) const {
    const std::size_t n = ring.size();
    std::size_t m = 0;
    for (std::size_t i = 1; i < n; ++i) {
      if (lexLess(ring[i], ring[m])) m = i;
    }
    return orientation(ring[(m + n - 1) % n], ring[m], ring[(m + 1) % n], counters_) == Sign::Positive;
  }

  const PlaneGraph& g_;
  ExactCounters& counters_;
  std::vector<std::uint32_t> rank_, byRank_, left_, right_;
  std::vector<std::uint32_t> start_, around_, place_;
  std::vector<std::uint32_t> component_;  // per vertex
  std::vector<std::int8_t> inLeft_;       // per half-edge: 1 the region on its left, 0 not, -1 unknown
  std::vector<std::uint32_t> componentUnder_, componentSeed_;  // per component
  std::vector<std::uint32_t> walkOf_, walkStart_, walkHalfEdges_;
  Point probe_{};
};

}  // namespace

std::vector<PolygonWithHoles> planeFaces(const PlaneGraph& graph, ExactCounters& counters) {
  return Faces(graph, counters).run();
}

}  // namespace gh::detail
