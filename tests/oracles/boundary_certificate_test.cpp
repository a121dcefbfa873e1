// The boundary certificate (ghoracle/boundary_certificate.h): it proves the exact variant's
// answers right on degenerate inputs too, proves no wrong answer, and the sampling oracle passes
// whatever it proves.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "ghclip/clip.h"
#include "ghio/formats.h"
#include "ghoracle/boundary_certificate.h"
#include "ghoracle/sampling_oracle.h"

namespace gh {
namespace {

// Whether answer is certified as op's on S and C, alone.
bool certified(const Region& s, const Region& c, Op op, const Region& answer) {
  return oracle::certifiedAnswers(s, c, {{op, &answer}})[0];
}

// The exact variant's five answers are each certified, and the sampling oracle passes them.
void expectEveryAnswerCertified(const std::string& subject, const std::string& clipWkt) {
  const Region s = io::readWkt(subject), c = io::readWkt(clipWkt);
  std::vector<Region> answers;
  std::vector<std::pair<Op, const Region*>> judged;
  for (Op op : kAllOps) answers.push_back(clip(s, c, op));
  for (std::size_t i = 0; i < answers.size(); ++i) judged.emplace_back(kAllOps[i], &answers[i]);
  const std::vector<bool> proved = oracle::certifiedAnswers(s, c, judged);
  for (std::size_t i = 0; i < answers.size(); ++i) {
    EXPECT_TRUE(proved[i]) << name(kAllOps[i]) << " of " << subject << " and " << clipWkt;
    EXPECT_TRUE(oracle::sampleCheck(s, c, kAllOps[i], answers[i]).pass()) << name(kAllOps[i]);
  }
}

TEST(BoundaryCertificate, CertifiesTheExactAnswersInGeneralPosition) {
  expectEveryAnswerCertified("POLYGON((0 0,4 0,4 4,0 4,0 0))", "POLYGON((1 1,6 2,5 6,2 5,1 1))");
  // Crossings that are not doubles: rounded by the clipper, matched within 2 ulps.
  expectEveryAnswerCertified("POLYGON((0 0,3 0.1,2.9 3.3,0.2 2.7,0 0))", "POLYGON((1 -1,4.1 1.3,1.7 4.1,-0.3 1.1,1 -1))");
}

TEST(BoundaryCertificate, CertifiesTheExactAnswersOnDegenerateInputs) {
  // A shared edge (the union's seam dissolved), a shared vertex, a vertex on an edge.
  expectEveryAnswerCertified("POLYGON((0 0,2 0,2 2,0 2,0 0))", "POLYGON((2 0,4 0,4 2,2 2,2 0))");
  expectEveryAnswerCertified("POLYGON((0 0,2 0,2 2,0 2,0 0))", "POLYGON((2 2,4 2,4 4,2 4,2 2))");
  expectEveryAnswerCertified("POLYGON((0 0,4 0,4 4,0 4,0 0))", "POLYGON((2 0,3 -2,5 -1,2 0))");
  // The same polygon twice, and overlapping collinear edges.
  expectEveryAnswerCertified("POLYGON((0 0,4 0,4 4,0 4,0 0))", "POLYGON((0 0,4 0,4 4,0 4,0 0))");
  expectEveryAnswerCertified("POLYGON((0 0,4 0,4 4,0 4,0 0))", "POLYGON((1 0,6 0,6 3,1 3,1 0))");
  // Many edges through one point: two fans of triangles around the origin, one turned.
  expectEveryAnswerCertified("MULTIPOLYGON(((0 0,4 0,4 1,0 0)),((0 0,1 4,0 4,0 0)),((0 0,-4 0,-4 -1,0 0)),((0 0,-1 -4,0 -4,0 0)))",
                             "MULTIPOLYGON(((0 0,4 2,2 4,0 0)),((0 0,-4 -2,-2 -4,0 0)),((0 0,-4 3,-3 1,0 0)))");
  // A self-intersecting ring (even-odd) against a square through its crossing.
  expectEveryAnswerCertified("POLYGON((0 0,4 4,4 0,0 4,0 0))", "POLYGON((1 1,3 1,3 3,1 3,1 1))");
  // A ring of C that runs out along a line and back (a zero-width spike crossing S).
  expectEveryAnswerCertified("POLYGON((0 0,4 0,4 4,0 4,0 0))", "POLYGON((2 -1,6 -1,6 5,2 5,2 2,-2 2,2 2,2 -1))");
}

TEST(BoundaryCertificate, CertifiesEmptyAnswersAndEmptyOperands) {
  expectEveryAnswerCertified("POLYGON((0 0,1 0,1 1,0 1,0 0))", "POLYGON((5 5,6 5,6 6,5 6,5 5))");
  expectEveryAnswerCertified("POLYGON((0 0,1 0,1 1,0 1,0 0))", "GEOMETRYCOLLECTION EMPTY");
}

TEST(BoundaryCertificate, CertifiesAtMixedMagnitudes) {
  // A unit square crossed by a 1e15-long edge, and a problem at 1e-300.
  expectEveryAnswerCertified("POLYGON((0 0,1 0,1 1,0 1,0 0))", "POLYGON((-1e15 0.3,1e15 0.7,1e15 2e15,-1e15 0.3))");
  expectEveryAnswerCertified("POLYGON((0 0,3e-300 0,3e-300 3e-300,0 3e-300,0 0))",
                             "POLYGON((1e-300 -1e-300,4e-300 1.3e-300,2e-300 4e-300,1e-300 -1e-300))");
}

TEST(BoundaryCertificate, CertifiesNoWrongAnswer) {
  const Region s = io::readWkt("POLYGON((0 0,4 0,4 4,0 4,0 0))"), c = io::readWkt("POLYGON((1 1,6 2,5 6,2 5,1 1))");
  for (Op op : kAllOps) {
    const Region right = clip(s, c, op);
    ASSERT_TRUE(certified(s, c, op, right)) << name(op);
    // Another operation's answer.
    for (Op other : kAllOps) {
      if (other != op) EXPECT_FALSE(certified(s, c, op, clip(s, c, other))) << name(op) << " given " << name(other);
    }
    // A ring left out; a vertex moved by 1e-9; nothing.
    if (right.size() > 1) EXPECT_FALSE(certified(s, c, op, Region(right.begin() + 1, right.end()))) << name(op);
    Region moved = right;
    moved.front().front().x += 1e-9;
    EXPECT_FALSE(certified(s, c, op, moved)) << name(op);
    EXPECT_FALSE(certified(s, c, op, Region{})) << name(op);
  }
  // A rounded crossing moved by 64 ulps: beyond what a rounding may be.
  const Region s2 = io::readWkt("POLYGON((0 0,3 0.1,2.9 3.3,0.2 2.7,0 0))"), c2 = io::readWkt("POLYGON((1 -1,4.1 1.3,1.7 4.1,-0.3 1.1,1 -1))");
  Region nudged = clip(s2, c2, Op::Intersection);
  ASSERT_TRUE(certified(s2, c2, Op::Intersection, nudged));
  bool moved = false;
  for (Point& p : nudged.front()) {
    const bool vertex = (p.x == 0 && p.y == 0) || (p.x == 3 && p.y == 0.1) || (p.x == 2.9 && p.y == 3.3) || (p.x == 0.2 && p.y == 2.7);
    if (!vertex && !moved) p.x += 64 * (std::nextafter(p.x, 10.0) - p.x), moved = true;
  }
  ASSERT_TRUE(moved);
  EXPECT_FALSE(certified(s2, c2, Op::Intersection, nudged));
  // A non-finite answer.
  Region infinite = clip(s, c, Op::Union);
  infinite.front().front().x = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(certified(s, c, Op::Union, infinite));
}

// An answer with a zero-width spike bounds the same interior (even-odd): certified, and left to
// the invariants, which flag spikes (ghoracle/invariants.h).
TEST(BoundaryCertificate, JudgesInteriorsNotRings) {
  const Region s = io::readWkt("POLYGON((0 0,2 0,2 2,0 2,0 0))"), c = io::readWkt("POLYGON((1 1,3 1,3 3,1 3,1 1))");
  const Region spiked = io::readWkt("POLYGON((1 1,2 1,2 2,1 2,1 1.5,0.5 1.5,1 1.5,1 1))");
  EXPECT_TRUE(certified(s, c, Op::Intersection, spiked));
}

}  // namespace
}  // namespace gh
