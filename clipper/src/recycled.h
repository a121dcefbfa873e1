// Large arrays a clip needs for its duration only (the ordered crossings, the vertex graph, the
// traced rings), borrowed from a per-thread spare and given back after: a clip of two 10^3-gons
// fills ~30 MB of them, and fresh memory costs page faults in every clip (the allocator returns
// freed blocks of that size to the system). A spare larger than kKeepBytes is let go instead.
#pragma once

#include <cstddef>
#include <vector>

namespace gh::detail {

enum class Spare { SubjectNodes, ClipNodes, TracedPoints };

inline constexpr std::size_t kKeepBytes = std::size_t{64} << 20;

template <class T, Spare kWhich>
std::vector<T>& spare() {
  thread_local std::vector<T> kept;
  return kept;
}

// An empty vector with the spare's capacity.
template <Spare kWhich, class T>
void borrow(std::vector<T>& into) {
  into.clear();
  into.swap(spare<T, kWhich>());
  into.clear();
}

template <Spare kWhich, class T>
void giveBack(std::vector<T>& from) {
  if (from.capacity() * sizeof(T) > kKeepBytes) return;
  spare<T, kWhich>().swap(from);
}

}  // namespace gh::detail
