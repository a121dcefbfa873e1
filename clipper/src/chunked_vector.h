// A growing sequence in fixed blocks: appending never moves what is there (no copy, and no moment
// with both an old and a new array alive, as a growing std::vector has), blocks are kept when it
// is cleared, and it is read in order. For phase 1's crossings, whose number is not known until
// they are found.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

namespace gh::detail {

template <class T>
class ChunkedVector {
 public:
  static constexpr std::size_t kBlock = std::size_t{1} << 14;

  void push_back(const T& value) {
    if (size_ == blocks_.size() * kBlock) blocks_.push_back(std::unique_ptr<T[]>(new T[kBlock]));
    blocks_[size_ / kBlock][size_ % kBlock] = value;
    ++size_;
  }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  void clear() { size_ = 0; }
  // Gives back blocks beyond what `keep` elements need.
  void trim(std::size_t keep) { blocks_.resize(std::min(blocks_.size(), (keep + kBlock - 1) / kBlock)); }
  const T& operator[](std::size_t i) const { return blocks_[i / kBlock][i % kBlock]; }

  // Calls f(element) for every element in order.
  template <class F>
  void forEach(F&& f) const {
    for (std::size_t b = 0, left = size_; left > 0; ++b) {
      const std::size_t n = std::min(left, kBlock);
      for (std::size_t i = 0; i < n; ++i) f(blocks_[b][i]);
      left -= n;
    }
  }

 private:
  std::vector<std::unique_ptr<T[]>> blocks_;
  std::size_t size_ = 0;
};

}  // namespace gh::detail
