// The oracles pass correct answers and fail damaged ones, with the exact error area of the damage.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "ghclip/clip.h"
#include "ghclip/measure.h"
#include "ghoracle/exact_oracle.h"
#include "ghoracle/invariants.h"
#include "ghoracle/sampling_oracle.h"
#include "ghwork/generators.h"
#include "common/hand_cases.h"
#include "ghio/formats.h"

namespace gh {
namespace {

using test::HandCase;

Ring rect(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

TEST(Oracles, PassEveryHandCaseAnswer) {
  for (const HandCase& c : test::handCases()) {
    for (int k = 0; k < 5; ++k) {
      const Op op = kAllOps[k];
      const Region r = clip(c.subject, c.clip, op);
      const auto exact = oracle::exactCheck(c.subject, c.clip, op, r);
      EXPECT_TRUE(exact.pass) << c.name << " " << name(op) << " error " << exact.errorArea;
      EXPECT_NEAR(exact.expectedArea, c.expected[k], 1e-12 * std::max(1.0, c.expected[k]))
          << c.name << " " << name(op);
      EXPECT_TRUE(oracle::sampleCheck(c.subject, c.clip, op, r).pass()) << c.name << " " << name(op);
      EXPECT_TRUE(oracle::invariantViolations(c.subject, c.clip, op, r).empty()) << c.name;
    }
  }
}

// The acceptance case: a correct answer with several rings passes; without its last
// ring it fails with an error area equal to that ring's area.
TEST(Oracles, PentagramAnswerWithoutItsLastRing) {
  const Region star = test::handCase("pentagram_in_square").subject;
  const Region square{rect(-2, -0.7, 2, -0.45)};  // cuts the two lower points apart
  Region r = clip(star, square, Op::Intersection);
  ASSERT_GE(r.size(), 2u);
  EXPECT_TRUE(oracle::exactCheck(star, square, Op::Intersection, r).pass);
  const double lastRing = evenOddArea({r.back()});
  r.pop_back();
  const auto v = oracle::exactCheck(star, square, Op::Intersection, r);
  EXPECT_FALSE(v.pass);
  EXPECT_NEAR(v.errorArea, lastRing, 1e-9 * lastRing);
}

// A finding, pinned: on degenerate input the naive variant moves vertices (the paper's
// perturbation), so the exact oracle fails its answer, by an error area of the size of the move
// (2^-42 of the largest coordinate times the edge lengths), not by anything gross.
TEST(Oracles, NaivePerturbationIsSeenAsASmallNonRoundingError) {
  const Region s{rect(0, 0, 2, 2)};
  const Region shared{rect(2, 0, 4, 2)};  // shares the edge x = 2
  for (const Region* c : {&s, &shared}) {
    Stats stats;
    const Region r = clip(s, *c, Op::Union, optionsOf(Variant::Naive), &stats);
    EXPECT_GT(stats.perturbations, 0u);
    const auto v = oracle::exactCheck(s, *c, Op::Union, r);
    EXPECT_FALSE(v.pass);
    EXPECT_GT(v.beyondRoundingArea, 0);
    EXPECT_LT(v.relativeError(), 1e-11);
  }
}

// Damaged answers: (subject, clip, op, damaged result, exact area of the damage).
struct Damage {
  std::string what;
  Region subject, clip;
  Op op;
  Region result;
  double damageArea;
};

std::vector<Damage> damages() {
  std::vector<Damage> out;
  // The gate's intersection with the square is two 1 x 2 rings; drop the last one.
  const HandCase& gate = test::handCase("figure7_gate");
  Region two = clip(gate.subject, gate.clip, Op::Intersection);
  two.pop_back();
  out.push_back({"ring dropped", gate.subject, gate.clip, Op::Intersection, two, 2});
  // Square [0,4]^2 with hole [1,3]^2 inside a larger clip: the answer is the subject itself;
  // losing the hole adds its area 4.
  const Region holed{rect(0, 0, 4, 4), rect(1, 1, 3, 3)};
  out.push_back({"hole lost", holed, {rect(-1, -1, 5, 5)}, Op::Intersection, {rect(0, 0, 4, 4)}, 4});
  // [0,2]^2 n [1,3]^2 = [1,2]^2; move its corner (2,2) right by 1e-6 of the extent 3: the region
  // gains the triangle (2,1), (2+d,2), (2,2) of area d/2.
  const double d = 3e-6;
  out.push_back({"vertex moved", {rect(0, 0, 2, 2)}, {rect(1, 1, 3, 3)}, Op::Intersection,
                 {{{1, 1}, {2, 1}, {2 + d, 2}, {1, 2}}}, d / 2});
  // Union given for intersection: 7 instead of 1.
  out.push_back({"operation confused", {rect(0, 0, 2, 2)}, {rect(1, 1, 3, 3)}, Op::Intersection,
                 clip({rect(0, 0, 2, 2)}, {rect(1, 1, 3, 3)}, Op::Union), 6});
  return out;
}

TEST(Oracles, FailDamagedAnswersWithTheExactDamageArea) {
  for (const Damage& dmg : damages()) {
    const auto exact = oracle::exactCheck(dmg.subject, dmg.clip, dmg.op, dmg.result);
    EXPECT_FALSE(exact.pass) << dmg.what;
    EXPECT_NEAR(exact.errorArea, dmg.damageArea, 1e-9 * dmg.damageArea) << dmg.what;
    ASSERT_TRUE(exact.witness.has_value()) << dmg.what;
    // The witness lies where the answer is wrong.
    const Point w = *exact.witness;
    EXPECT_NE(insideEvenOdd(dmg.result, w),
              apply(dmg.op, insideEvenOdd(dmg.subject, w), insideEvenOdd(dmg.clip, w)))
        << dmg.what;
    EXPECT_FALSE(oracle::sampleCheck(dmg.subject, dmg.clip, dmg.op, dmg.result).pass()) << dmg.what;
  }
}

TEST(Oracles, ExactAnswerHasTheExpectedArea) {
  for (const HandCase& c : test::handCases()) {
    for (int k = 0; k < 5; ++k) {
      EXPECT_NEAR(evenOddArea(oracle::exactAnswer(c.subject, c.clip, kAllOps[k])), c.expected[k],
                  1e-9 * std::max(1.0, c.expected[k]))
          << c.name << " " << name(kAllOps[k]);
    }
  }
}

TEST(Oracles, OverlappingSegmentsCountWithMultiplicity) {
  // R = S drawn twice is the empty set under even-odd; S alone is the answer to S n S.
  const Region s{rect(0, 0, 1, 1)};
  const Region twice{rect(0, 0, 1, 1), rect(0, 0, 1, 1)};
  EXPECT_TRUE(oracle::exactCheck(s, s, Op::Intersection, s).pass);
  const auto v = oracle::exactCheck(s, s, Op::Intersection, twice);
  EXPECT_FALSE(v.pass);
  EXPECT_DOUBLE_EQ(v.errorArea, 1);
}

TEST(Oracles, InvariantsCatchImpossibleAreas) {
  const Region a{rect(0, 0, 2, 2)}, b{rect(1, 1, 3, 3)};
  EXPECT_FALSE(oracle::invariantViolations(a, b, Op::Intersection, {rect(0, 0, 3, 3)}).empty());
  EXPECT_FALSE(oracle::invariantViolations(a, b, Op::Union, {rect(0, 0, 1, 1)}).empty());
  EXPECT_FALSE(
      oracle::invariantViolations(a, b, Op::Intersection, {{{1, 1}, {1, 1}, {2, 2}, {1, 2}}}).empty());
}

// Rings that enclose nothing, and spikes, are debris the clean-up must remove: caught whatever their size,
// with collinearity decided exactly (a point one ulp off the line makes a real triangle).
TEST(Oracles, InvariantsCatchRingsThatEncloseNothing) {
  const Region a{rect(0, 0, 2, 2)}, b{rect(1, 1, 3, 3)};
  const auto with = [](Ring extra) { return Region{rect(1, 1, 2, 2), std::move(extra)}; };
  const auto first = [&](const Region& r) {
    const auto v = oracle::invariantViolations(a, b, Op::Intersection, r);
    return v.empty() ? std::string() : v.front();
  };
  EXPECT_EQ(first({rect(1, 1, 2, 2)}), "");
  EXPECT_EQ(first(with({{1, 1}, {2, 2}})), "ring 2 has fewer than 3 vertices");
  EXPECT_EQ(first(with({{1, 1}, {1.5, 1.5}, {2, 2}})), "ring 2 has all its vertices on one line");
  EXPECT_EQ(first(with({{1e300, 1e300}, {-1e300, -1e300}, {0.5, 0.5}, {1e-300, 1e-300}})), "ring 2 has all its vertices on one line");
  EXPECT_EQ(first(with({{1, 1}, {1.5, std::nextafter(1.5, 2.0)}, {2, 2}})), "");
  EXPECT_EQ(first({{{1, 1}, {2, 1}, {2, 2}, {1.5, 2}, {1.5, 3}, {1.5, 2}, {1, 2}}}), "ring 1 folds back on itself at vertex 5 (a zero-width spike)");
  EXPECT_EQ(first({{{1, 1}, {2, 1}, {2, 2}, {1, 2}, {1, 0.5}}}), "ring 1 folds back on itself at vertex 5 (a zero-width spike)");
  EXPECT_EQ(first({{{1, 1}, {1.5, 1}, {2, 1}, {2, 2}, {1, 2}}}), "");  // straight on is not a spike
}

// 400 seeded cases of the paper's workload (n = 5..50, all five operations): the two oracles
// must reach the same verdict. Half the answers are damaged (largest ring dropped) so that both
// verdicts are exercised.
TEST(Oracles, AgreeOnTheRandomWorkload) {
  int agree = 0, passes = 0, fails = 0;
  for (int i = 0; i < 400; ++i) {
    const std::size_t n = 5 + static_cast<std::size_t>(i) % 46;
    const Region s{work::randomRing(n, 2 * i + 1)}, c{work::randomRing(n, 2 * i + 2)};
    const Op op = kAllOps[i % 5];
    Region r = clip(s, c, op);
    if (i % 2 == 1 && !r.empty()) {
      auto largest = std::max_element(r.begin(), r.end(), [](const Ring& a, const Ring& b) {
        return std::abs(signedArea(a)) < std::abs(signedArea(b));
      });
      r.erase(largest);
    }
    const bool exact = oracle::exactCheck(s, c, op, r, {false, false, false}).pass;
    oracle::SampleOptions so;
    so.seed = static_cast<std::uint64_t>(i);
    const bool sample = oracle::sampleCheck(s, c, op, r, so).pass();
    EXPECT_EQ(exact, sample) << "case " << i << " n=" << n << " " << name(op);
    agree += exact == sample;
    (exact ? passes : fails)++;
  }
  RecordProperty("agreements", agree);
  EXPECT_GT(passes, 120);
  EXPECT_GT(fails, 120);
}

// The answers of one S and C judged together (one arrangement, shared sample points) get the
// verdicts each gets alone (the zone count may differ: faces cut finer by the other answers'
// edges have smaller boxes, so fewer zones that could not excuse anything are built): on the random workload and on grid cases (shared vertices, overlapping
// edges), right answers, damaged ones (largest ring dropped), naive answers (rounding errors
// beyond the zones), a wrong operation's answer, and answers reaching beyond S and C's box.
TEST(Oracles, AnswersJudgedTogetherGetTheirOwnVerdicts) {
  int fails = 0, passes = 0, violating = 0, jointlyOnly = 0;
  for (int i = 0; i < 60; ++i) {
    const std::size_t n = 4 + static_cast<std::size_t>(i) % 12;
    const bool grid = i % 3 == 0;
    const Region s = grid ? work::generate("grid", n, i + 1).subject : Region{work::randomRing(n, 2 * i + 1)};
    const Region c = grid ? work::generate("grid", n, i + 1).clip : Region{work::randomRing(n, 2 * i + 2)};
    std::vector<oracle::Answer> answers;
    for (Op op : kAllOps) {
      Region r = clip(s, c, op, optionsOf(i % 2 ? Variant::Naive : Variant::Exact));
      if (i % 4 == 1 && !r.empty()) {
        r.erase(std::max_element(r.begin(), r.end(), [](const Ring& a, const Ring& b) {
          return std::abs(signedArea(a)) < std::abs(signedArea(b));
        }));
      }
      answers.push_back({op, std::move(r)});
    }
    answers.push_back({Op::Union, answers[0].result});                         // a wrong operation's answer
    answers.push_back({Op::Intersection, {{{-1, -1}, {20, -1}, {20, 20}}}});  // beyond the box
    const auto together = oracle::exactCheckAll(s, c, answers);
    oracle::SampleOptions so;
    so.seed = static_cast<std::uint64_t>(i);
    oracle::SamplingJudge judge(s, c, so);
    const oracle::InvariantJudge invariants(s, c);
    // All the answers in one sampling check (as the fuzz targets judge their five): a mismatch
    // found for an answer alone is found, and an answer the exact oracle passes passes.
    std::vector<std::pair<Op, const Region*>> all;
    for (const oracle::Answer& a : answers) all.emplace_back(a.op, &a.result);
    const auto sampledJointly = judge.check(all);
    for (std::size_t j = 0; j < answers.size(); ++j) {
      const auto violations = invariants.violations(answers[j].op, answers[j].result);
      EXPECT_EQ(violations, oracle::invariantViolations(s, c, answers[j].op, answers[j].result)) << i << " " << j;
      violating += !violations.empty();
      const auto alone = oracle::exactCheck(s, c, answers[j].op, answers[j].result);
      EXPECT_EQ(together[j].pass, alone.pass) << i << " " << j;
      EXPECT_EQ(together[j].errorAreaExact, alone.errorAreaExact) << i << " " << j;
      EXPECT_EQ(together[j].beyondRoundingAreaExact, alone.beyondRoundingAreaExact) << i << " " << j;
      (alone.pass ? passes : fails)++;
      const auto sampledAlone = oracle::sampleCheck(s, c, answers[j].op, answers[j].result, so);
      const auto sampledTogether = judge.check(answers[j].op, answers[j].result);
      EXPECT_EQ(sampledTogether.checked, sampledAlone.checked) << i << " " << j;
      EXPECT_EQ(sampledTogether.skipped, sampledAlone.skipped) << i << " " << j;
      EXPECT_EQ(sampledTogether.mismatched, sampledAlone.mismatched) << i << " " << j;
      if (!sampledAlone.pass()) EXPECT_FALSE(sampledJointly[j].pass()) << i << " " << j;
      if (alone.pass) EXPECT_TRUE(sampledJointly[j].pass()) << i << " " << j;
      jointlyOnly += sampledAlone.pass() && !sampledJointly[j].pass();
    }
    std::vector<std::pair<Region, Region>> pairs;
    for (std::size_t j = 0; j + 1 < answers.size(); j += 2) pairs.emplace_back(answers[j].result, answers[j + 1].result);
    const auto differences = oracle::symmetricDifferenceAreas(pairs);
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      const double alone = oracle::exactCheck(pairs[k].first, {}, Op::Union, pairs[k].second, {false, false, false}).errorArea;
      EXPECT_NEAR(differences[k], alone, 1e-12 * (1 + alone)) << i << " " << k;
    }
  }
  EXPECT_GT(passes, 100);
  EXPECT_GT(fails, 60);
  EXPECT_GT(violating, 20);
  std::printf("sampling: %d wrong answers found only when judged with the others\n", jointlyOnly);
}

// The invariants' operand areas, measured once, at the ends of the double range too: a judge
// that kept them at the wrong scale, or for an answer that changes the scale, says otherwise.
TEST(Oracles, InvariantsJudgedTogetherGetTheirOwnVerdicts) {
  for (double scale : {1.0, 0x1p-1060, 0x1p-600, 0x1p400, 0x1p480}) {
    const auto scaled = [&](Ring r) {
      for (Point& p : r) p = {p.x * scale, p.y * scale};
      return r;
    };
    const Region s{scaled(rect(0, 0, 4, 4))}, c{scaled(rect(2, 2, 6, 6))};
    const oracle::InvariantJudge invariants(s, c);
    std::vector<std::pair<Op, Region>> answers;
    for (Op op : kAllOps) answers.push_back({op, clip(s, c, op)});
    answers.push_back({Op::Intersection, {scaled(rect(0, 0, 6, 6))}});              // too large
    answers.push_back({Op::Union, {scaled(rect(0, 0, 1, 1))}});                     // too small
    // Too large, with a ring that no common scale holds exactly next to 2^-1060.
    answers.push_back({Op::Union, {scaled(rect(0, 0, 6, 6)), rect(0, 0, 0.1, 0x1p-30)}});
    int violating = 0;
    for (const auto& [op, r] : answers) {
      const auto violations = invariants.violations(op, r);
      EXPECT_EQ(violations, oracle::invariantViolations(s, c, op, r)) << scale << " " << name(op);
      violating += !violations.empty();
    }
    EXPECT_EQ(violating, 3) << scale;
  }
}

// Judging at the ends of the double range (the clip's own tests at those scales are in
// tests/clipper/clip_test.cpp).
// fuzz_clip_exact_oracle: the exact answer is a sliver whose constructed vertices, rounded to the
// nearest doubles, all lie on one line; the rounded ring bounds nothing and is dropped. That is a
// rounding-level error: the tolerance must count the exact answer's constructed vertices, not
// only the result's (there are none).
TEST(ExtremeMagnitudes, AnswerFlattenedByRoundingIsWithinTolerance) {
  const Region s = io::readWkt("MULTIPOLYGON(((0 0,0 4,3 5,0 2.0000000000000013,0 0)))");
  const Region c = io::readWkt(
      "MULTIPOLYGON(((0 2,4.0000000000001137 0,1 0,5 3,3 3,3 2,4 -9.8813129168249309e-324,0 2)),"
      "((0 4,4.9406564584124654e-324 0,0 0,0 0,0 0,0 4)))");
  const Region r = clip(s, c, Op::Intersection);
  const auto v = oracle::exactCheck(s, c, Op::Intersection, r);
  EXPECT_NE(v.errorAreaExact, "0");  // not exactly right: the answer has area ~2.5e-323
  EXPECT_TRUE(v.pass);
  // A real error of that size still fails: drop the answer of a normal-sized problem.
  const Region big{rect(0, 0, 1, 1)};
  EXPECT_FALSE(oracle::exactCheck(big, big, Op::Intersection, {}).pass);
}

// fuzz_clip_exact: areas of ~1e-323 measured in doubles are off by denormals; the union
// invariant must allow for the measurement's own error.
TEST(ExtremeMagnitudes, InvariantsAllowForDenormalAreaMeasurement) {
  const Region s = io::readWkt(
      "MULTIPOLYGON(((4.0000000000001137 5,-9.8813129168249309e-324 0,0 0,0 0,0 0,0 0,0.5 0.5,0 0,0 0,0 0,"
      "0 -1.4821969375237396e-323,0 3,0 1,0 0,4.0000000000001137 5)),((0 -1.4821969375237396e-323,0 0,"
      "2.001953125 0,0 -1.4821969375237396e-323)))");
  const Region r = clip(s, {}, Op::Union);
  EXPECT_TRUE(oracle::exactCheck(s, {}, Op::Union, r).pass);
  EXPECT_TRUE(oracle::invariantViolations(s, {}, Op::Union, r).empty());
}

// Issue 17's cases: the tolerance is each constructed vertex's own rounding, so a small feature
// next to huge coordinates is judged at its own resolution. Each answer must pass both oracles;
// every candidate that misses the small feature must fail both.
struct MixedCase {
  const char* name;
  Region subject, clip;
  Op op;
};

std::vector<MixedCase> mixedMagnitudeCases() {
  const double big = 1125899906842624;  // 2^50
  const Ring star{{0, 2}, {0.5, 0.5}, {2, 0}, {0.5, -0.5}, {0, -2}, {-0.5, -0.5}, {-2, 0}, {-0.5, 0.5}};
  auto scaled = [](Ring r, double f) {
    for (Point& p : r) p = {p.x * f, p.y * f};
    return r;
  };
  return {
      // The first case: a 2^50 triangle whose edge y = x / 2 cuts the unit square.
      {"big triangle, unit square",
       {{{-big, -big / 2}, {big, big / 2}, {big, big}}},
       {rect(-1, -1, 1, 1)},
       Op::Intersection},
      // The same edge with crossings that are not doubles (a star of 1/3-ish slopes).
      {"big triangle, small star",
       {{{-big, -big / 2}, {big, big / 2}, {big, big}}},
       {star},
       Op::Intersection},
      // A +-1e10 triangle holding a 1e-10 hole, against a 1e-10 square over the hole's corner.
      {"1e10 triangle with 1e-10 hole",
       {{{-1e10, -1e10}, {1e10, -1e10}, {0, 1e10}}, rect(-1e-10, -1e-10, 1e-10, 1e-10)},
       {scaled(star, 1e-10)},
       Op::Intersection},
      {"1e10 triangle with 1e-10 hole, difference",
       {{{-1e10, -1e10}, {1e10, -1e10}, {0, 1e10}}, rect(-1e-10, -1e-10, 1e-10, 1e-10)},
       {scaled(star, 1e-10)},
       Op::Difference},
      // A unit square next to 1e150 coordinates, disjoint from them.
      {"unit square beside 1e150",
       {rect(1e150, 1e150, 2e150, 3e150)},
       {{{0, 0}, {1, 0.3}, {0.7, 1}}},
       Op::Union},
      // The crash case: a 2.6e120 triangle against a 1e-200 square.
      {"2.6e120 triangle, 1e-200 square",
       {{{-2.5822498780869086e+120, -1.2911249390434543e+120},
         {2.5822498780869086e+120, 1.2911249390434543e+120},
         {2.5822498780869086e+120, 2.5822498780869086e+120}}},
       {rect(-1e-200, -1e-200, 1e-200, 1e-200)},
       Op::Intersection},
  };
}

TEST(LocalTolerance, SmallFeaturesBesideHugeCoordinatesAreJudgedAtTheirOwnScale) {
  for (const MixedCase& c : mixedMagnitudeCases()) {
    const Region answer = clip(c.subject, c.clip, c.op);
    EXPECT_TRUE(oracle::exactCheck(c.subject, c.clip, c.op, answer).pass) << c.name;
    EXPECT_TRUE(oracle::sampleCheck(c.subject, c.clip, c.op, answer).pass()) << c.name;
    const Region candidates[] = {{}, c.subject, c.clip, answer.empty() ? Region{} : Region(answer.begin() + 1, answer.end())};
    for (const Region& wrong : candidates) {
      if (oracle::sameExactArea(wrong, answer) && oracle::exactCheck(c.subject, c.clip, c.op, wrong).errorAreaExact == "0") {
        continue;  // not wrong for this case
      }
      const auto v = oracle::exactCheck(c.subject, c.clip, c.op, wrong);
      EXPECT_FALSE(v.pass) << c.name << ": a wrong candidate of " << wrong.size() << " rings passes, error "
                           << v.errorArea;
      EXPECT_NE(v.beyondRoundingAreaExact, "0") << c.name;
      EXPECT_FALSE(oracle::sampleCheck(c.subject, c.clip, c.op, wrong).pass())
          << c.name << ": the sampling oracle passes a wrong candidate " << io::writeWkt(wrong);
    }
  }
}

// The mixed-magnitude workload (triangles to 2^480 holding holes down to 2^-300): the exact
// variant's answers pass both judges; the empty answer and either operand fail both.
TEST(LocalTolerance, MixedMagnitudeWorkloadAnswersPassAndWrongOnesFail) {
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    const auto w = work::generate("mixed-magnitude", 12, seed);
    for (Op op : {Op::Intersection, Op::Union, Op::Difference}) {
      const Region answer = clip(w.subject, w.clip, op);
      EXPECT_TRUE(oracle::exactCheck(w.subject, w.clip, op, answer).pass) << seed << " " << name(op);
      EXPECT_TRUE(oracle::sampleCheck(w.subject, w.clip, op, answer).pass()) << seed << " " << name(op);
      for (const Region* wrong : {&w.subject, &w.clip}) {
        if (oracle::exactCheck(w.subject, w.clip, op, *wrong).errorAreaExact == "0") continue;
        EXPECT_FALSE(oracle::exactCheck(w.subject, w.clip, op, *wrong).pass) << seed << " " << name(op);
        EXPECT_FALSE(oracle::sampleCheck(w.subject, w.clip, op, *wrong).pass()) << seed << " " << name(op);
      }
      EXPECT_FALSE(oracle::exactCheck(w.subject, w.clip, op, {}).pass) << seed << " " << name(op);
      EXPECT_FALSE(oracle::sampleCheck(w.subject, w.clip, op, {}).pass()) << seed << " " << name(op);
    }
  }
}

// Certified sums (the issue saw 5.2 and 5.199999999999999 for two answers of exactly 26/5): the
// square [0,2]^2 cut by the line 3x + 5y = 15 has area 4 - 1/30 = 119/30 exactly, with
// crossings (2, 9/5) and (5/3, 2) that are not doubles. The interval the oracle reports for it
// must contain 119/30 however the sum is associated, i.e. for every rotation of the rings.
TEST(LocalTolerance, AreaIntervalsContainTheExactArea) {
  const Region square{rect(0, 0, 2, 2)};
  Ring triangle{{0, 0}, {5, 0}, {0, 3}};
  const long double truth = 119.0L / 30;
  for (int turn = 0; turn < 3; ++turn) {
    std::rotate(triangle.begin(), triangle.begin() + 1, triangle.end());
    const Region answer = clip(square, {triangle}, Op::Intersection);
    const auto v = oracle::exactCheck(square, {triangle}, Op::Intersection, answer, {false, false, false});
    EXPECT_LT(v.areaUncertainty, 1e-12);
    const long double lo = static_cast<long double>(v.expectedArea) - v.areaUncertainty;
    const long double hi = static_cast<long double>(v.expectedArea) + v.areaUncertainty;
    EXPECT_LE(lo, truth) << turn;
    EXPECT_GE(hi, truth) << turn;
    EXPECT_TRUE(v.pass);
  }
}

// The deep-run failure (exact, swap_xy, grid): xor of two disjoint triangles, once as
// given and once with x and y swapped, is both rings unchanged, area exactly 26/5 both times;
// the uncertified sums said 5.1999999999999993 and 5.2000000000000002 with no room between.
TEST(LocalTolerance, SwappedDisjointXorHasOneCertifiedArea) {
  const Region s = io::readWkt("MULTIPOLYGON(((3 0,0 2,0 0,3 0)))");
  const Region c = io::readWkt("MULTIPOLYGON(((1 8,0 5,2 5,0 3,1 8)))");
  auto swapXY = [](Region r) {
    for (Ring& ring : r) {
      for (Point& p : ring) std::swap(p.x, p.y);
    }
    return r;
  };
  const Region plain = clip(s, c, Op::Xor), swapped = clip(swapXY(s), swapXY(c), Op::Xor);
  const auto a = oracle::exactCheck(plain, {}, Op::Union, {}, {false, false, false});
  const auto b = oracle::exactCheck(swapped, {}, Op::Union, {}, {false, false, false});
  EXPECT_LE(std::abs(a.expectedArea - b.expectedArea), a.areaUncertainty + b.areaUncertainty);
  EXPECT_LE(std::abs(a.expectedArea - 5.2), a.areaUncertainty + 1e-15);
  EXPECT_EQ(oracle::exactArea(plain).rational, "26/5");
  EXPECT_EQ(oracle::exactArea(swapped).rational, "26/5");
}

// fuzz_clip_naive (corpus input 07e8f293...): the naive variant's union is wrong near vertices that
// are rounded crossings of S and C (coordinates as fuzzed, in hex: a repeated closing vertex and
// the 2^-12 offsets must survive, which a WKT round trip would not). The judge prunes the radii
// around such a vertex only when an edge of S or C passing near it is within a quarter of its
// delta (OperandEdges::passesNear); counting every edge near a vertex as passing through it lets
// this answer pass.
TEST(SamplingOracle, PruningAtRoundedCrossingsKeepsAWrongUnionWrong) {
  const Region s{
      {{0x1.8p+2, 0x1.8p+2},{0x1.c000000002p+2, 0x1.8004p+2},{0x1.0008p+1, 0x1.0008p+1},{0x1.0008p+1, 0x1.0008p+1},
       {0x1.0008p+1, 0x1.0008p+1},{0x1.0008p+1, 0x1.0008p+1},{0x1.0008p+1, 0x1.0008p+1},{0x1.00008p+1, 0x1p+0},
       {0x1p+1, 0x0p+0},{0x1.0008p+1, 0x1.0008p+1},},
      {{0x1.0008p+1, 0x0p+0},{0x0p+0, 0x0p+0},{0x1p-12, 0x1.0008p+1},{0x1.0008p+1, 0x1.0008p+1},
       {0x1.0008p+1, 0x1.0008p+1},{0x1.0008p+1, 0x1.0008p+1},{0x1.0008p+1, 0x1.0008p+1},{0x1.0002p+3, 0x1p+1},
       {0x1.0000000000008p+3, 0x1p+0},{0x1.4p+2, -0x0.0000000000003p-1022},{0x1.8p+2, 0x1.c0000002p+2},{0x1.0000000000002p+2, 0x0p+0},
       {0x1p+1, 0x1p+0},{0x1.8000000000002p+2, 0x1.ffffffffffffdp+1},},};
  const Region c{
      {{0x1.4p+2, 0x1p-8},{0x1.cp+2, 0x1p+0},{0x1.8p+0, 0x0p+0},{0x0p+0, 0x1p-21},
       {0x1p+3, 0x1.9p+1},{0x1.8p+0, -0x0.0000000000002p-1022},{0x1.0000000000001p+2, 0x1.800002p+2},{0x1.0000000000001p+0, 0x1.4p+2},
       {0x1.0000000000004p+3, 0x1.8p+1},{0x0p+0, 0x1.000000000001p+2},{0x1p+0, 0x1.3fffffffffffep+2},{0x1p+2, 0x1.800000000008p+2},
       {0x1.8000000002p+2, 0x1.404p+2},{0x1.cp+2, 0x1p+0},{0x1.0000000000003p+3, 0x1.8p+0},{0x0p+0, 0x0p+0},},};
  const Region wrong{
      {{0x1.76526203513f5p+2, 0x1.4511f82f59f55p+2},{0x1.c000000002p+2, 0x1.8004p+2},{0x1.8p+2, 0x1.8p+2},{0x1.5571d09adebd8p+2, 0x1.5571d09adebd8p+2},
       {0x1p+2, 0x1.800000000008p+2},{0x1p+0, 0x1.3fffffffffffep+2},{0x0p+0, 0x1.000000000001p+2},{0x1.c71c71c71c72dp+1, 0x1.c71c71c71c72dp+1},
       {0x1.071c71c71c71dp+2, 0x1.071c71c71c71dp+2},{0x1.0000000000001p+0, 0x1.4p+2},{0x1.0000000000001p+2, 0x1.800002p+2},{0x1.4924910fac6b6p+1, 0x1.4924910fac6b6p+1},
       {0x1.0008p+1, 0x1.0008p+1},{0x1.0004cd02981d9p+1, 0x1.334a400c927a8p+0},{0x1.000200300fc1ap+1, 0x1.333ccf4d253cp+0},{0x1.0008p+1, 0x1.0008p+1},
       {0x1.4001655d19f44p+1, 0x1.33368e790f8e8p+1},{0x1.2aadd00edbbdbp+1, 0x1.00078e45d52dbp+1},{0x1.0008p+1, 0x1.0008p+1},{0x1p-12, 0x1.0008p+1},
       {0x1.fff6402f7718fp-35, 0x1.00031ff0bc4a5p-21},{0x0p+0, 0x1p-21},{0x1.fff0007fa6b04p-35, 0x1.ffffffffaaad7p-22},{0x0p+0, 0x0p+0},
       {0x1.8p+0, 0x0p+0},{0x1.0008p+1, 0x0p+0},{0x1.003b3e3f772f9p+1, 0x1.99f8639b0bp-10},{0x1.ff3384fe009b8p+1, 0x1.98f603fec98bdp-9},
       {0x1.0000000000002p+2, 0x0p+0},{0x1.000ea1c0198ep+2, 0x1.99b102cd58p-9},{0x1.4p+2, 0x1p-8},{0x1.4009d7dbb3f9cp+2, 0x1.139c07b08b84p-8},
       {0x1.4p+2, -0x0.0000000000003p-1022},{0x1.0000000000008p+3, 0x1p+0},{0x1.0002p+3, 0x1p+1},{0x1.b003c9b818f48p+2, 0x1.0001aaabcc2a2p+1},
       {0x1.8000000002p+2, 0x1.404p+2},},
      {{0x1.1ffdca24e0dbcp+2, 0x1.0000a1ac520a7p+2},{0x1.f2252a8c9e177p+1, 0x1.c1bb5aae6c3e3p+1},{0x1.3dcb08d398814p+2, 0x1.b08d3dcb19e09p+1},{0x1.4609a90e33954p+2, 0x1.ea439f659961bp+1},},
      {{0x1.000064002a101p+1, 0x1.9000a84040292p-1},{0x1.0000300009p+1, 0x1.800048000f63ap-2},{0x1.00017ff6403f6p+1, 0x1.80023ff16242bp-2},{0x1.00031ff0dc49bp+1, 0x1.9004ede84bb36p-1},},
      {{0x1.00001ec4fb19cp+1, 0x1.ec4fb19c77dap-3},{0x1.00000ba2ead7dp+1, 0x1.745d5af9bcc18p-4},{0x1.00005d14e48e8p+1, 0x1.745f34d6af741p-4},{0x1.0000f623640a8p+1, 0x1.ec562a4b5051p-3},},
      {{0x1.0000003333334p+1, 0x1.999999edd18p-10},{0x1p+1, 0x0p+0},{0x1.000001998ccfcp+1, 0x1.99999c2b2d979p-10},},
      {{0x1.47b2fce76b4a8p+2, 0x1.0003d70565d87p+1},{0x1.6a40af533dc51p+2, 0x1.00031ebc58eebp+1},{0x1p+3, 0x1.9p+1},{0x1.52e99ba37ab7ep+2, 0x1.08c682f1e4a87p+1},
       {0x1.5084e896f4091p+2, 0x1.ce897084c19b4p+0},{0x1.197a4b017fac6p+2, 0x1.64b01a1693108p+0},{0x1.20292abb9b13ap+2, 0x1.c24056447da3cp+0},},
      {{0x1.45f92c5f8bc5dp+2, 0x1.4e81b4e811916p-1},{0x1.48ceadcc4a375p+2, 0x1.ed3604b26fc61p-1},{0x1.0e7d95bc4f20fp+2, 0x1.95bc609a77498p-1},{0x1.08c462310e014p+2, 0x1.eaf57abd4159p-2},},
      {{0x1.5e50d79413db3p+2, 0x1.a86bca1afb09fp+1},{0x1.61e1e1e1bcadap+2, 0x1.da5a5a5a6f9dp+1},{0x1.658469ee5846ep+2, 0x1.d8469ee5846ap+1},{0x1.492492492492ep+2, 0x1.adb6db6db6dcp+1},
       {0x1.5555ed09beaf8p+2, 0x1.aaaa84bd9054ep+1},{0x1.6aaaed09b641cp+2, 0x1.d5552f682a23cp+1},{0x1.0000000000004p+3, 0x1.8p+1},},
      {{0x1.6ef654b01e07dp+2, 0x1.48bc50d249e94p+2},{0x1.8p+2, 0x1.c0000002p+2},{0x1.600c017fd01e6p+2, 0x1.502a0540d89a4p+2},},
      {{0x1.aaaaaaaaaa5acp+1, 0x1.555555555695cp-2},{0x1.745d1745d129ep+1, 0x1.1745d1745dac8p-1},{0x1.3b1c66f979d49p+1, 0x1.d8aa9a76387dp-2},{0x1.0e42651a51252p+1, 0x1.c753c0992708p-4},},
      {{0x1.6323232323233p+1, 0x1.39b9b9b9b9b9dp-1},{0x1.1f7044a10dc66p+1, 0x1.c11f76bde4736p-1},{0x1.a423310e812f8p+1, 0x1.483b830b0e8bp+0},{0x1.3b4ffe65f2f84p+1, 0x1.da475c4d08f6p-2},},};
  oracle::SampleOptions options;
  options.uniformPoints = 200;  // as the clip fuzz targets judge
  EXPECT_FALSE(oracle::sampleCheck(s, c, Op::Union, wrong, options).pass());
  EXPECT_TRUE(oracle::sampleCheck(s, c, Op::Union, clip(s, c, Op::Union), options).pass());
}

// The delta near an edge of S or C is that of its largest crossing, wherever along it a point
// lies: S's bottom edge (y = 0, to x = 1e6) crosses a small square of C near x = 0.5 and a large
// one at x = 9e5, so a sliver 1e-12 thick along it by the small square lies within its delta
// (about 1e-9) and is left out. Without the far square the edge's largest crossing is the small
// one (delta about 1e-15) and the same sliver is judged wrong. (A search for the largest crossing
// that stopped at the first one met judged the first answer wrong too.)
TEST(SamplingOracle, TheDeltaNearAnEdgeIsThatOfItsLargestCrossing) {
  const Region s{rect(-1, 0, 1e6, 1e6)};
  const Region small{rect(0.25, -0.25, 0.75, 0.25)};
  const Region both{rect(0.25, -0.25, 0.75, 0.25), rect(9e5, -0.5, 9e5 + 1, 0.5)};
  const Ring sliver = rect(0.3, -1e-12, 0.4, 0);  // below S's edge, inside C: not in S n C
  const Region rightBoth{rect(0.25, 0, 0.75, 0.25), rect(9e5, 0, 9e5 + 1, 0.5)};
  Region wrongBoth = rightBoth;
  wrongBoth.push_back(sliver);
  const Region rightSmall{rect(0.25, 0, 0.75, 0.25)};
  Region wrongSmall = rightSmall;
  wrongSmall.push_back(sliver);
  oracle::SampleOptions options;
  options.uniformPoints = 200;
  EXPECT_TRUE(oracle::sampleCheck(s, both, Op::Intersection, rightBoth, options).pass());
  EXPECT_TRUE(oracle::sampleCheck(s, both, Op::Intersection, wrongBoth, options).pass());
  EXPECT_TRUE(oracle::sampleCheck(s, small, Op::Intersection, rightSmall, options).pass());
  EXPECT_FALSE(oracle::sampleCheck(s, small, Op::Intersection, wrongSmall, options).pass());
}

// fuzz_diff_vatti (corpus input be9aa8b9...), the naive variant's reverse difference: slivers
// a few hundred ulps wide, one of them wrong at a point 2e-15 from its vertex (hex: the answer's
// constructed coordinates). Around a vertex a point is left out when the segment from a point
// judged farther out in its direction meets no edge near the vertex; at a few ulps from the
// vertex the vertex's own edges (rays) can lie between two such points, so they must be among
// the edges tested: a judge that tested only the nearest edges not through the vertex let this
// answer pass.
// Every operation's answer lies in S and C's box, which the uniform points cover once for all
// answers; an answer reaching beyond it is sampled beyond it too. Uniform points alone (no points
// near vertices) must find a wrong square far outside, where S and C are not.
TEST(SamplingOracle, UniformPointsReachAnAnswerBeyondTheOperandsBox) {
  const Region square{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  const Region far{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{10, 10}, {11, 10}, {11, 11}, {10, 11}}};
  oracle::SampleOptions options;
  options.nearVertices = false;
  options.uniformPoints = 2000;
  const oracle::SampleVerdict v = oracle::sampleCheck(square, square, Op::Intersection, far, options);
  EXPECT_FALSE(v.pass());
  ASSERT_TRUE(v.firstMismatch.has_value());
  EXPECT_GE(v.firstMismatch->x, 10);
  EXPECT_GE(v.firstMismatch->y, 10);
  oracle::SamplingJudge judge(square, square, options);
  EXPECT_EQ(judge.check(Op::Intersection, far).mismatched, v.mismatched);
  EXPECT_TRUE(judge.check(Op::Intersection, square).pass());
}

TEST(SamplingOracle, PointsLeftOutNearAVertexLieInOneFaceWithAJudgedOne) {
  const Region s = io::readWkt(
      "MULTIPOLYGON(((3 1,0 3,3 3,3 3,3 0,2 3,3 1)),((3 4,8 3,3 3,3 5,3 5,5 5,5 5,5 5,1 7,0 0,0 0,0 0,3 4)),"
      "((5 5,5 3,3 3,5 5)))");
  const Region c = io::readWkt(
      "MULTIPOLYGON(((3 3,5 5,3 3,3 3,0 1,3 3,3 3)),((3 3,1 1,1 1,1 1,4 1,1 1,3 3)),"
      "((1 1,3 3,3 3,3 3,3 3,3 3,3 3,3 3,1 3,3 3,3 3,1 1)))");
  const Region wrong{
      {{0x1.7fffffffffc5fp+0, 0x1.ffffffffffbe4p+0}, {0x1.7fffffffffd77p+0, 0x1.ffffffffffc9fp+0},
       {0x1.7fffffffffd76p+0, 0x1.ffffffffffc9dp+0}},
      {{0x1.8p+1, 0x1.7fffffffffe4fp+1}, {0x1.8000000000288p+1, 0x1.8p+1}, {0x1.8000000000e0bp+1, 0x1.80000000007acp+1},
       {0x1.8000000000289p+1, 0x1.8p+1}},
      {{0x1.8p+1, 0x1.7fffffffff9a1p+1}, {0x1.800000000066p+1, 0x1.8p+1}, {0x1.8000000000e0bp+1, 0x1.80000000007acp+1},
       {0x1.800000000065fp+1, 0x1.8p+1}},
      {{0x1.8p+1, 0x1.7fffffffff9a1p+1}, {0x1.800000000065fp+1, 0x1.8p+1}, {0x1.8000000000e0bp+1, 0x1.80000000007acp+1},
       {0x1.800000000066p+1, 0x1.8p+1}},
      {{0x1.1745d1745d1cap+1, 0x1.3a2e8ba2e8aa1p+1}, {0x1.1745d1745d1cap+1, 0x1.3a2e8ba2e8aa2p+1},
       {0x1.1fffffffffdecp+1, 0x1.3fffffffffd59p+1}},
  };
  oracle::SampleOptions options;
  options.uniformPoints = 200;  // as the clip fuzz targets judge
  const oracle::SampleVerdict v = oracle::sampleCheck(s, c, Op::ReverseDifference, wrong, options);
  EXPECT_FALSE(v.pass());
  ASSERT_TRUE(v.firstMismatch.has_value());
  EXPECT_LT(std::hypot(v.firstMismatch->x - 0x1.7fffffffffc5fp+0, v.firstMismatch->y - 0x1.ffffffffffbe4p+0), 1e-14);
  EXPECT_TRUE(oracle::sampleCheck(s, c, Op::ReverseDifference, clip(s, c, Op::ReverseDifference), options).pass());
}

// Two triangles sharing a vertex (a fuzz input): the paper arithmetic's answers for three
// operations (of five) are wrong beyond rounding (the exact oracle), and the only points that
// show it lie in a sector around a vertex that none of the eight directions or the bisector falls
// in. Judged with every sector's middle point, those three fail; the exact variant's answers pass.
TEST(SamplingOracle, EverySectorAroundAVertexIsJudged) {
  const Region s = io::readWkt("POLYGON((0 3,3 6,1 0,0 3))");
  const Region c = io::readWkt("POLYGON((0 3,6 1,7 3,0 3))");
  oracle::SampleOptions options;
  options.uniformPoints = 200;  // as the clip fuzz targets judge
  for (Variant variant : {Variant::Naive, Variant::Exact}) {
    std::vector<std::pair<Op, Region>> answers;
    for (Op op : kAllOps) answers.emplace_back(op, clip(s, c, op, optionsOf(variant)));
    std::vector<std::pair<Op, const Region*>> all;
    for (const auto& [op, r] : answers) all.emplace_back(op, &r);
    const auto verdicts = oracle::SamplingJudge(s, c, options).check(all);
    for (std::size_t i = 0; i < answers.size(); ++i) {
      const Op op = answers[i].first;
      const bool exact = oracle::exactCheck(s, c, op, answers[i].second).pass;
      if (variant == Variant::Exact) {
        EXPECT_TRUE(exact) << name(op);
        EXPECT_TRUE(verdicts[i].pass()) << name(op);
      } else if (op == Op::ReverseDifference || op == Op::Union || op == Op::Xor) {
        EXPECT_FALSE(exact) << name(op);
        EXPECT_FALSE(verdicts[i].pass()) << name(op);
      }
    }
  }
}

// The answers' sides come from one ray per point for all of them, each distinct segment once
// with the answers it bounds. An edge an answer holds twice (two rings along one segment, or one
// ring there and back) changes nothing for that answer, and a point on it is on that answer's
// boundary, whatever the other answers that share the segment hold. Judged together and alone,
// right answers pass and the wrong ones fail.
TEST(SamplingOracle, AnswersSharingAndDoublingEdgesAreJudgedEachByItsOwnRings) {
  const Region s = io::readWkt("POLYGON((0 0,1 0,1 1,0 1,0 0))");
  const Region c = io::readWkt("POLYGON((1 0,3 0,3 1,1 1,1 0))");
  // The union as the two rings, their shared edge held twice (once each way): right. (Off the
  // middle of the x-range, so that rays from points on either side of it cross it.)
  const Region twoSquares = io::readWkt("MULTIPOLYGON(((0 0,1 0,1 1,0 1,0 0)),((1 0,3 0,3 1,1 1,1 0)))");
  // The intersection (the operands only touch) as a ring there and back along the shared edge,
  // and as nothing: both right.
  const Region seam = io::readWkt("POLYGON((1 0,1 1,1 0))");
  const Region square = io::readWkt("POLYGON((0 0,1 0,1 1,0 1,0 0))");
  const Region nothing;
  // The union missing the right square, with the shared edge twice in one ring: wrong.
  const Region leftOnly = io::readWkt("POLYGON((0 0,1 0,1 1,1 0,1 1,0 1,0 0))");
  oracle::SampleOptions options;
  options.uniformPoints = 200;
  const std::vector<std::pair<Op, const Region*>> all = {
      {Op::Union, &twoSquares}, {Op::Intersection, &seam},     {Op::Intersection, &nothing},
      {Op::Difference, &square}, {Op::ReverseDifference, &c}, {Op::Xor, &twoSquares},
      {Op::Union, &leftOnly},   {Op::Difference, &twoSquares}};
  const std::vector<bool> right = {true, true, true, true, true, true, false, false};
  oracle::SamplingJudge judge(s, c, options);
  const auto together = judge.check(all);
  for (std::size_t i = 0; i < all.size(); ++i) {
    EXPECT_EQ(together[i].pass(), right[i]) << i;
    EXPECT_EQ(oracle::sampleCheck(s, c, all[i].first, *all[i].second, options).pass(), right[i]) << i;
    EXPECT_EQ(oracle::exactCheck(s, c, all[i].first, *all[i].second).pass, right[i]) << i;
  }
}

// A fuzz input: (6 6) is the tip of a spike of S with edges 6 long, and a vertex of the paper
// arithmetic's union with edges 1 to 1.7 long. That union is wrong beyond rounding (the exact
// oracle), and the sampling oracle sees it on the spike's bisector 1.5 below the tip (a quarter
// of S's edge). The vertex is sampled once for all rings through it, each corner at the radii it
// would get alone; judged at the shortest corner's radii only, the union passed.
TEST(SamplingOracle, EachCornerThroughAVertexIsJudgedAtItsOwnScale) {
  const Region s = io::readWkt(
      "MULTIPOLYGON(((2.999999999999999 4,6 0,6 6,6 6,6 6,5.999999999999997 0,"
      "7.999999999999999 2.000000000029104,3.814697265625e-06 4,4.000000059604645 2.0009765625,"
      "1 0,3.9999999999999996 3.0000000000000036,7.999999999999999 2.0000076293945312,"
      "3.0000000000000004 5,2.999999999999999 4)),((0.9999999999999998 4,6.000000000000003 1,"
      "5.000000000931323 1,2.0000076293945312 3.0000000000000004,5 3.999999999999999,"
      "4 5.999999999999999,0.9999999999999998 4)))");
  const Region c = io::readWkt(
      "MULTIPOLYGON(((8.000000476837158 1.0000000000000007,5.000000000000002 5.999999999999999,"
      "1.0000000000000007 2.000000000000057,7.5 0,0 0,0 0,0 0,0 0,"
      "8.000000476837158 1.0000000000000007)))");
  const Region wrong = io::readWkt(
      "MULTIPOLYGON(((5.485714313742336 0.6857142483460379,5.55000000000247 0.5999999999992571,"
      "3.051946077994981 1.3686319760015833,1.2306306193529215 0.15382881825020345,"
      "5.485714313742336 0.6857142483460379)),((6.0000000000014735 0.46153846153802147,"
      "6.000000000001396 0.7499999552966942,6.000000000001394 0.749999955296694,"
      "6.000000000001471 0.4615384615380229,6.0000000000014735 0.46153846153802147)),"
      "((6.000000000000443 4.333333598242086,6 6,6.000000000000442 4.333333598242088,"
      "5.000000000000002 5.999999999999999,4.33333333333333 5.3333333333333375,"
      "4 5.999999999999999,0.9999999999999998 4,2.2499999999999765 3.250000000000014,"
      "2.4000005340647776 3.400000534064813,3.814697265625e-06 4,"
      "2.0003262192291507 3.000326219229192,1.0000000000000007 2.000000000000057,"
      "2.529411764706185 1.529411764705832,1.1428571331265611 0.14285713312587153,0 0,7.5 0,"
      "6.352941176467123 0.35294117647166473,6.857142798740854 0.8571427987529152,"
      "8.000000476837158 1.0000000000000007,7.625000260761489 1.6250002607850007,"
      "7.999999999999999 2.000000000029104,7.294118016630144 2.17647058001673,"
      "7.294113640971289 2.176477872780328,7.999999999999999 2.0000076293945312,"
      "7.062494700780736 2.562509378406529,6.000000000000443 4.333333598242086)),"
      "((3.6250005960470055 4.625000596047023,3.0000000000000004 5,"
      "2.999999999999999 4.000000000000026,3.6250005960470055 4.625000596047023)))");
  EXPECT_FALSE(oracle::exactCheck(s, c, Op::Union, wrong).pass);
  oracle::SampleOptions options;
  options.uniformPoints = 200;  // as the clip fuzz targets judge
  EXPECT_FALSE(oracle::SamplingJudge(s, c, options).check(Op::Union, wrong).pass());
  EXPECT_TRUE(oracle::SamplingJudge(s, c, options).check(Op::Union, clip(s, c, Op::Union)).pass());
}

// A vertex nearer another edge than its smallest radius (a fuzz input's clip: a ring of denormal
// coordinates at the origin, with an edge along the x axis): all its corners' radii are sampled,
// and beyond the disk where only the edges near it cut, the eight directions only at each
// corner's smallest radius there; at the larger ones, each corner's bisector both ways. The
// paper arithmetic's intersection, difference and xor are wrong beyond rounding, by slivers
// 1e-12 high along the x axis that a bisector meets 0.25 from the vertex. Without the bisectors
// beyond that smallest radius, the five answers judged together all passed.
TEST(SamplingOracle, EveryRadiusOfACornerKeepsItsBisector) {
  const Region s{
      {{7, 6}, {8, 0}, {-9.8813129168249309e-324, 1.8189894035458565e-12}, {3, 7.000030517578125}, {1, 5},
       {5.0000000000000027, 0.0001220703125}, {4.9999999999999982, 8}, {8, 7}, {5.0000000000000009, 4}},
      {{8, 4}, {8, 0}, {0, 0}, {2.9999999999999991, 4.0000001192092896}, {3.0000000000000009, 8.0000000000000036},
       {2.00048828125, 2}, {1, 0}, {1.0001220703125, 1.0000000000000002}, {2.03125, 1}, {2, 5}, {1, 5},
       {4.0001220703125, 1}, {6, 0}, {1, 0}, {6.000000000007276, 5.9999999999999991}, {0, 0}},
      {{1.4901161193847656e-08, 3.5}, {0, 0}, {0, 1.4821969375237396e-323}}};
  const Region c{{{0, 1.4821969375237396e-323}, {-4.9406564584124654e-324, 0}, {0, 0}, {0, 0}, {0, 0},
                  {4.9406564584124654e-324, 0}, {0, -1.4821969375237396e-323}, {0, 0}, {6, 0}, {0, 0}, {0, 0}, {0, 0}}};
  std::vector<std::pair<Op, Region>> answers;
  for (Op op : kAllOps) answers.emplace_back(op, clip(s, c, op, optionsOf(Variant::Naive)));
  std::vector<std::pair<Op, const Region*>> all;
  for (const auto& [op, r] : answers) all.emplace_back(op, &r);
  oracle::SampleOptions options;
  options.uniformPoints = 200;  // as the clip fuzz targets judge
  const auto verdicts = oracle::SamplingJudge(s, c, options).check(all);
  for (std::size_t i = 0; i < answers.size(); ++i) {
    const Op op = answers[i].first;
    if (op != Op::Intersection && op != Op::Difference && op != Op::Xor) continue;
    EXPECT_FALSE(oracle::exactCheck(s, c, op, answers[i].second).pass) << name(op);
    EXPECT_FALSE(verdicts[i].pass()) << name(op);
  }
}

// What the uniform points are for: a wrong face that no vertex of S, C or the answer bounds. S is
// two horizontal bars, C two vertical ones; their intersection is four squares whose corners are
// all crossings, and an answer that leaves one square out has no vertex near it (the nearest lie
// 2 away, past every radius sampled around them). Points near vertices alone pass that answer; the
// uniform points, as many as the clip fuzz targets draw, find it (the square is 9 % of the box).
TEST(SamplingOracle, UniformPointsFindAWrongFaceNoVertexBounds) {
  const Region s = io::readWkt("MULTIPOLYGON(((0 1,10 1,10 4,0 4,0 1)),((0 6,10 6,10 9,0 9,0 6)))");
  const Region c = io::readWkt("MULTIPOLYGON(((1 0,4 0,4 10,1 10,1 0)),((6 0,9 0,9 10,6 10,6 0)))");
  ASSERT_DOUBLE_EQ(evenOddArea(clip(s, c, Op::Intersection)), 36);
  const Region threeSquares = io::readWkt(
      "MULTIPOLYGON(((1 1,4 1,4 4,1 4,1 1)),((6 1,9 1,9 4,6 4,6 1)),((1 6,4 6,4 9,1 9,1 6)))");
  oracle::SampleOptions nearOnly;
  nearOnly.uniformPoints = 0;
  EXPECT_TRUE(oracle::sampleCheck(s, c, Op::Intersection, threeSquares, nearOnly).pass());
  oracle::SampleOptions targets;
  targets.uniformPoints = 200;  // as the clip fuzz targets judge (fuzz/clip_target.h)
  const oracle::SampleVerdict v = oracle::sampleCheck(s, c, Op::Intersection, threeSquares, targets);
  EXPECT_FALSE(v.pass());
  ASSERT_TRUE(v.firstMismatch.has_value());
  EXPECT_GT(v.firstMismatch->x, 6);
  EXPECT_GT(v.firstMismatch->y, 6);
  EXPECT_TRUE(oracle::sampleCheck(s, c, Op::Intersection, clip(s, c, Op::Intersection), targets).pass());
}

// The fuzz targets' judge stops once every answer has a mismatch (stopWhenAllFail): the answers'
// verdicts and first mismatches stay the full check's, one found only near a vertex (the notched
// union below) beside one found among the first uniform points included; and it does stop.
TEST(SamplingOracle, StoppingWhenEveryAnswerFailedKeepsEveryVerdict) {
  const Region s = io::readWkt("POLYGON((0 0,6 0,6 6,0 6,0 0))");
  const Region c = io::readWkt("POLYGON((3 1,9 1,9 7,3 7,3 1))");
  const Region right = clip(s, c, Op::Union);
  // The union with a notch 1e-3 deep at (6 6): judged wrong near that vertex, nowhere else.
  const Region notched = io::readWkt("POLYGON((0 0,6 0,6 1,9 1,9 7,3 7,3 6,5.999 6,6 5.999,6 6,3 6,0 6,0 0))");
  oracle::SampleOptions full;
  full.uniformPoints = 200;
  oracle::SampleOptions stopping = full;
  stopping.stopWhenAllFail = true;
  const std::vector<std::pair<Op, const Region*>> answers = {
      {Op::Union, &notched}, {Op::Difference, &c}, {Op::Union, &right}, {Op::Intersection, &s}};
  const auto a = oracle::SamplingJudge(s, c, full).check(answers);
  const auto b = oracle::SamplingJudge(s, c, stopping).check(answers);
  const std::vector<bool> pass = {false, false, true, false};
  for (std::size_t i = 0; i < answers.size(); ++i) {
    EXPECT_EQ(a[i].pass(), pass[i]) << i;
    EXPECT_EQ(b[i].pass(), pass[i]) << i;
    EXPECT_EQ(a[i].firstMismatch.has_value(), b[i].firstMismatch.has_value()) << i;
    if (a[i].firstMismatch && b[i].firstMismatch) {
      EXPECT_EQ(a[i].firstMismatch->x, b[i].firstMismatch->x) << i;
      EXPECT_EQ(a[i].firstMismatch->y, b[i].firstMismatch->y) << i;
    }
  }
  // The notched union is found wrong only near its vertices: not among the uniform points.
  oracle::SampleOptions uniformOnly = full;
  uniformOnly.nearVertices = false;
  EXPECT_TRUE(oracle::SamplingJudge(s, c, uniformOnly).check(Op::Union, notched).pass());
  // Every answer wrong: it stops, at fewer points than the full check judges.
  const std::vector<std::pair<Op, const Region*>> wrong = {{Op::Union, &notched}, {Op::Difference, &c}};
  const auto fullWrong = oracle::SamplingJudge(s, c, full).check(wrong);
  const auto stoppedWrong = oracle::SamplingJudge(s, c, stopping).check(wrong);
  for (std::size_t i = 0; i < wrong.size(); ++i) {
    EXPECT_FALSE(fullWrong[i].pass()) << i;
    EXPECT_FALSE(stoppedWrong[i].pass()) << i;
    EXPECT_LT(stoppedWrong[i].checked, fullWrong[i].checked) << i;
  }
}

}  // namespace
}  // namespace gh

