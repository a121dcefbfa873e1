// The findings a fuzz campaign recorded (fuzz/findings.h: one TSV line per finding), grouped by
// cause: what was found and what kind of degeneracy the operands hold, one row each, with the
// counts per operation and per kind of coordinates. Prints a markdown table for the report.
//   fuzz_findings FINDINGS.tsv...
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <set>
#include <sstream>
#include <tuple>
#include <unordered_map>

#include "ghclip/operation.h"
#include "ghclip/region.h"
#include "ghio/formats.h"
#include "ghoracle/exact_orientation.h"
#include "tool_main.h"

using namespace gh;

namespace {

struct Edge {
  Point a, b;
  std::size_t ring, index;
};

// The judges' exact orientation (a filter in doubles first): rationals for every test took 10
// minutes over the 930,694 findings of one hour-long campaign.
using oracle::orientation;

// p on the closed segment ab, given that the three are collinear.
bool within(Point a, Point b, Point p) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
}

// The strongest degeneracy between two edges of S and C (of different rings, or of one ring but
// not adjacent), decided exactly: overlapping collinear edges, a vertex inside another edge, a
// shared vertex; else a vertex within 2^-40 of the extent from another edge (near-degenerate);
// else general position.
std::string degeneracy(const Region& s, const Region& c) {
  std::vector<Edge> edges;
  double extent = 0;
  std::size_t ringId = 0;
  for (const Region* r : {&s, &c}) {
    for (const Ring& ring : *r) {
      for (std::size_t i = 0; i < ring.size(); ++i) {
        // The targets refuse non-finite input before they judge; a line written otherwise is
        // named, not tested (the orientation takes finite coordinates only).
        if (!std::isfinite(ring[i].x) || !std::isfinite(ring[i].y)) return "non-finite coordinates";
        edges.push_back({ring[i], ring[(i + 1) % ring.size()], ringId, i});
        extent = std::max({extent, std::abs(ring[i].x), std::abs(ring[i].y)});
      }
      ++ringId;
    }
  }
  int strongest = 0;  // 0 general, 1 near, 2 shared vertex, 3 vertex on edge, 4 overlap
  for (std::size_t i = 0; i < edges.size(); ++i) {
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      const Edge& e = edges[i];
      const Edge& f = edges[j];
      if (e.ring == f.ring && (e.b == f.a || f.b == e.a)) continue;  // adjacent on a ring
      if (e.a == e.b || f.a == f.b) continue;
      const int fa = orientation(e.a, e.b, f.a), fb = orientation(e.a, e.b, f.b);
      if (fa == 0 && fb == 0) {
        if (within(e.a, e.b, f.a) || within(e.a, e.b, f.b) || within(f.a, f.b, e.a)) {
          const bool touchOnly = (f.a == e.a || f.a == e.b || f.b == e.a || f.b == e.b) &&
                                 !(within(e.a, e.b, f.a) && f.a != e.a && f.a != e.b) &&
                                 !(within(e.a, e.b, f.b) && f.b != e.a && f.b != e.b) &&
                                 !(within(f.a, f.b, e.a) && e.a != f.a && e.a != f.b) &&
                                 !(within(f.a, f.b, e.b) && e.b != f.a && e.b != f.b);
          strongest = std::max(strongest, touchOnly ? 2 : 4);
          continue;
        }
      }
      for (const auto& [p, o, q] : {std::tuple{f.a, fa, &e}, std::tuple{f.b, fb, &e}}) {
        if (o == 0 && within(q->a, q->b, p)) strongest = std::max(strongest, p == q->a || p == q->b ? 2 : 3);
      }
      const int ea = orientation(f.a, f.b, e.a), eb = orientation(f.a, f.b, e.b);
      for (const auto& [p, o] : {std::pair{e.a, ea}, std::pair{e.b, eb}}) {
        if (o == 0 && within(f.a, f.b, p)) strongest = std::max(strongest, p == f.a || p == f.b ? 2 : 3);
      }
      if (strongest < 1) {  // near: a vertex close to the other edge's line, inside its box
        for (const auto& [p, q] : {std::pair{f.a, &e}, std::pair{f.b, &e}, std::pair{e.a, &f}, std::pair{e.b, &f}}) {
          const double dx = q->b.x - q->a.x, dy = q->b.y - q->a.y, length = std::hypot(dx, dy);
          const double distance = std::abs(dx * (p.y - q->a.y) - dy * (p.x - q->a.x)) / length;
          if (length > 0 && distance <= std::ldexp(extent, -40) && within(q->a, q->b, p)) strongest = 1;
        }
      }
    }
  }
  static const char* kNames[] = {"general position", "near-degenerate (a vertex within 2^-40 of an edge)",
                                 "shared vertex", "vertex inside another edge", "overlapping collinear edges"};
  return kNames[strongest];
}

