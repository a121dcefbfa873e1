// The sampling oracle's pooled vectors: storage reused from one judge to the next, contents never.
#include <gtest/gtest.h>

#include <utility>

#include "pooled_vector.h"

namespace gh::oracle {
namespace {

// A type of its own, so that no other test's vectors are in the pool.
struct Item {
  int value = 0;
};

TEST(PooledVector, StorageIsReusedButStartsEmpty) {
  const Item* storage = nullptr;
  {
    PooledVector<Item> first(1000, Item{7});
    storage = first.data();
  }
  PooledVector<Item> second;
  EXPECT_TRUE(second.empty());        // none of the last one's items
  EXPECT_GE(second.capacity(), 1000u);  // but its storage
  EXPECT_EQ(second.data(), storage);
  second.push_back(Item{1});
  EXPECT_EQ(second.size(), 1u);
  EXPECT_EQ(second[0].value, 1);
}

TEST(PooledVector, CopiesAreDeepAndMovesLeaveNothingBehind) {
  PooledVector<Item> a(3, Item{2});
  PooledVector<Item> b(a);
  b[0].value = 9;
  EXPECT_EQ(a[0].value, 2);
  EXPECT_EQ(b.size(), 3u);
  PooledVector<Item> c(std::move(b));
  EXPECT_EQ(c.size(), 3u);
  EXPECT_EQ(c[0].value, 9);
  a = c;
  EXPECT_EQ(a[0].value, 9);
  PooledVector<Item> d;
  d = std::move(a);
  EXPECT_EQ(d.size(), 3u);
  // Two alive at once never share storage.
  PooledVector<Item> e(5), f(5);
  EXPECT_NE(e.data(), f.data());
}

}  // namespace
}  // namespace gh::oracle
