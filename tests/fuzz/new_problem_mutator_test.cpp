// The fuzz targets' custom mutator: a mutation is retried, from the parent's bytes, while the
// input decodes to a problem judged before (its parent's or another's); the engine always gets a
// mutation back.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "fuzz_input.h"
#include "new_problem_mutator.h"

namespace gh::fuzz {
namespace {

// A problem read from byte 1 onwards (byte 0 is never read), as the targets read theirs.
ProblemKey fromByteOne(const std::uint8_t* data, std::size_t size) {
  ProblemKey key;
  for (std::size_t i = 1; i < size; ++i) key.add(data[i]);
  return key;
}

TEST(NewProblemMutator, RetriesFromTheParentUntilTheProblemChanges) {
  std::vector<std::uint8_t> data{10, 20, 30, 0, 0};
  int calls = 0;
  auto mutate = [&](std::uint8_t* d, std::size_t size, std::size_t maxSize) -> std::size_t {
    EXPECT_EQ(size, 3u);
    EXPECT_EQ(maxSize, 5u);
    // Every attempt starts from the parent's bytes.
    EXPECT_EQ(d[0], 10);
    EXPECT_EQ(d[1], 20);
    EXPECT_EQ(d[2], 30);
    ++calls;
    if (calls < 3) {
      d[0] = static_cast<std::uint8_t>(d[0] + 1);  // unread: the same problem
      return size;
    }
    d[2] = 31;
    d[3] = 7;
    return 4;  // grew by a byte
  };
  JudgedProblems judged;
  const std::size_t size = mutateToNewProblem(data.data(), 3, 5, fromByteOne, mutate, judged);
  EXPECT_EQ(calls, 3);
  EXPECT_EQ(size, 4u);
  EXPECT_EQ(data[0], 10);  // the unread changes of the first two attempts were undone
  EXPECT_EQ(data[2], 31);
  EXPECT_EQ(data[3], 7);
}

TEST(NewProblemMutator, KeepsTheLastMutationWhenNoneChangesTheProblem) {
  std::vector<std::uint8_t> data{1, 2, 3};
  int calls = 0;
  auto mutate = [&](std::uint8_t* d, std::size_t size, std::size_t) {
    ++calls;
    d[0] = static_cast<std::uint8_t>(100 + calls);
    return size;
  };
  JudgedProblems judged;
  const std::size_t size = mutateToNewProblem(data.data(), 3, 3, fromByteOne, mutate, judged, 5);
  EXPECT_EQ(calls, 5);
  EXPECT_EQ(size, 3u);
  EXPECT_EQ(data[0], 105);  // the engine gets a mutation, not its parent back
}

TEST(NewProblemMutator, AShorterInputThatReadsTheSameIsTheSameProblem) {
  std::vector<std::uint8_t> data{1, 2, 3};
  int calls = 0;
  auto mutate = [&](std::uint8_t*, std::size_t size, std::size_t) -> std::size_t {
    return ++calls < 2 ? size : size - 1;  // erasing the last byte drops a read value
  };
  JudgedProblems judged;
  EXPECT_EQ(mutateToNewProblem(data.data(), 3, 3, fromByteOne, mutate, judged), 2u);
  EXPECT_EQ(calls, 2);
}

TEST(NewProblemMutator, RetriesAProblemJudgedForAnotherParentAndRemembersWhatItReturns) {
  const std::uint8_t other[] = {0, 9, 9};
  JudgedProblems judged;
  EXPECT_TRUE(judged.add(fromByteOne(other, 3)));
  std::vector<std::uint8_t> data{1, 2, 3};
  int calls = 0;
  auto mutate = [&](std::uint8_t* d, std::size_t size, std::size_t) {
    d[1] = 9, d[2] = static_cast<std::uint8_t>(++calls < 2 ? 9 : 8);  // {9, 9} was judged; {9, 8} not
    return size;
  };
  EXPECT_EQ(mutateToNewProblem(data.data(), 3, 3, fromByteOne, mutate, judged), 3u);
  EXPECT_EQ(calls, 2);
  EXPECT_FALSE(judged.add(fromByteOne(data.data(), 3)));  // the mutation returned counts as judged
  const std::uint8_t parent[] = {1, 2, 3};
  EXPECT_FALSE(judged.add(fromByteOne(parent, 3)));  // and its parent
}

TEST(JudgedProblems, ForgetsEverythingPastItsLimit) {
  JudgedProblems judged;
  const ProblemKey first = ProblemKey().add(std::int64_t{-1});
  EXPECT_TRUE(judged.add(first));
  EXPECT_FALSE(judged.add(first));
  const auto limit = static_cast<std::int64_t>(JudgedProblems::kLimit);
  for (std::int64_t i = 1; i + 1 < limit; ++i) ASSERT_TRUE(judged.add(ProblemKey().add(i)));
  EXPECT_FALSE(judged.add(first));  // one short of the limit: all remembered
  EXPECT_TRUE(judged.add(ProblemKey().add(limit - 1)));  // the limit reached
  EXPECT_TRUE(judged.add(first));  // past it: all forgotten, this one added
  EXPECT_TRUE(judged.add(ProblemKey().add(std::int64_t{1})));
  EXPECT_FALSE(judged.add(first));
}

TEST(ProblemKey, TellsProblemsApartByTheirBits) {
  const Region square{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  const Region negativeZero{{{-0.0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  const Region twoRings{{{0, 0}, {1, 0}}, {{1, 1}, {0, 1}}};
  EXPECT_TRUE(ProblemKey().add(square) == ProblemKey().add(square));
  EXPECT_FALSE(ProblemKey().add(square) == ProblemKey().add(negativeZero));
  EXPECT_FALSE(ProblemKey().add(square) == ProblemKey().add(twoRings));  // same points, other rings
  const Region splitLater{{{0, 0}, {1, 0}, {1, 1}}, {{0, 1}, {2, 2}}};
  const Region splitEarlier{{{0, 0}, {1, 0}}, {{1, 1}, {0, 1}, {2, 2}}};
  EXPECT_FALSE(ProblemKey().add(splitLater) == ProblemKey().add(splitEarlier));  // same ring count too
  EXPECT_FALSE(ProblemKey().add(square).add(Region{}) == ProblemKey().add(Region{}).add(square));
  const double nan = std::nan("");
  const Region withNan{{{nan, 0}, {1, 0}, {1, 1}}};
  EXPECT_TRUE(ProblemKey().add(withNan) == ProblemKey().add(withNan));
}

// What the mutator is for: the clip targets' decoder leaves bytes unread, so a change there
// (the kind of mutation the retry throws away) judges the parent's problem again.
TEST(ProblemKey, ABytePastWhatTheDecoderReadsDoesNotChangeTheProblem) {
  std::vector<std::uint8_t> data(256);
  for (std::size_t i = 0; i < data.size(); ++i) data[i] = static_cast<std::uint8_t>(i * 37 + 11);
  data.back() = 0;  // mode 0; FuzzedDataProvider reads integers from the end
  const ProblemKey parent = keyOf(pair(data.data(), data.size(), 3, 16));
  std::vector<std::uint8_t> unread = data, read = data;
  unread[0] ^= 0xFF;  // the first byte: past what 2 regions of at most 48 points read
  read[data.size() - 3] ^= 0x01;
  EXPECT_TRUE(keyOf(pair(unread.data(), unread.size(), 3, 16)) == parent);
  EXPECT_FALSE(keyOf(pair(read.data(), read.size(), 3, 16)) == parent);
}

// The mutator's keys decode into storage kept from call to call: a problem with fewer rings, or
// shorter ones, than the last decoded must not keep any of its rings or points.
TEST(ProblemKey, DecodedIntoKeptStorageItIsTheFreshDecodesKey) {
  std::vector<std::vector<std::uint8_t>> inputs;
  for (int k = 0; k < 40; ++k) {
    std::vector<std::uint8_t> data(static_cast<std::size_t>(8 + 23 * k % 300));
    for (std::size_t i = 0; i < data.size(); ++i) data[i] = static_cast<std::uint8_t>(i * 37 + 11 * k + 5);
    inputs.push_back(data);
  }
  std::size_t distinctRingCounts = 0;
  std::vector<std::size_t> seen;
  for (int pass = 0; pass < 2; ++pass) {
    for (const auto& data : inputs) {
      const Pair fresh = pair(data.data(), data.size(), 3, 16);
      EXPECT_TRUE(problemKey(data.data(), data.size(), 3, 16) == keyOf(fresh)) << data.size();
      const std::size_t rings = fresh.subject.size() * 4 + fresh.clip.size();
      if (std::find(seen.begin(), seen.end(), rings) == seen.end()) seen.push_back(rings), ++distinctRingCounts;
    }
  }
  EXPECT_GE(distinctRingCounts, 4u);  // the inputs decode to problems of several shapes
}

}  // namespace
}  // namespace gh::fuzz