std::string coordinates(const Region& s, const Region& c) {
  bool grid = true, extreme = false;
  for (const Region* r : {&s, &c}) {
    for (const Ring& ring : *r) {
      for (const Point& p : ring) {
        for (double v : {p.x, p.y}) {
          grid &= v == std::floor(v) && std::abs(v) <= 1e6;
          extreme |= (v != 0 && std::abs(v) < 1e-300) || std::abs(v) > 1e15;
        }
      }
    }
  }
  return grid ? "integers" : extreme ? "subnormal or huge" : "off the grid";
}

// The finding without its numbers or ring numbers: "sampling oracle disagrees", "invariant: an
// area bound" (union smaller than an operand, ...), "invariant: a ring has a zero-length edge".
std::string cause(std::string what) {
  if (const auto paren = what.find(" ("); paren != std::string::npos) what.erase(paren);
  if (what.rfind("invariant: ", 0) == 0) {
    const auto ring = what.find("ring ");
    if (ring == std::string::npos) return "invariant: an area bound";
    const auto rest = what.find(' ', ring + 5);
    return "invariant: a ring" + (rest == std::string::npos ? std::string() : what.substr(rest));
  }
  return what;
}

}  // namespace

int run(int argc, char** argv) {
  CLI::App app{"Groups a fuzz campaign's recorded findings by cause, as a markdown table."};
  std::vector<std::string> files;
  app.add_option("FINDINGS", files, "findings TSV files (fuzz/findings.h)")->required();
  if (const auto exitCode = tools::parseCommandLine(app, "fuzz_findings", argc, argv)) return *exitCode;
  // One row per target, cause and degeneracy; the operations and the kinds of coordinates are
  // columns (the table a campaign against the naive variant wrote before had 70 rows).
  using Key = std::tuple<std::string, std::string, std::string>;
  struct Row {
    std::map<std::string, std::size_t> byOperation, byCoordinates;
    std::size_t findings = 0;
    std::set<std::string> inputs;
  };
  std::map<Key, Row> rows;
  std::unordered_map<std::string, std::pair<std::string, std::string>> kinds;  // operands -> degeneracy, coordinates
  for (const std::string& file : files) {
    std::ifstream in(file);
    if (!in) throw tools::BadInput(file + ": cannot read");
    std::string line;
    while (std::getline(in, line)) {
      std::vector<std::string> f;
      std::istringstream fields(line);
      for (std::string x; std::getline(fields, x, '\t');) f.push_back(x);
      if (f.size() != 6) throw tools::BadInput(file + ": not a findings line (6 tab-separated fields)");
      // One input's operands come with each operation it failed: classified once (the exact
      // degeneracy test is quadratic in the edges, and a campaign records 10^5 findings).
      auto [kind, fresh] = kinds.try_emplace(f[3] + '\t' + f[4]);
      if (fresh) {
        const Region s = io::readWkt(f[3]), c = io::readWkt(f[4]);
        kind->second = {degeneracy(s, c), coordinates(s, c)};
      }
      Row& row = rows[Key{f[0], cause(f[1]), kind->second.first}];
      ++row.byOperation[f[2]], ++row.byCoordinates[kind->second.second], ++row.findings;
      row.inputs.insert(f[5]);
    }
  }
  const char* kCoordinates[] = {"integers", "off the grid", "subnormal or huge"};
  std::cout << "| target | finding | degeneracy of the operands |";
  for (Op op : kAllOps) std::cout << " " << name(op) << " |";
  std::cout << " integers / off the grid / subnormal or huge | findings | distinct inputs |\n|---|---|---|";
  for (std::size_t i = 0; i < std::size(kAllOps) + 3; ++i) std::cout << "---:|";
  std::cout << "\n";
  for (const auto& [key, row] : rows) {
    const auto& [target, what, degenerate] = key;
    auto count = [](const std::map<std::string, std::size_t>& m, const std::string& k) {
      const auto it = m.find(k);
      return it == m.end() ? std::size_t{0} : it->second;
    };
    std::cout << "| " << target << " | " << what << " | " << degenerate << " |";
    for (Op op : kAllOps) std::cout << " " << count(row.byOperation, std::string(name(op))) << " |";
    std::cout << " " << count(row.byCoordinates, kCoordinates[0]) << " / " << count(row.byCoordinates, kCoordinates[1])
              << " / " << count(row.byCoordinates, kCoordinates[2]) << " | " << row.findings << " | " << row.inputs.size()
              << " |\n";
  }
  return 0;
}

int main(int argc, char** argv) { return tools::guardedMain("fuzz_findings", argc, argv, run); }