namespace gh {
namespace {

// What the tools print of an area is the exact rational rounded once: the expected area of a
// polygon xor its copy moved by one ulp (all slivers, whose certified intervals are far wider
// than themselves) equals the exact error area of the empty answer, to the last bit.
TEST(ExactAreas, ExpectedAreaOfSliversIsTheExactRationalRounded) {
  Ring ring;
  for (int i = 0; i < 400; ++i) {
    const double a = 2 * M_PI * i / 400;
    ring.push_back({100 + 30 * std::cos(a) + 0.7 * std::sin(7 * a), 40 + 20 * std::sin(a)});
  }
  Ring moved = ring;
  for (Point& p : moved) p.x = std::nextafter(p.x, INFINITY);
  oracle::ExactOptions options;
  options.exactAreas = true;
  const auto v = oracle::exactCheck({ring}, {moved}, Op::Xor, {}, options);
  EXPECT_FALSE(v.pass);
  EXPECT_GT(v.expectedArea, 0);
  EXPECT_EQ(v.expectedArea, v.errorArea);
  EXPECT_EQ(v.resultArea, 0);
}

}  // namespace
}  // namespace gh

namespace gh {
namespace {

// `constructionUlps` k widens each crossing's rounding by k - 1 doubles on each side, counted as
// doubles (across binades and zero), not as k - 1 steps: a crossing moved by 1000 of its ulps
// passes at k = 1001 and fails at k = 999; k = 2^20 is as quick as k = 1 (no timing here: the
// judge counts by arithmetic on the representation).
TEST(ExactAreas, ConstructionUlpsCountDoubles) {
  const Region s{{{0, 0}, {3, 0}, {3, 3}, {0, 3}}};
  const Region c{{{1.5, -1.1}, {4.1, 1.7}, {1.5, 4.3}, {-1.1, 1.3}}};
  Region r = clip(s, c, Op::Intersection);
  bool moved = false;
  for (Ring& ring : r) {
    for (Point& p : ring) {
      if (!moved && p.x == 3 && p.y != 0 && p.y != 3) {  // a crossing on x = 3: move it off that line
        for (int i = 0; i < 1000; ++i) p.x = std::nextafter(p.x, INFINITY);
        moved = true;
      }
    }
  }
  ASSERT_TRUE(moved);
  for (const auto& [ulps, pass] : {std::pair{999, false}, std::pair{1001, true}, std::pair{1 << 20, true}}) {
    oracle::ExactOptions options;
    options.constructionUlps = ulps;
    EXPECT_EQ(oracle::exactCheck(s, c, Op::Intersection, r, options).pass, pass) << ulps;
  }
}

}  // namespace
}  // namespace gh
