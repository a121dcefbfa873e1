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
// heap with every check. A block is resized or freed by the heap that owns it (onAsanHeap), so
// numbers may be made in one scope and freed in another. GMP blocks hold limbs, never pointers,
// so LeakSanitizer loses no path to an ASan block (it no longer sees a judge's leaked limbs).
// Everywhere else (the normal build, judges with the sanitizers, no ASan) a JudgeHeap does nothing.
#pragma once

#if defined(__has_feature)
#if __has_feature(address_sanitizer) && defined(GHCLIP_FUZZ_JUDGES_UNSANITIZED)
#define GHCLIP_JUDGE_HEAP 1
#endif
#endif

#ifdef GHCLIP_JUDGE_HEAP
#include <gmp.h>
#include <sanitizer/allocator_interface.h>

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>

extern "C" void* __libc_malloc(std::size_t size);
extern "C" void* __libc_realloc(void* block, std::size_t size);
extern "C" void __libc_free(void* block);
#endif

namespace gh::fuzz {

#ifdef GHCLIP_JUDGE_HEAP

namespace judge_heap {

inline thread_local int depth = 0;  // open JudgeHeap scopes on this thread

inline void* allocate(std::size_t size) {
  void* block = depth > 0 ? __libc_malloc(size) : std::malloc(size);
  if (!block) std::abort();  // GMP's own functions abort too when memory runs out
  return block;
}

inline std::uintptr_t breakAtInstall = 0;

// Which heap a block is on. __sanitizer_get_ownership answers quickly for ASan's small blocks but
// scans ASan's list of large blocks to say no (9 % of fuzz_clip_exact's time when asked for every
// glibc block). glibc's main arena grows by brk, which ASan's allocator never uses (it maps its own
// regions), so a block between the break at installation and today's is glibc's: no question asked.
inline bool onAsanHeap(void* block) {
  const auto at = reinterpret_cast<std::uintptr_t>(block);
  if (at >= breakAtInstall && at < reinterpret_cast<std::uintptr_t>(sbrk(0))) return false;
  return __sanitizer_get_ownership(block) != 0;
}

inline void* reallocate(void* block, std::size_t, std::size_t size) {
  if (!block) return allocate(size);
  void* moved = onAsanHeap(block) ? std::realloc(block, size) : __libc_realloc(block, size);
  if (!moved) std::abort();
  return moved;
}

inline void release(void* block, std::size_t) {
  if (onAsanHeap(block)) {
    std::free(block);
  } else {
    __libc_free(block);
  }
}

}  // namespace judge_heap

class JudgeHeap {
 public:
  JudgeHeap() {
    // Blocks GMP made before this ran came from ASan's malloc; release() returns them there.
    static const bool installed = [] {
      judge_heap::breakAtInstall = reinterpret_cast<std::uintptr_t>(sbrk(0));
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
