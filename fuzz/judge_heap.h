// In the fuzz build the judges' GMP numbers live on glibc's heap, not on ASan's.
//
// The judges (oracles/, peers/) are compiled without the sanitizers unless
// GHCLIP_FUZZ_SANITIZE_JUDGES is ON (see CMakeLists.txt), yet every block they allocate still went
// through ASan's allocator: its fill, poisoning and quarantine. The exact oracle builds CGAL
// arrangements over GMP rationals and allocates a GMP block for almost every number: perf put
// about 40 % of fuzz_clip_exact_oracle's corpus replay in that allocator.
//
// While a JudgeHeap is alive on a thread, GMP allocates from glibc (__libc_malloc), which ASan
// does not intercept. GMP numbers made outside any JudgeHeap (the exact clipper's) stay on ASan's
// heap with every check. A block is resized or freed by the heap that owns it (releasedByGlibc),
// so numbers may be made in one scope and freed in another. GMP blocks hold limbs, never
// pointers, so LeakSanitizer loses no path to an ASan block (it no longer sees a judge's leaked
// limbs). fuzz_clip_exact_oracle also routes its scalar `new` so (judge_operator_new.cpp).
// Everywhere else (the normal build, judges with the sanitizers, no ASan) a JudgeHeap does nothing.
#pragma once

#if defined(__has_feature)
#if __has_feature(address_sanitizer) && defined(GHCLIP_FUZZ_JUDGES_UNSANITIZED)
#define GHCLIP_JUDGE_HEAP 1
#endif
#endif

#ifdef GHCLIP_JUDGE_HEAP
#include <gmp.h>
#include <malloc.h>
#include <sanitizer/allocator_interface.h>

#include <unistd.h>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstdlib>

extern "C" void* __libc_malloc(std::size_t size);
extern "C" int __libc_mallopt(int parameter, int value);
extern "C" void* __libc_calloc(std::size_t count, std::size_t size);
extern "C" void* __libc_realloc(void* block, std::size_t size);
extern "C" void __libc_free(void* block);
#endif

namespace gh::fuzz {

#ifdef GHCLIP_JUDGE_HEAP

namespace judge_heap {

inline thread_local int depth = 0;  // open JudgeHeap scopes on this thread

inline std::uintptr_t breakAtInstall = 0;

// glibc's blocks that lie outside its break range: the large ones it maps on their own, and any
// when the break cannot grow. A set of addresses, open-addressed in glibc's own memory (a set made
// with `new` would call back into judge_operator_new.cpp), behind a spin lock.
class MappedBlocks {
 public:
  void insert(const void* block) {
    const Lock lock(busy_);
    if (2 * (filled_ + 1) > capacity_) rehash();
    std::size_t i = home(block);
    while (slots_[i] != kEmpty && slots_[i] != kGone) i = (i + 1) & (capacity_ - 1);
    if (slots_[i] == kEmpty) ++filled_;
    slots_[i] = block;
    size_.fetch_add(1, std::memory_order_relaxed);
  }
  // Whether the block is one of them; if so, it leaves the set.
  bool erase(const void* block) {
    if (size_.load(std::memory_order_relaxed) == 0) return false;  // the usual case: no lock
    const Lock lock(busy_);
    // Slots in use and emptied ones (kGone) fill at most half the array: a probe ends at kEmpty.
    for (std::size_t i = home(block); slots_[i] != kEmpty; i = (i + 1) & (capacity_ - 1)) {
      if (slots_[i] == block) {
        slots_[i] = kGone;
        size_.fetch_sub(1, std::memory_order_relaxed);
        return true;
      }
    }
    return false;
  }

