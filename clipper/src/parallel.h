// Work split over threads with a result that does not depend on how many there are: the range
// [0, count) is cut into `pieces` contiguous pieces, piece p gets [begin(p), end(p)) and its own
// output slot p, threads take pieces in turn, and the caller merges the slots in piece order.
// std::thread per call: a clip is long enough to pay for starting them (callers only split large
// work), and nothing outlives the call.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace gh::detail {

struct Pieces {
  std::size_t count = 0, pieces = 1;
  std::size_t begin(std::size_t p) const { return count * p / pieces; }
  std::size_t end(std::size_t p) const { return count * (p + 1) / pieces; }
};

// How many pieces to cut `count` units of work into for `threads` threads: one when there is one
// thread or too little work to share, else a few per thread so that uneven pieces balance.
inline Pieces piecesFor(std::size_t count, unsigned threads, std::size_t minimumPerPiece) {
  if (threads <= 1 || count < 2 * minimumPerPiece) return {count, 1};
  return {count, std::min<std::size_t>(4 * std::size_t{threads}, std::max<std::size_t>(1, count / minimumPerPiece))};
}

// Calls run(p) for every piece p in [0, pieces.pieces), on up to `threads` threads (the caller is
// one of them). The first exception a piece throws is rethrown here, after all threads stopped.
template <class Run>
void runPieces(const Pieces& pieces, unsigned threads, Run&& run) {
  if (pieces.pieces <= 1 || threads <= 1) {
    for (std::size_t p = 0; p < pieces.pieces; ++p) run(p);
    return;
  }
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failureMutex;
  auto work = [&] {
    for (std::size_t p; (p = next.fetch_add(1)) < pieces.pieces;) {
      try {
        run(p);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(failureMutex);
        if (!failure) failure = std::current_exception();
      }
    }
  };
  std::vector<std::thread> helpers;
  const unsigned extra = static_cast<unsigned>(std::min<std::size_t>(threads, pieces.pieces)) - 1;
  helpers.reserve(extra);
  for (unsigned t = 0; t < extra; ++t) helpers.emplace_back(work);
  work();
  for (std::thread& t : helpers) t.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace gh::detail
