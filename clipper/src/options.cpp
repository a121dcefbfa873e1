#include "ghclip/options.h"

#include <algorithm>
#include <thread>

namespace gh {

unsigned availableThreads() { return std::max(1u, std::thread::hardware_concurrency()); }

Options optionsOf(Variant variant) {
  Options o;
  switch (variant) {
    case Variant::Naive: o.arithmetic = Arithmetic::Paper, o.search = Search::AllPairs; break;
    case Variant::Sweep: o.arithmetic = Arithmetic::Paper, o.search = Search::Sweep; break;
    case Variant::Exact: o.arithmetic = Arithmetic::Exact, o.search = Search::Auto; break;
  }
  return o;
}

std::string_view name(Variant variant) {
  switch (variant) {
    case Variant::Naive: return "naive";
    case Variant::Sweep: return "sweep";
    case Variant::Exact: return "exact";
  }
  return "?";
}

std::optional<Variant> parseVariant(std::string_view text) {
  for (Variant v : kAllVariants) {
    if (name(v) == text) return v;
  }
  return std::nullopt;
}

std::string_view name(Arithmetic arithmetic) { return arithmetic == Arithmetic::Exact ? "exact" : "paper"; }

std::string_view name(Search search) {
  switch (search) {
    case Search::Auto: return "auto";
    case Search::AllPairs: return "all-pairs";
    case Search::Sweep: return "sweep";
  }
  return "?";
}

std::optional<Arithmetic> parseArithmetic(std::string_view text) {
  for (Arithmetic a : {Arithmetic::Exact, Arithmetic::Paper}) {
    if (name(a) == text) return a;
  }
  return std::nullopt;
}

std::optional<Search> parseSearch(std::string_view text) {
  for (Search s : {Search::Auto, Search::AllPairs, Search::Sweep}) {
    if (name(s) == text) return s;
  }
  return std::nullopt;
}

std::string name(const Options& o) {
  if (o.arithmetic == Arithmetic::Paper) return o.search == Search::Sweep ? "sweep" : "naive";
  switch (o.search) {
    case Search::Auto: return "exact";
    case Search::AllPairs: return "exact-allpairs";
    case Search::Sweep: return "exact-sweep";
  }
  return "?";
}

std::optional<Options> parseOptions(std::string_view text) {
  if (const auto v = parseVariant(text)) return optionsOf(*v);
  for (Arithmetic a : {Arithmetic::Exact, Arithmetic::Paper}) {
    for (Search s : {Search::Auto, Search::AllPairs, Search::Sweep}) {
      Options o;
      o.arithmetic = a, o.search = s;
      if (name(o) == text) return o;
    }
  }
  return std::nullopt;
}

}  // namespace gh
