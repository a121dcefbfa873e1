// The scalar operator new and delete of a fuzz target that judges with CGAL (linked into
// fuzz_clip_exact_oracle only, fuzz/CMakeLists.txt): inside a JudgeHeap they take their blocks
// from glibc, like the judges' GMP numbers (judge_heap.h), and everywhere else from ASan.
//
// Why: the exact oracle's arrangement, its sweep and its lazy numbers allocate a block for almost
// every vertex, edge, event and number, all through `new`. The judge is compiled without the
// sanitizers, but its blocks still went through ASan's allocator (its fill, poisoning, quarantine
// and the libFuzzer hooks on it): 29 % of fuzz_clip_exact_oracle's time (perf, its grown corpus).
//
// What the clipper keeps: outside a JudgeHeap every block is ASan's (bounds, use after free,
// double free, leaks), delete hands each block back to the heap that owns it, and the sized
// delete checks the size as ASan's does (new-delete-type-mismatch). What it gives up in this one
// target: ASan's own operators tag a block as made by new, so a block of new given to free() or
// one of malloc() to delete is reported; here new makes ASan blocks with malloc(), and those two
// mix-ups pass. fuzz_clip_exact runs the same exact clipper on the same kind of input with ASan's
// own operators, so the mix-ups stay caught there. The array and aligned forms are ASan's: a
// delete of new[]'s block is still caught here (ASan reports new[] freed by free()).
//
// Without ASan, or with the judges under the sanitizers (judge_heap.h), this file defines nothing.
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <new>

#include "judge_heap.h"

#ifdef GHCLIP_JUDGE_HEAP

namespace {

using gh::fuzz::judge_heap::freeBlock;

void* allocate(std::size_t size) {
  if (size == 0) size = 1;  // distinct pointers for empty objects
  for (;;) {
    if (void* block = gh::fuzz::judge_heap::tryAllocate(size)) return block;
    const std::new_handler handler = std::get_new_handler();
    if (!handler) return nullptr;
    handler();
  }
}

// ASan's sized delete checks that the size is the one the block was made with (the delete of a
// base class without a virtual destructor); so does this one, for ASan's blocks (the clipper's).
void freeSized(void* block, std::size_t size) {
  if (!gh::fuzz::judge_heap::inBreakRange(block) && __sanitizer_get_ownership(block)) {
    const std::size_t made = __sanitizer_get_allocated_size(block);
    if (made != (size == 0 ? 1 : size)) {  // allocate() made an empty object 1 byte
      std::fprintf(stderr,
                   "ERROR: new-delete-type-mismatch (fuzz/judge_operator_new.cpp): a block of %zu bytes deleted as %zu "
                   "bytes\n",
                   made, size);
      std::abort();
    }
  }
  freeBlock(block);
}

}  // namespace

void* operator new(std::size_t size) {
  void* block = allocate(size);
  if (!block) throw std::bad_alloc();
  return block;
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return allocate(size);
  } catch (...) {  // a new_handler may throw
    return nullptr;
  }
}
void operator delete(void* block) noexcept {
  if (block) freeBlock(block);
}
void operator delete(void* block, const std::nothrow_t&) noexcept {
  if (block) freeBlock(block);
}
void operator delete(void* block, std::size_t size) noexcept {
  if (block) freeSized(block, size);
}

#endif
