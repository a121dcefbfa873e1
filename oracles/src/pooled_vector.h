// A std::vector whose storage is taken from, and given back to, a per-thread pool of vectors of
// its element type. The sampling judge is built afresh for every fuzz execution, and its grids,
// bands and scratch lists came to ~350 blocks and ~550 KB an execution: under ASan every fresh
// block goes through the sanitizer's allocator (its poisoning, and a quarantine that hands out
// memory not touched since), even for the judge, compiled without the sanitizers (which cost 1.6
// times in the fuzz build what it costs in a normal build, not all of it there). Pooled, the
// storage of the last execution is reused.
//
// It is a std::vector in every other way (contents, growth, copies); only where its storage
// comes from and goes differs. A pool keeps at most kMostPooled vectors per element type, each
// of at most kMostBytes: a judge of one huge problem does not keep its memory for good.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

namespace gh::oracle {

template <class T>
class PooledVector : public std::vector<T> {
 public:
  PooledVector() { take(); }
  explicit PooledVector(std::size_t n) {
    take();
    this->resize(n);
  }
  PooledVector(std::size_t n, const T& value) {
    take();
    this->assign(n, value);
  }
  template <class Iterator>
  PooledVector(Iterator first, Iterator last) {
    take();
    this->assign(first, last);
  }
  PooledVector(const PooledVector& other) : std::vector<T>() {
    take();
    this->assign(other.begin(), other.end());
  }
  PooledVector(PooledVector&& other) noexcept : std::vector<T>(std::move(other)) {}
  PooledVector& operator=(const PooledVector& other) {
    if (this != &other) this->assign(other.begin(), other.end());
    return *this;
  }
  PooledVector& operator=(PooledVector&& other) noexcept {
    if (this != &other) {
      giveBack();
      std::vector<T>::operator=(std::move(other));
    }
    return *this;
  }
  ~PooledVector() { giveBack(); }

 private:
  static constexpr std::size_t kMostPooled = 16;
  static constexpr std::size_t kMostBytes = std::size_t{4} << 20;

  static std::vector<std::vector<T>>& pool() {
    thread_local std::vector<std::vector<T>> vectors;
    return vectors;
  }
  void take() {
    std::vector<std::vector<T>>& vectors = pool();
    if (vectors.empty()) return;
    this->swap(vectors.back());
    vectors.pop_back();
  }
  void giveBack() {
    if (this->capacity() == 0 || this->capacity() > kMostBytes / sizeof(T)) return;
    std::vector<std::vector<T>>& vectors = pool();
    if (vectors.size() >= kMostPooled) return;
    this->clear();
    vectors.emplace_back();
    vectors.back().swap(*this);
  }
};

}  // namespace gh::oracle
