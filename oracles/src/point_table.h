// A map from finite points (by exact coordinates, 0 and -0 one key) to small values, open-addressed
// in one array of 24-byte slots (an empty slot's key is NaN): the sampling oracle looks up every
// sample point of every answer here, and a node-per-entry std::unordered_map spent most of that
// time on cache misses. (The clipper has tables of its own; the judges share no code with it.)
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <utility>
#include <vector>

#include "ghclip/region.h"
#include "mix_bits.h"

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
    if (2 * (size_ + 1) > slots_.size()) grow();
    std::size_t i = home(p);
    for (; !empty(slots_[i]); i = (i + 1) & mask_) {
      if (slots_[i].key == p) return {slots_[i].value, false};
    }
    slots_[i] = {p, Value{}};
    ++size_;
    return {slots_[i].value, true};
  }

  std::size_t size() const { return size_; }

  // Empty again, keeping its slots.
  void clear() {
    std::fill(slots_.begin(), slots_.end(), Slot{});
    size_ = 0;
  }

  // The slot index is the hash's low bits, and a double with a short significand (a small
  // integer, a dyadic fraction) has all its low bits zero: each coordinate goes through a full
  // avalanche (splitmix64's finalizer) first. A multiply-and-shift left the points of a 9 x 9
  // integer grid in 9 of 256 slots.
  static std::uint64_t hash(Point p) {
    const double x = p.x + 0.0, y = p.y + 0.0;  // + 0.0: -0 and 0 are one key
    std::uint64_t bx, by;
    std::memcpy(&bx, &x, sizeof bx), std::memcpy(&by, &y, sizeof by);
    return mixBits(mixBits(bx) + by);
  }

 private:
  struct Slot {
    Point key{kNaN, kNaN};
    Value value{};
  };
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  static bool empty(const Slot& s) { return s.key.x != s.key.x; }

  std::size_t home(Point p) const { return static_cast<std::size_t>(hash(p)) & mask_; }

  // The slot array of the thread's last table, kept for its next: a judge made for every problem
  // (a fuzz target's five answers) otherwise grew, faulted in and freed the same arrays each time,
  // about 5 % of fuzz_clip_exact's time. Arrays beyond kKeptSlots are let go.
  static constexpr std::size_t kKeptSlots = std::size_t{1} << 16;
  static std::vector<Slot>& kept() {
    thread_local std::vector<Slot> slots;
    return slots;
  }
  void keepSlots() {
    if (slots_.size() > kKeptSlots || slots_.size() <= kept().size()) return;
    kept().swap(slots_);
  }

  void grow() {
    if (slots_.empty() && !kept().empty()) {  // the kept array, emptied
      slots_.swap(kept());
      std::fill(slots_.begin(), slots_.end(), Slot{});
      mask_ = slots_.size() - 1;
      size_ = 0;
      if (2 * (size_ + 1) <= slots_.size()) return;
    }
    std::vector<Slot> old = std::move(slots_);
    slots_.assign(old.empty() ? 1024 : 2 * old.size(), Slot{});
    mask_ = slots_.size() - 1;
    size_ = 0;
    for (const Slot& s : old) {
      if (empty(s)) continue;
      std::size_t i = home(s.key);
      while (!empty(slots_[i])) i = (i + 1) & mask_;
      slots_[i] = s;
      ++size_;
    }
  }

  std::vector<Slot> slots_;
  std::size_t mask_ = 0;
  std::size_t size_ = 0;
};

}  // namespace gh::oracle
