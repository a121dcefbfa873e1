// Per-thread working memory that the phases of a clip use in turn: phase 1's sort items and
// phase 3's trace arrays are never alive together, so they share one block, and a clip's peak
// memory is the larger of them rather than their sum. The block is kept for the thread's next
// clip (fresh memory costs page faults), unless it grew beyond kKeepBytes (recycled.h).
//
//   ScratchLayout layout;
//   const auto items = layout.add<SortItem>(k);
//   const auto position = layout.add<std::uint32_t>(k);
//   std::byte* base = scratch(layout.bytes());   // contents undefined; trivially copyable types
//   SortItem* i = items(base);
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <type_traits>

#include "recycled.h"

namespace gh::detail {

// Where each array of a scratch block starts; every array 64-byte aligned.
class ScratchLayout {
 public:
  template <class T>
  struct Slot {
    std::size_t offset;
    T* operator()(std::byte* base) const { return reinterpret_cast<T*>(base + offset); }
  };
  template <class T>
  Slot<T> add(std::size_t count) {
    static_assert(std::is_trivially_copyable_v<T> && alignof(T) <= 64, "scratch holds plain data");
    const Slot<T> slot{bytes_};
    bytes_ += (count * sizeof(T) + 63) / 64 * 64;
    return slot;
  }
  std::size_t bytes() const { return bytes_; }

 private:
  std::size_t bytes_ = 0;
};

// The calling thread's block, at least `bytes` long and 64-byte aligned; what it held is lost.
inline std::byte* scratch(std::size_t bytes) {
  struct alignas(64) Line {
    std::byte b[64];
  };
  thread_local std::unique_ptr<Line[]> block;
  thread_local std::size_t lines = 0;
  const std::size_t needed = (bytes + 63) / 64;
  if (lines < needed || lines * 64 > kKeepBytes + bytes) {
    block.reset();
    block.reset(new Line[needed]);  // not zeroed: every use writes before it reads
    lines = needed;
  }
  return reinterpret_cast<std::byte*>(block.get());
}

}  // namespace gh::detail
