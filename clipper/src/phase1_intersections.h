// Phase 1 of Greiner-Hormann (paper, Section 4.1): find every crossing of a subject edge with a
// clip edge and order the crossings along both operands' edges.
//
// Written once over two plug-ins:
//   Search     which edge pairs to test (search/: all pairs, or a sweep), as a plan of units that
//              can be visited in pieces: plan(subject, clip).visit(begin, end, onRow, onPair)
//   Arithmetic how a pair is decided and how crossings are ordered along an edge (arithmetic/:
//              the paper's doubles, or exact predicates under Simulation of Simplicity):
//                PairTest test(subject, se, clip, ce, Crossing& out, Extra& extra)
//                void testRow(subject, se, clip, CrossingBuffer<Extra>&)   (all clip edges)
//                int compareAlongSubject(SortItem a, SortItem b, edge, subject, clip),
//                    compareAlongClip, double errorAlongSubject(Extra), errorAlongClip,
//                    bool atInputVertex(Extra)
//              where Extra is whatever the policy's ordering needs beside the Crossing (nothing for
//              the paper's), kept only during phase 1.
// A policy that can meet degenerate contacts (Arithmetic::kReportsDegeneracies, the paper's only)
// reports them; phase 1 then lists the vertices concerned and stops before ordering. What to do
// about them is not phase 1's business: paper_perturbation.h wraps it.
//
// The search runs in pieces on `threads` threads (parallel.h), each piece into its own buffer;
// the buffers are read in piece order, and the order along the edges is a total order, so the
// result does not depend on the number of threads. Ordering costs O(k + n + m) plus short sorts:
// crossings are bucketed by edge (counting sort, stable) and each edge's own crossings are sorted
// along it. Ties (several crossings at one point) are broken by the other edge's index, so every
// search yields the same lists.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "arithmetic/pair_test.h"
#include "arithmetic/row_kernels.h"
#include "ghclip/stats.h"
#include "parallel.h"
#include "phase1_buffers.h"
#include "phase1_result.h"
#include "recycled.h"
#include "scratch.h"

