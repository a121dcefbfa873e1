// Checks fuzz/judge_heap.h and fuzz/judge_operator_new.cpp as the fuzz build uses them (compiled
// with ASan by judge_heap_test.sh): GMP blocks and blocks of `new` made inside a JudgeHeap are
// glibc's, those made outside stay ASan's, and every block is resized and freed by its own heap
// whichever scope it crosses into. A block handed to the wrong heap is a crash under ASan (or
// glibc's "free(): invalid pointer"), so the program exiting 0 is part of the check. Prints one
// line per failed expectation and exits 1. With an argument it commits one memory error outside
// any JudgeHeap (the script expects ASan, or the sized delete's own check, to stop it).
#include <gmpxx.h>
#include <sanitizer/allocator_interface.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "judge_heap.h"

#ifndef GHCLIP_JUDGE_HEAP
#error "judge_heap_test.cpp must be compiled with ASan and GHCLIP_FUZZ_JUDGES_UNSANITIZED"
#endif

namespace {

int failures = 0;

void expect(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "FAILED: %s\n", what);
    ++failures;
  }
}

bool onAsan(const void* block) { return __sanitizer_get_ownership(block) != 0; }
bool onAsan(const mpz_class& z) { return onAsan(z.get_mpz_t()->_mp_d); }

struct Base {
  long a = 1;
};
struct Derived : Base {  // no virtual destructor: deleting it as a Base deletes the wrong size
  long b[4] = {2, 3, 4, 5};
};

// One memory error on blocks of `new` made outside any JudgeHeap (the clipper's). volatile: the
// compiler may not see through to the error and drop it.
int commit(const std::string& error) {
  if (error == "heap-buffer-overflow") {
    Derived* volatile block = new Derived;
    volatile long* past = block->b;
    past[4] = 1;  // one past the end
    delete block;
  } else if (error == "heap-use-after-free") {
    int* volatile block = new int(7);
    delete block;
    return *block;
  } else if (error == "alloc-dealloc-mismatch") {
    int* volatile block = new int[1];  // one int: the sized delete's size is right, ASan sees new[]
    delete block;
  } else if (error == "new-delete-type-mismatch") {
    Base* volatile block = new Derived;
    delete block;  // the sized delete, given Base's size
  } else if (error == "double-free") {
    int* volatile block = new int(1);
    delete block;
    delete block;
  } else {
    std::fprintf(stderr, "unknown error %s\n", error.c_str());
    return 3;
  }
  std::fprintf(stderr, "%s: not stopped\n", error.c_str());
  return 0;
}

