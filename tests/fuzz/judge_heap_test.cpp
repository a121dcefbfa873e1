// Checks fuzz/judge_heap.h as the fuzz build uses it (compiled with ASan by judge_heap_test.sh):
// GMP blocks made inside a JudgeHeap are glibc's, those made outside stay ASan's, and every
// block is resized and freed by its own heap whichever scope it crosses into. A block handed to
// the wrong heap is a crash under ASan (or glibc's "free(): invalid pointer"), so the program
// exiting 0 is part of the check. Prints one line per failed expectation and exits 1.
#include <gmpxx.h>
#include <sanitizer/allocator_interface.h>

#include <cstdio>
#include <memory>

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

bool onAsan(const mpz_class& z) { return __sanitizer_get_ownership(z.get_mpz_t()->_mp_d) != 0; }

mpz_class big(unsigned long bits) {
  mpz_class z = 1;
  z <<= bits;
  return z + 1;
}

}  // namespace

int main() {
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
  if (failures == 0) std::printf("judge heap: every expectation met\n");
  return failures == 0 ? 0 : 1;
}
