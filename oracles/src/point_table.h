// A map from finite points (by exact coordinates, 0 and -0 one key) to small values, open-addressed
// in one array of 24-byte slots (an empty slot's key is NaN): the sampling oracle looks up every
// sample point of every answer here, and a node-per-entry std::unordered_map spent most of that
// time on cache misses. (The clipper has tables of its own; the judges share no code with it.)
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "ghclip/region.h"
#include "point_hash.h"

namespace gh::oracle {

template <class Value>
class PointTable {
 public:
  PointTable() = default;
  PointTable(const PointTable&) = default;
  PointTable(PointTable&&) noexcept = default;
  PointTable& operator=(const PointTable&) = default;
  PointTable& operator=(PointTable&&) noexcept = default;
  ~PointTable() { keepSlots(); }

  // The value stored under p (finite), default-made if p is new; and whether it was new. The
  // reference holds until the next insertion.
  std::pair<Value&, bool> findOrAdd(Point p) {
    if (2 * (size_ + 1) > capacity()) grow();
    std::size_t i = home(p);
    for (; !empty(slots_[i]); i = (i + 1) & mask_) {
      if (slots_[i].key == p) return {slots_[i].value, false};
    }
    slots_[i] = {p, Value{}};
    used_.push_back(static_cast<std::uint32_t>(i));
    ++size_;
    return {slots_[i].value, true};
  }

  std::size_t size() const { return size_; }

  // Empty again, keeping its slots: those in use emptied one by one, not the whole array.
  void clear() {
    for (const std::uint32_t i : used_) slots_[i] = Slot{};
    used_.clear();
    size_ = 0;
  }

  // The slot index is the hash's low bits, and a double with a short significand (a small
  // integer, a dyadic fraction) has all its low bits zero: each coordinate goes through a full
  // avalanche (splitmix64's finalizer) first. A multiply-and-shift left the points of a 9 x 9
  // integer grid in 9 of 256 slots.
  static std::uint64_t hash(Point p) { return mixedPointHash(p); }  // -0 and 0 are one key

 private:
  struct Slot {
    Point key{kNaN, kNaN};
    Value value{};
  };
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  static bool empty(const Slot& s) { return s.key.x != s.key.x; }

  std::size_t home(Point p) const { return static_cast<std::size_t>(hash(p)) & mask_; }
  // The slots in use are slots_[0 .. capacity()): the array may be longer (below).
  std::size_t capacity() const { return slots_.empty() ? 0 : mask_ + 1; }

  // The slot array of the thread's last table, emptied, kept for its next: a judge made for every
  // problem (a fuzz target's five answers) otherwise grew, faulted in and freed the same arrays each
  // time, about 5 % of fuzz_clip_exact's time. It is emptied slot by slot, those in use (used_),
  // and the next table starts with the capacity the last one ended with (the array growth from the
  // smallest would have reached), cut to what it held when that is 4 times less: the largest array
  // any table of the thread had needed, filled empty for every judge, was 3.5 % of
  // fuzz_clip_naive's time (perf), and left unfilled, its probes missed the cache. The array itself
  // is never cut: a table uses only its first capacity() slots, so its probes stay as near as in
  // an array of that size, and it grows within the array by rehashing in place. (Cutting and
  // regrowing the array made 52 KB of fresh slots an execution on fuzz_clip_exact's corpus, each
  // block through ASan's allocator in the fuzz build.) Arrays beyond kKeptSlots are let go.
  static constexpr std::size_t kSmallest = 1024, kKeptSlots = std::size_t{1} << 16;
  struct Kept {
    std::vector<Slot> slots;  // every slot empty
    std::vector<std::uint32_t> used;
    std::size_t capacity = 0;  // where the next table starts
    std::vector<Slot> moving;  // scratch: the entries of a table growing in place
  };
  static Kept& kept() {
    thread_local Kept k;
    return k;
  }
  void keepSlots() {
    if (slots_.empty() || slots_.size() > kKeptSlots) return;
    std::size_t fit = kSmallest;
    while (2 * (size_ + 1) > fit) fit *= 2;
    const std::size_t next = capacity() >= 4 * fit ? fit : capacity();
    clear();
    kept().slots.swap(slots_);
    kept().used.swap(used_);
    kept().capacity = next;
  }

  // Twice the capacity (kSmallest at first), every entry placed again in the order it came.
  void grow() {
    if (slots_.empty() && !kept().slots.empty()) {  // the kept array, empty
      slots_.swap(kept().slots);
      used_.swap(kept().used);
      mask_ = kept().capacity - 1;
      size_ = 0;
      if (2 * (size_ + 1) <= capacity()) return;
    }
    const std::size_t wanted = slots_.empty() ? kSmallest : 2 * capacity();
    if (wanted <= slots_.size()) {  // within the array: every slot past capacity() is empty
      std::vector<Slot>& moving = kept().moving;
      moving.clear();
      for (const std::uint32_t j : used_) moving.push_back(slots_[j]), slots_[j] = Slot{};
      used_.clear();
      mask_ = wanted - 1;
      size_ = 0;
      for (const Slot& slot : moving) place(slot);  // (at most kKeptSlots / 2 of them: kept arrays only)
      return;
    }
    std::vector<Slot> old = std::move(slots_);
    std::vector<std::uint32_t> oldUsed;
    oldUsed.swap(used_);
    slots_.assign(wanted, Slot{});
    mask_ = slots_.size() - 1;
    size_ = 0;
    for (const std::uint32_t j : oldUsed) place(old[j]);
  }
  // An entry whose key is not in the table yet, in the first empty slot from its home.
  void place(const Slot& slot) {
    std::size_t i = home(slot.key);
    while (!empty(slots_[i])) i = (i + 1) & mask_;
    slots_[i] = slot;
    used_.push_back(static_cast<std::uint32_t>(i));
    ++size_;
  }
  std::vector<Slot> slots_;
  std::vector<std::uint32_t> used_;  // the slots in use, in the order filled
  std::size_t mask_ = 0;
  std::size_t size_ = 0;
};

}  // namespace gh::oracle