mpz_class big(unsigned long bits) {
  mpz_class z = 1;
  z <<= bits;
  return z + 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1) return commit(argv[1]);
  using gh::fuzz::JudgeHeap;
  // Made before any JudgeHeap installed the functions: GMP's default malloc, i.e. ASan's.
  auto early = std::make_unique<mpz_class>(big(4000));
  expect(onAsan(*early), "a number made before installation is on ASan's heap");

  std::unique_ptr<mpz_class> judged, judgedLarge;
  mpz_class clipper = big(3000);  // the clipper's: outside every scope
  {
    const JudgeHeap heap;
    expect(!onAsan(big(100)), "a number made inside a JudgeHeap is on glibc's heap");
    judged = std::make_unique<mpz_class>(big(5000));
    expect(!onAsan(*judged), "a number made inside a JudgeHeap is on glibc's heap (kept)");
    // 2^21 bits = 256 KiB of limbs: above glibc's mmap threshold, outside the brk heap.
    judgedLarge = std::make_unique<mpz_class>(big(1ul << 21));
    expect(!onAsan(*judgedLarge), "a large number made inside a JudgeHeap is glibc's");
    mpz_realloc2(clipper.get_mpz_t(), 20000);  // an ASan block grown inside a scope stays ASan's
    expect(onAsan(clipper), "an ASan block resized inside a JudgeHeap stays on ASan's heap");
    early.reset();  // an ASan block freed inside a scope
    {
      const JudgeHeap nested;
      expect(!onAsan(big(200)), "nested scopes allocate from glibc");
    }
    expect(!onAsan(big(300)), "a scope still open after a nested one closed allocates from glibc");
  }
  expect(onAsan(big(100)), "after the last scope closed, numbers are on ASan's heap again");
  mpz_realloc2(judged->get_mpz_t(), 20000);  // a glibc block grown outside any scope stays glibc's
  expect(!onAsan(*judged), "a glibc block resized outside a JudgeHeap stays on glibc's heap");
  judged.reset();  // glibc blocks freed outside any scope
  judgedLarge.reset();
  mpz_class fresh = big(2000);
  expect(onAsan(fresh), "a number made after the scopes is on ASan's heap");

  // Blocks of `new` (judge_operator_new.cpp): CGAL's arrangement and lazy numbers in the judge.
  std::vector<std::unique_ptr<Derived>> judgedObjects, crossing;
  std::vector<double> clipperVector(100, 1.0);  // the clipper's, outside every scope
  expect(onAsan(clipperVector.data()), "a vector made outside a JudgeHeap is on ASan's heap");
  {
    const JudgeHeap heap;
    for (int i = 0; i < 10; ++i) judgedObjects.push_back(std::make_unique<Derived>());
    expect(!onAsan(judgedObjects.back().get()), "an object made by new inside a JudgeHeap is glibc's");
    expect(!onAsan(judgedObjects.data()), "a vector's array grown inside a JudgeHeap is glibc's");
    std::vector<char> large(1 << 20);  // above glibc's mmap threshold
    expect(!onAsan(large.data()), "a large array made inside a JudgeHeap is glibc's");
    clipperVector.resize(10000);  // an ASan array replaced inside a scope: the old one back to ASan
    expect(!onAsan(clipperVector.data()), "a vector grown inside a JudgeHeap moves to glibc's heap");
    crossing.push_back(std::make_unique<Derived>());  // a vector made outside, grown inside
    expect(!onAsan(crossing.data()) && !onAsan(crossing.back().get()), "blocks made inside a JudgeHeap are glibc's");
    std::string text(1000, 'x');  // through libstdc++'s own calls to operator new
    expect(!onAsan(text.data()), "a string made inside a JudgeHeap is glibc's");
    auto* array = new int[10];  // new[] is ASan's everywhere (it is not replaced)
    expect(onAsan(array), "new[] inside a JudgeHeap stays ASan's");
    delete[] array;
  }
  auto outside = std::make_unique<Derived>();
  expect(onAsan(outside.get()), "an object made by new after the scopes is on ASan's heap");
  Base* asBase = new Derived;
  delete static_cast<Derived*>(asBase);  // the sized delete with the right size passes
  judgedObjects.clear();  // glibc blocks deleted outside any scope (sized deletes)
  crossing.clear();
  clipperVector.clear();
  clipperVector.shrink_to_fit();
  // Large glibc blocks (mapped, noted in a set) made and freed many times over, with ASan blocks
  // freed in between (each a look-up of a block not in the set, which must end).
  {
    std::vector<std::vector<char>> large;
    large.reserve(64);
    for (int i = 0; i < 3000; ++i) {
      {
        const JudgeHeap heap;
        large.emplace_back(200000 + 16 * (i % 97));
        expect(!onAsan(large.back().data()), "a large block made inside a JudgeHeap is glibc's");
      }
      if (large.size() == 64) large.erase(large.begin(), large.begin() + 32);
      expect(onAsan(std::make_unique<Derived>().get()), "an object made outside every scope is ASan's");
    }
  }
  // The set itself, over many distinct addresses (never dereferenced) with few in it at once:
  // its emptied slots must not use up the array, or a look-up of an address not in it never ends.
  {
    gh::fuzz::judge_heap::MappedBlocks set;
    auto address = [](std::uintptr_t k) { return reinterpret_cast<const void*>((k + 1) << 12); };
    bool all = true;
    for (std::uintptr_t k = 0; k < 100000; ++k) {
      set.insert(address(k));
      if (k >= 8) all &= set.erase(address(k - 8));
      all &= !set.erase(address(k + 1000000));
    }
    expect(all, "the set of mapped blocks finds what it holds and not what it does not");
  }
  if (failures == 0) std::printf("judge heap: every expectation met\n");
  return failures == 0 ? 0 : 1;
}
