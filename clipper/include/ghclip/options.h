// How gh::clip works: two independent axes, and the names of their usual combinations.
//
//   arithmetic  how phase 1 decides crossings and their order, and phase 2 its starting status
//     Exact     exact predicates with Simulation of Simplicity: no input vertex ever moves, every
//               crossing point is the exact one rounded faithfully; S n S = S exactly (default)
//     Paper     the paper's doubles, alpha values and perturbation of degenerate vertices: the
//               algorithm as published, fragile on shared edges and extreme magnitudes
//   search      which edge pairs phase 1 tests
//     Auto      the paper arithmetic: all pairs, as in the paper; the exact arithmetic: the sweep
//               when edges are short against the input's extent, all pairs when nearly every pair
//               of edge boxes overlaps anyway (default)
//     AllPairs  every subject edge against every clip edge, n * m
//     Sweep     x-monotone chains swept by their boxes: O((n + m) log(n + m) + pairs)
//
// The named combinations, used by the command-line tools and in every report:
//   naive = Paper + AllPairs (the paper as written), sweep = Paper + Sweep, exact = Exact + Auto,
//   exact-allpairs, exact-sweep = Exact with the search forced.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace gh {

enum class Arithmetic {
  Exact,  // exact predicates + Simulation of Simplicity (default)
  Paper,  // doubles + the paper's perturbation
};

enum class Search {
  Auto,      // all pairs for Paper, the cheaper one for Exact (default)
  AllPairs,  // n * m pairs
  Sweep,     // bounding-box sweep over monotone chains
};

struct Options {
  Arithmetic arithmetic = Arithmetic::Exact;
  Search search = Search::Auto;
  // Drop rings with fewer than 3 distinct vertices instead of throwing InvalidInput.
  bool sanitize = false;
  // Threads for the parallel parts of a clip (phase 1's search and ordering, phase 2's ring
  // starts), 0 for every core. Answers do not depend on it: bit for bit the same as one thread.
  unsigned threads = 1;
};

// What threads = 0 means here: the hardware's threads (at least 1).
unsigned availableThreads();

// The usual combinations by name.
enum class Variant {
  Naive,  // Paper + AllPairs: the paper as published
  Sweep,  // Paper + Sweep: the same decisions, a sub-quadratic search
  Exact,  // Exact + Auto
};
inline constexpr Variant kAllVariants[] = {Variant::Naive, Variant::Sweep, Variant::Exact};

Options optionsOf(Variant variant);
std::string_view name(Variant variant);
std::optional<Variant> parseVariant(std::string_view text);

std::string_view name(Arithmetic arithmetic);  // "exact", "paper"
std::string_view name(Search search);          // "auto", "all-pairs", "sweep"
std::optional<Arithmetic> parseArithmetic(std::string_view text);
std::optional<Search> parseSearch(std::string_view text);

// The report name of a combination: "naive", "sweep", "exact", "exact-allpairs", "exact-sweep"
// (Paper + Auto is naive); parseOptions reads each of them back.
std::string name(const Options& options);
std::optional<Options> parseOptions(std::string_view text);

}  // namespace gh
