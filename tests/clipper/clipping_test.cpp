// Clipping (clipping.h): phases 1 and 2 once, phase 3 per operation. Asked every operation in
// several orders, and some twice, one Clipping gives what a fresh clip() gives for each, bit for
// bit, with the same counts: tracing and clean-up leave nothing behind for the next operation.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "common/hand_cases.h"
#include "ghclip/clip.h"
#include "ghclip/clipping.h"
#include "ghclip/errors.h"
#include "ghwork/generators.h"

namespace gh {
namespace {

bool sameBits(const Region& a, const Region& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t r = 0; r < a.size(); ++r) {
    if (a[r].size() != b[r].size()) return false;
    if (!a[r].empty() && std::memcmp(a[r].data(), b[r].data(), a[r].size() * sizeof(Point)) != 0) return false;
  }
  return true;
}

// Every operation, forwards, backwards and forwards again, from one Clipping.
const std::vector<Op>& askedOrder() {
  static const std::vector<Op> order = [] {
    std::vector<Op> o(std::begin(kAllOps), std::end(kAllOps));
    o.insert(o.end(), std::rbegin(kAllOps), std::rend(kAllOps));
    o.insert(o.end(), std::begin(kAllOps), std::end(kAllOps));
    return o;
  }();
  return order;
}

void expectSameAsFreshClips(const Region& s, const Region& c, const Options& options, const std::string& what) {
  std::vector<Region> fresh;
  std::vector<Stats> freshStats;
  for (Op op : kAllOps) {
    Stats st;
    fresh.push_back(clip(s, c, op, options, &st));
    freshStats.push_back(st);
  }
  Clipping pair(s, c, options);
  for (Op op : askedOrder()) {
    const auto i = static_cast<std::size_t>(op);
    Stats st;
    const Region r = pair.result(op, &st);
    EXPECT_TRUE(sameBits(r, fresh[i])) << what << ", " << name(op);
    const Stats& f = freshStats[i];
    EXPECT_EQ(st.intersections, f.intersections) << what << ", " << name(op);
    EXPECT_EQ(st.candidatePairs, f.candidatePairs) << what << ", " << name(op);
    EXPECT_EQ(st.perturbations, f.perturbations) << what << ", " << name(op);
    EXPECT_EQ(st.filterFailures, f.filterFailures) << what << ", " << name(op);
    EXPECT_EQ(st.expansionDecisions, f.expansionDecisions) << what << ", " << name(op);
    EXPECT_EQ(st.exactConstructions, f.exactConstructions) << what << ", " << name(op);
    EXPECT_EQ(st.outputVertices, f.outputVertices) << what << ", " << name(op);
  }
}

TEST(Clipping, EveryOperationOfOnePairMatchesAFreshClipOnTheHandCases) {
  for (const test::HandCase& h : test::handCases()) {
    for (Variant v : kAllVariants) {
      expectSameAsFreshClips(h.subject, h.clip, optionsOf(v), h.name + " (" + std::string(name(v)) + ")");
    }
  }
}

TEST(Clipping, EveryOperationOfOnePairMatchesAFreshClipOnTheWorkloads) {
  for (const std::string& w : work::workloadNames()) {
    for (std::uint64_t seed : {1, 2}) {
      const work::Workload load = work::generate(w, 40, seed);
      for (Variant v : kAllVariants) {
        Options o = optionsOf(v);
        if (v == Variant::Naive || v == Variant::Sweep) {
          try {  // the paper arithmetic may give up on some workloads: then both must
            (void)clip(load.subject, load.clip, Op::Intersection, o);
          } catch (const ClipFailure&) {
            EXPECT_THROW(Clipping(load.subject, load.clip, o).result(Op::Intersection), ClipFailure) << w;
            continue;
          }
        }
        expectSameAsFreshClips(load.subject, load.clip, o, w + " seed " + std::to_string(seed) + " (" + std::string(name(v)) + ")");
      }
    }
  }
}

TEST(Clipping, OnAllThreadsMatchesOneThread) {
  const work::Workload load = work::generate("random", 300, 7);
  Options one, all;
  one.threads = 1, all.threads = 0;
  Clipping a(load.subject, load.clip, one), b(load.subject, load.clip, all);
  for (Op op : askedOrder()) EXPECT_TRUE(sameBits(a.result(op), b.result(op))) << name(op);
}

TEST(Clipping, RefusesBadInputNamingTheOperand) {
  const Region good{{{0, 0}, {1, 0}, {0, 1}}};
  const Region bad{{{0, 0}, {std::nan(""), 0}, {0, 1}}};
  try {
    Clipping pair(good, bad);
    FAIL() << "accepted a NaN coordinate";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("clip"), std::string::npos) << e.what();
  }
}

TEST(Clipping, AMovedClippingGivesTheSameAnswers) {
  const test::HandCase& h = test::handCases().front();
  Clipping first(h.subject, h.clip);
  const Region before = first.result(Op::Xor);
  Clipping moved(std::move(first));
  EXPECT_TRUE(sameBits(moved.result(Op::Xor), before));
  EXPECT_TRUE(sameBits(moved.result(Op::Union), clip(h.subject, h.clip, Op::Union)));
}

}  // namespace
}  // namespace gh
