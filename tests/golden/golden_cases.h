// The cases the golden pin test covers, and how a crossing list and an answer are fingerprinted.
//
// Golden data (variants.golden) pins, for every variant, the crossings phase 1 finds (edges and
// constructed points, in order along both operands) and the answers gh::clip returns, bit for bit,
// on the paper's Table 1 pools and on the degenerate families. It was written by the code before
// the variants were refactored onto two axes (issue 15); a refactoring or an optimisation must
// reproduce it exactly. A deliberate change of a decision is recorded in the file, line by line,
// with its reason.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "ghclip/operation.h"
#include "ghclip/region.h"

namespace gh::golden {

// FNV-1a over the bytes of the values fed to it.
class Fingerprint {
 public:
  void add(std::uint64_t v) {
    for (int i = 0; i < 8; ++i) {
      h_ ^= (v >> (8 * i)) & 0xff;
      h_ *= 0x100000001b3ull;
    }
  }
  void add(double d) {
    std::uint64_t bits;
    std::memcpy(&bits, &d, sizeof bits);
    add(bits);
  }
  void add(Point p) { add(p.x), add(p.y); }
  std::uint64_t value() const { return h_; }

 private:
  std::uint64_t h_ = 0xcbf29ce484222325ull;
};

// An answer: its rings in order, each ring's size and points.
inline std::uint64_t fingerprint(const Region& region) {
  Fingerprint f;
  f.add(static_cast<std::uint64_t>(region.size()));
  for (const Ring& ring : region) {
    f.add(static_cast<std::uint64_t>(ring.size()));
    for (const Point& p : ring) f.add(p);
  }
  return f.value();
}

// One workload instance.
struct Case {
  std::string workload;
  std::size_t n;
  std::uint64_t seed;
  std::vector<Op> ops;
};

// The paper's Table 1 pools (random n-gons, seeds 1000..1015 as in experiments/common) and the
// degenerate families with every magnitude suffix.
inline std::vector<Case> cases() {
  std::vector<Case> out;
  const std::vector<Op> all(std::begin(kAllOps), std::end(kAllOps));
  // Intersection, union and xor between them take every tracing direction (xor is the two
  // differences): the large pools run only these.
  const std::vector<Op> three{Op::Intersection, Op::Union, Op::Xor};
  for (std::size_t n : {10, 20, 50, 100, 200, 500, 1000, 2000}) {
    for (std::uint64_t seed = 1000; seed < 1016; ++seed) out.push_back({"random", n, seed, n <= 500 ? all : three});
  }
  for (const char* family : {"grid", "identical", "shared-edge", "touching-vertex", "nested-touching", "sliver",
                             "sub-boundary", "bitset-grid"}) {
    for (const char* suffix : {"", "+ulp", "+tiny", "+huge", "+far"}) {
      for (std::size_t n : {6, 20}) {
        for (std::uint64_t seed = 0; seed < 10; ++seed) {
          out.push_back({std::string(family) + suffix, n, seed, all});
        }
      }
    }
  }
  for (const char* realistic : {"simple", "holes", "circles", "coastline"}) {
    for (std::uint64_t seed = 0; seed < 5; ++seed) out.push_back({realistic, 200, seed, all});
  }
  return out;
}

inline std::string key(const std::string& variant, const Case& c) {
  return variant + " " + c.workload + " " + std::to_string(c.n) + " " + std::to_string(c.seed);
}

}  // namespace gh::golden