namespace gh::detail {

// Vertices found on the other operand's edges (sorted, unique).
struct Degeneracies {
  std::vector<std::uint32_t> subject, clip;
  bool empty() const { return subject.empty() && clip.empty(); }
};

// One crossing as the sort along an edge sees it, with what the node it becomes needs: its
// position there (with a certified error bound, 0 when the arithmetic has none), its point, the
// other edge (the tie-breaker) and where it comes from.
struct SortItem {
  double alpha, err;
  Point point;
  std::uint32_t other;
  std::uint32_t index : 31;
  std::uint32_t atInputVertex : 1;  // the point is exactly an input vertex (the exact arithmetic's limit)
};
static_assert(sizeof(SortItem) == 40, "a sort item is 40 bytes");

// Sorts the crossings of one edge, [first, last), along it, in the order of a total order:
// alpha first (ties: the other edge), which is the whole order for an arithmetic whose order is
// alpha's (the paper's); otherwise alpha only approximates it, and the arithmetic's compare(a, b)
// (-1, 0: a tie, +1; consistent with every certified interval alpha +- err) decides within each
// group of crossings whose intervals overlap. Expected O(s) for s crossings: the alphas are spread
// over s slots by value and each slot's few are sorted by insertion.
template <bool kAlphaOrderIsExact, class Compare>
void sortAlongEdge(SortItem* first, SortItem* last, std::vector<SortItem>& scratch, std::vector<std::uint32_t>& slots,
                   Compare&& compare) {
  const std::size_t s = static_cast<std::size_t>(last - first);
  if (s < 2) return;
  if constexpr (!kAlphaOrderIsExact) {
    // An alpha the arithmetic could not approximate (NaN or infinite: its determinants under- or
    // overflowed) only starts the sort somewhere: its unbounded interval sends it to the exact
    // comparison, as it does in the arithmetic's own compare.
    for (SortItem* i = first; i < last; ++i) {
      if (!std::isfinite(i->alpha)) i->alpha = 0.5, i->err = INFINITY;
    }
  }
  auto byAlpha = [](const SortItem& a, const SortItem& b) {
    return a.alpha < b.alpha || (!(b.alpha < a.alpha) && a.other < b.other);
  };
  auto insertionSort = [&byAlpha](SortItem* b, SortItem* e) {
    for (SortItem* i = b + 1; i < e; ++i) {
      const SortItem x = *i;
      SortItem* j = i;
      for (; j > b && byAlpha(x, *(j - 1)); --j) *j = *(j - 1);
      *j = x;
    }
  };
  if (s <= 16) {
    insertionSort(first, last);
  } else {
    // Spread: slot floor(alpha * s), monotone in alpha, so sorting within slots sorts all.
    slots.assign(s + 1, 0);
    auto slotOf = [s](double alpha) {
      const double t = alpha * static_cast<double>(s);
      if (!(t > 0)) return std::size_t{0};
      return t >= static_cast<double>(s) ? s - 1 : static_cast<std::size_t>(t);
    };
    for (SortItem* i = first; i < last; ++i) ++slots[slotOf(i->alpha) + 1];
    for (std::size_t k = 0; k < s; ++k) slots[k + 1] += slots[k];
    scratch.resize(s);
    for (SortItem* i = first; i < last; ++i) scratch[slots[slotOf(i->alpha)]++] = *i;
    std::copy(scratch.begin(), scratch.end(), first);
    for (std::size_t k = 0, begin = 0; k < s; begin = slots[k], ++k) {
      // After the placement, slots[k] is where slot k ends.
      const std::size_t end = slots[k];
      if (end - begin > 32) {
        std::sort(first + begin, first + end, byAlpha);
      } else {
        insertionSort(first + begin, first + end);
      }
    }
  }
  if constexpr (!kAlphaOrderIsExact) {
    // Groups: cut before i where every later interval lies strictly above every earlier one.
    scratch.resize(s);  // reused for the suffix minima of the lower bounds
    double lowest = INFINITY;
    for (std::size_t i = s; i-- > 0;) {
      lowest = std::min(lowest, first[i].alpha - first[i].err);  // -inf for an infinite err
      scratch[i].alpha = lowest;
    }
    auto less = [&compare](const SortItem& x, const SortItem& y) {
      if (const int c = compare(x, y)) return c < 0;
      return x.other < y.other;
    };
    std::size_t begin = 0;
    double highest = first[0].alpha + first[0].err;
    for (std::size_t i = 1; i <= s; ++i) {
      if (i == s || scratch[i].alpha > highest) {
        if (i - begin > 1) std::sort(first + begin, first + i, less);
        begin = i;
        if (i < s) highest = first[i].alpha + first[i].err;
      } else {
        highest = std::max(highest, first[i].alpha + first[i].err);
      }
    }
  }
}

// Sorts every bucket of `items` (given by offsets) along its edge, in pieces over `threads`.
// compare(a, b, edge, piece) is the arithmetic's order along `edge` (the bucket).
template <bool kAlphaOrderIsExact, class Compare>
void sortBuckets(SortItem* items, const std::vector<std::uint32_t>& offsets, unsigned threads, Compare&& compare) {
  const std::size_t buckets = offsets.size() - 1;
  const Pieces pieces = piecesFor(buckets, threads, 256);
  runPieces(pieces, threads, [&](std::size_t p) {
    std::vector<SortItem> scratch;
    std::vector<std::uint32_t> slots;
    for (std::size_t b = pieces.begin(p); b < pieces.end(p); ++b) {
      sortAlongEdge<kAlphaOrderIsExact>(items + offsets[b], items + offsets[b + 1], scratch, slots,
                                        [&](const SortItem& x, const SortItem& y) {
                                          return compare(x, y, static_cast<std::uint32_t>(b), p);
                                        });
    }
  });
}

// Orders the crossings the pieces found (in piece order: the order one thread would have found
// them in) along the subject into r.subjectNodes and along the clip into r.clipNodes.
template <class Arithmetic, class Extra>
void orderAlongEdges(Phase1Result& r, const std::vector<CrossingBuffer<Extra>>& pieces, std::size_t pieceCount,
                     const Arithmetic& arithmetic, unsigned threads) {
  constexpr bool kHasExtra = !std::is_empty_v<Extra>;
  constexpr bool kExact = Arithmetic::kAlphaOrderIsExact;
  // The crossings found, in order (pieces one after the other), with their extras: f(index,
  // crossing, extra) for the indices in [begin, end).
  std::vector<std::size_t> pieceStart(pieceCount + 1, 0);
  for (std::size_t p = 0; p < pieceCount; ++p) pieceStart[p + 1] = pieceStart[p] + pieces[p].crossings.size();
  const std::size_t k = pieceStart[pieceCount];
  if (k >= (std::size_t{1} << 31)) throw std::length_error("ghclip: more than 2^31 crossings");
  const Extra none{};
  auto forEachFound = [&](std::size_t begin, std::size_t end, auto&& f) {
    std::size_t p = static_cast<std::size_t>(std::upper_bound(pieceStart.begin(), pieceStart.end(), begin) - pieceStart.begin()) - 1;
    for (std::size_t i = begin; i < end; ++p) {
      const CrossingBuffer<Extra>& b = pieces[p];
      for (std::size_t j = i - pieceStart[p]; j < b.crossings.size() && i < end; ++j, ++i) {
        if constexpr (kHasExtra) {
          f(static_cast<std::uint32_t>(i), b.crossings[j], b.extras[j]);
        } else {
          f(static_cast<std::uint32_t>(i), b.crossings[j], none);
        }
      }
    }
  };
  // Scatters the crossings into buckets by key(crossing) (stable: the found order within each
  // bucket), items[slot] = make(index, crossing, extra); offsets gets where each bucket starts. In
  // pieces over threads when there are many crossings per bucket: each piece counts its range,
  // then writes from where the pieces before it in that bucket end.
  // Kept by the calling thread; named through a reference, so that lambdas running on other
  // threads see this thread's vector, not their own.
  thread_local std::vector<std::uint32_t> bucketStarts;
  std::vector<std::uint32_t>& offsets = bucketStarts;
  auto scatter = [&](std::size_t buckets, SortItem* items, auto&& key, auto&& make) {
    const Pieces ranges = k > 4 * buckets ? piecesFor(k, threads, std::size_t{1} << 15) : Pieces{k, 1};
    std::vector<std::vector<std::uint32_t>> counts(ranges.pieces, std::vector<std::uint32_t>(buckets, 0));
    runPieces(ranges, threads, [&](std::size_t p) {
      forEachFound(ranges.begin(p), ranges.end(p), [&](std::uint32_t, const Crossing& c, const Extra&) { ++counts[p][key(c)]; });
    });
    offsets.assign(buckets + 1, 0);
    for (std::size_t b = 0; b < buckets; ++b) {
      std::uint32_t at = offsets[b];
      for (std::size_t p = 0; p < ranges.pieces; ++p) {
        const std::uint32_t n = counts[p][b];
        counts[p][b] = at;
        at += n;
      }
      offsets[b + 1] = at;
    }
    runPieces(ranges, threads, [&](std::size_t p) {
      std::vector<std::uint32_t>& at = counts[p];
      forEachFound(ranges.begin(p), ranges.end(p),
                   [&](std::uint32_t i, const Crossing& c, const Extra& e) { items[at[key(c)]++] = make(i, c, e); });
    });
  };
  // Per piece of the sorts: their own counters (the exact arithmetic's fallbacks), summed after.
  std::vector<ExactCounters> counters(4 * std::size_t{std::max(threads, 1u)} + 1);
  std::vector<Arithmetic> local;
  for (ExactCounters& c : counters) local.emplace_back(c);
  ScratchLayout layout;
  const auto itemsSlot = layout.add<SortItem>(k);
  const auto positionSlot = layout.add<std::uint32_t>(k);
  std::byte* base = scratch(layout.bytes());
  SortItem* items = itemsSlot(base);
  std::uint32_t* position = positionSlot(base);  // where each found crossing stands along the subject

  // Along the subject: crossings scattered into their edge's bucket (in the search's order: the
  // rows of all pairs come bucketed already), each bucket sorted, the nodes written in that order.
  scatter(
      r.subject.size(), items, [](const Crossing& c) { return c.subjectEdge; },
      [&](std::uint32_t i, const Crossing& c, const Extra& e) {
        return SortItem{c.alphaSubject, arithmetic.errorAlongSubject(e), c.point, c.clipEdge, i, arithmetic.atInputVertex(e)};
      });
  sortBuckets<kExact>(items, offsets, threads, [&](const SortItem& a, const SortItem& b, std::uint32_t edge, std::size_t p) {
    return local[p].compareAlongSubject(a, b, edge, r.subject, r.clip);
  });
  borrow<Spare::SubjectNodes>(r.subjectNodes);
  r.subjectNodes.resize(k);
  const Pieces subjectEdges = piecesFor(r.subject.size(), threads, 256);
  runPieces(subjectEdges, threads, [&](std::size_t p) {
    for (auto edge = static_cast<std::uint32_t>(subjectEdges.begin(p)); edge < subjectEdges.end(p); ++edge) {
      for (std::uint32_t i = offsets[edge]; i < offsets[edge + 1]; ++i) {
        r.subjectNodes[i] = Node(items[i].point, edge, 0);
        position[items[i].index] = i;
      }
    }
  });

  // Along the clip: the same, each node linked to its copy in the subject's list.
  scatter(
      r.clip.size(), items, [](const Crossing& c) { return c.clipEdge; },
      [&](std::uint32_t i, const Crossing& c, const Extra& e) {
        return SortItem{c.alphaClip, arithmetic.errorAlongClip(e), c.point, c.subjectEdge, position[i], arithmetic.atInputVertex(e)};
      });
  sortBuckets<kExact>(items, offsets, threads, [&](const SortItem& a, const SortItem& b, std::uint32_t edge, std::size_t p) {
    return local[p].compareAlongClip(a, b, edge, r.subject, r.clip);
  });
  borrow<Spare::ClipNodes>(r.clipNodes);
  r.clipNodes.resize(k);
  const Pieces clipEdges = piecesFor(r.clip.size(), threads, 256);
  runPieces(clipEdges, threads, [&](std::size_t p) {
    for (auto edge = static_cast<std::uint32_t>(clipEdges.begin(p)); edge < clipEdges.end(p); ++edge) {
      for (std::uint32_t j = offsets[edge]; j < offsets[edge + 1]; ++j) {
        const std::uint32_t i = items[j].index;
        r.clipNodes[j] = Node(items[j].point, edge, i);
        r.subjectNodes[i].setNeighbor(j);  // independent writes: their cache misses overlap
      }
    }
  });
  for (const ExactCounters& c : counters) arithmetic.counters() += c;
}

template <class Search, class Arithmetic>
Phase1Result findIntersections(Operand subject, Operand clip, const Search& search, const Arithmetic& arithmetic,
                               Stats& stats, Degeneracies* degeneracies = nullptr, unsigned threads = 1) {
  using Extra = typename Arithmetic::Extra;
  Phase1Result r{std::move(subject), std::move(clip), {}, {}};
  const auto plan = search.plan(r.subject, r.clip);
  // A piece is worth a thread from about 2^15 candidate pairs on.
  const Pieces pieces =
      piecesFor(plan.units, threads, std::max<std::size_t>(1, (std::size_t{1} << 15) / std::max<std::size_t>(plan.pairsPerUnit, 1)));
  auto& buffers = crossingBuffers<Extra>(pieces.pieces);
  // The clip's edges as arrays for the vectorized rows (row_kernels.h), when rows are tested.
  const EdgeArrays clipArrays = plan.rows && rowKernelsAvailable() ? EdgeArrays(r.clip) : EdgeArrays();
  const EdgeArrays* arrays = clipArrays.size() ? &clipArrays : nullptr;
  runPieces(pieces, threads, [&](std::size_t p) {
    CrossingBuffer<Extra>& buffer = buffers[p];
    const Arithmetic local(buffer.counters);
    plan.visit(
        pieces.begin(p), pieces.end(p),
        [&](std::uint32_t se) { local.testRow(r.subject, se, r.clip, arrays, buffer); },
        [&](std::uint32_t se, std::uint32_t ce) { local.testPair(r.subject, se, r.clip, ce, buffer); });
  });

  Degeneracies found;
  std::size_t total = 0;
  for (std::size_t p = 0; p < pieces.pieces; ++p) {
    CrossingBuffer<Extra>& b = buffers[p];
    stats.candidatePairs += b.pairs;
    arithmetic.counters() += b.counters;
    total += b.crossings.size();
    if constexpr (Arithmetic::kReportsDegeneracies) {
      found.subject.insert(found.subject.end(), b.degenerateSubject.begin(), b.degenerateSubject.end());
      found.clip.insert(found.clip.end(), b.degenerateClip.begin(), b.degenerateClip.end());
    }
  }
  if constexpr (Arithmetic::kReportsDegeneracies) {
    if (!found.empty()) {
      for (auto* vs : {&found.subject, &found.clip}) {
        std::sort(vs->begin(), vs->end());
        vs->erase(std::unique(vs->begin(), vs->end()), vs->end());
      }
      if (degeneracies) *degeneracies = std::move(found);
      return r;  // unordered: the caller must resolve the degeneracies first
    }
  }
  stats.intersections = total;
  orderAlongEdges(r, buffers, pieces.pieces, arithmetic, threads);
  for (std::size_t p = 0; p < pieces.pieces; ++p) buffers[p].trim();
  return r;
}

}  // namespace gh::detail