 private:
  struct Lock {
    explicit Lock(std::atomic_flag& f) : flag(f) {
      while (flag.test_and_set(std::memory_order_acquire)) {
      }
    }
    ~Lock() { flag.clear(std::memory_order_release); }
    std::atomic_flag& flag;
  };
  static inline const void* const kEmpty = nullptr;
  static inline const void* const kGone = reinterpret_cast<const void*>(1);  // never a block's address
  std::size_t home(const void* block) const {
    auto h = static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(block));
    h = (h ^ (h >> 33)) * 0xff51afd7ed558ccdULL;
    return static_cast<std::size_t>(h ^ (h >> 33)) & (capacity_ - 1);
  }
  // Into an array four times the live entries (at least 64 slots), the emptied ones dropped.
  void rehash() {
    const void** old = slots_;
    const std::size_t oldCapacity = capacity_, live = size_.load(std::memory_order_relaxed);
    capacity_ = 64;
    while (capacity_ < 4 * (live + 1)) capacity_ *= 2;
    slots_ = static_cast<const void**>(__libc_calloc(capacity_, sizeof(const void*)));
    if (!slots_) std::abort();
    filled_ = 0;
    for (std::size_t j = 0; j < oldCapacity; ++j) {
      if (old[j] == kEmpty || old[j] == kGone) continue;
      std::size_t i = home(old[j]);
      while (slots_[i] != kEmpty) i = (i + 1) & (capacity_ - 1);
      slots_[i] = old[j];
      ++filled_;
    }
    __libc_free(old);
  }
  std::atomic_flag busy_ = ATOMIC_FLAG_INIT;
  const void** slots_ = nullptr;
  std::size_t capacity_ = 0;
  std::size_t filled_ = 0;           // slots not kEmpty: in use or emptied
  std::atomic<std::size_t> size_{0};  // slots in use
};

inline MappedBlocks mappedBlocks;

// glibc's main arena grows by brk, which ASan's allocator never uses (it maps its own regions),
// so a block between the break at installation and the break is glibc's: no question asked. The
// break as last read (sbrk(0) is a system call here: 1 % of fuzz_clip_exact_oracle's time when
// read for every block) is at most today's, as glibc is told never to give memory back by
// lowering it (JudgeHeap); it is read again only for a new block beyond it.
inline std::atomic<std::uintptr_t> breakSeen{0};
inline bool inBreakRange(const void* block) {
  const auto at = reinterpret_cast<std::uintptr_t>(block);
  return at >= breakAtInstall && at < breakSeen.load(std::memory_order_relaxed);
}

// A block from glibc, its address noted when it lies outside the break range.
inline void* fromGlibc(void* block) {
  if (block && !inBreakRange(block)) {
    breakSeen.store(reinterpret_cast<std::uintptr_t>(sbrk(0)), std::memory_order_relaxed);
    if (!inBreakRange(block)) mappedBlocks.insert(block);
  }
  return block;
}

// Whether a block is glibc's (made in a JudgeHeap), known positively; if it was noted, the note
// goes: the caller is about to free or move it. Every other block is handed to ASan, which owns
// it or reports the free: a double free or a wild pointer in the clipper is caught as before.
// (Asking ASan instead, __sanitizer_get_ownership, says no for a block it has already freed,
// which sent a double free to glibc; it also scans ASan's list of large blocks to say no.)
inline bool releasedByGlibc(void* block) { return inBreakRange(block) || mappedBlocks.erase(block); }

// A block from the heap of the scope: glibc's inside a JudgeHeap, else ASan's. Null when out of
// memory (GMP aborts, operator new tries its new_handler).
inline void* tryAllocate(std::size_t size) { return depth > 0 ? fromGlibc(__libc_malloc(size)) : std::malloc(size); }

// Hands a block to the heap that owns it.
inline void freeBlock(void* block) {
  if (releasedByGlibc(block)) {
    __libc_free(block);
  } else {
    std::free(block);  // ASan's, or a double free or wild pointer for ASan to report
  }
}

inline void* allocate(std::size_t size) {
  void* block = tryAllocate(size);
  if (!block) std::abort();  // GMP's own functions abort too when memory runs out
  return block;
}

inline void* reallocate(void* block, std::size_t, std::size_t size) {
  if (!block) return allocate(size);
  void* moved = releasedByGlibc(block) ? fromGlibc(__libc_realloc(block, size)) : std::realloc(block, size);
  if (!moved) std::abort();
  return moved;
}

inline void release(void* block, std::size_t) { freeBlock(block); }

}  // namespace judge_heap

class JudgeHeap {
 public:
  JudgeHeap() {
    // Blocks GMP made before this ran came from ASan's malloc; release() returns them there.
    static const bool installed = [] {
      judge_heap::breakAtInstall = reinterpret_cast<std::uintptr_t>(sbrk(0));
      judge_heap::breakSeen.store(judge_heap::breakAtInstall, std::memory_order_relaxed);
      // The break never comes down (inBreakRange): no trimming of the top of glibc's heap.
      __libc_mallopt(M_TRIM_THRESHOLD, -1);
      mp_set_memory_functions(judge_heap::allocate, judge_heap::reallocate, judge_heap::release);
      return true;
    }();
    (void)installed;
    ++judge_heap::depth;
  }
  ~JudgeHeap() { --judge_heap::depth; }
  JudgeHeap(const JudgeHeap&) = delete;
  JudgeHeap& operator=(const JudgeHeap&) = delete;
};

#else

class JudgeHeap {
 public:
  JudgeHeap() {}  // user-provided: a scope guard is not an unused variable
  JudgeHeap(const JudgeHeap&) = delete;
  JudgeHeap& operator=(const JudgeHeap&) = delete;
};

#endif

}  // namespace gh::fuzz
