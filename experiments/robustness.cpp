// The robustness study: every variant and every peer, input class by input class, every
// operation, each answer judged by the exact oracle. Every case runs in a worker process
// (common/isolated_run.h), so a crash or a hang of any method is counted, not fatal.
// Writes OUT_DIR/robustness.md, OUT_DIR/robustness.svg (heat map, via gnuplot),
// OUT_DIR/robustness.json (every count) and, for every failing cell, its smallest failing case in
// OUT_DIR/counterexamples/<method>/robustness-<class>-<op>.{wkt,svg}.
//   robustness OUT_DIR [--cases N] [--full] [--timeout SECONDS]
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include "common/isolated_run.h"
#include "common/judge.h"
#include "common/provenance.h"
#include "common/shard.h"
#include "ghclip/errors.h"
#include "ghclip/measure.h"
#include "ghclip/ogc_layout.h"
#include "ghio/formats.h"
#include "ghio/svg.h"
#include "ghoracle/exact_oracle.h"
#include "ghwork/generators.h"
#include "tool_main.h"

namespace fs = std::filesystem;
using namespace gh;
using namespace gh::experiments;

namespace {

struct InputClass {
  std::string name;      // also the workload given to work::generate
  std::size_t minN, maxN;
  bool valid;            // valid polygons with holes, so GEOS, Boost.Geometry and CGAL run too
  std::string description;
};

const InputClass kClasses[] = {
    {"random", 4, 20, false, "the paper's random n-gons in the unit square (self-intersecting)"},
    {"simple", 5, 30, true, "random simple polygons (star-shaped or 2-opt)"},
    {"holes", 20, 60, true, "a square shell with 2-5 star holes against another"},
    {"circles", 32, 96, true, "two perturbed circles crossing twice"},
    {"grid", 3, 12, false, "random n-gons on the integer grid 0..8: vertices on edges, overlapping edges"},
    {"identical", 3, 10, true, "the same grid polygon twice"},
    {"shared-edge", 4, 4, true, "two rectangles whose edges partly overlap"},
    {"touching-vertex", 4, 4, true, "a rectangle and a triangle meeting at one corner"},
    {"nested-touching", 4, 4, true, "C inside S, sharing part of an edge and touching at a vertex"},
    {"sliver", 4, 4, true, "rectangles overlapping in a strip of width 2^-20"},
    {"sub-boundary", 3, 8, true, "C's vertices are every other vertex of S"},
    {"bitset-grid", 18, 50, true, "unions of unit cells of two random bitsets (edges shared everywhere)"},
    {"grid+ulp", 3, 12, false, "the grid class with every coordinate moved by one ulp: near-degenerate"},
    {"identical+ulp", 3, 10, true, "two copies of a polygon, each coordinate moved by one ulp independently"},
    {"simple+tiny", 5, 30, true, "the simple class scaled by 2^-997 (coordinates near 1e-300)"},
    {"grid+tiny", 3, 12, false, "the grid class scaled by 2^-997"},
    {"simple+huge", 5, 30, true, "the simple class scaled to coordinates near 2^497 (1e150)"},
    {"grid+huge", 3, 12, false, "the grid class scaled to coordinates near 2^497"},
    {"simple+far", 5, 30, true, "the simple class moved by (1e9, 1e9)"},
    {"grid+far", 3, 12, false, "the grid class moved by (1e9, 1e9)"},
    {"mixed-magnitude", 5, 30, true,
     "a triangle of size 2^10..2^480 with an edge through the origin, holding a star hole of size "
     "2^-300..1 above it, against a star of the hole's size crossing both"},
};

enum class Verdict { Exact, Rounding, Beyond, Gross, Refused, Threw, Crashed, TimedOut, Unjudged };
constexpr Verdict kVerdicts[] = {Verdict::Exact,   Verdict::Rounding, Verdict::Beyond,   Verdict::Gross,
                                 Verdict::Refused, Verdict::Threw,    Verdict::Crashed,  Verdict::TimedOut,
                                 Verdict::Unjudged};
const char* key(Verdict v) {
  switch (v) {
    case Verdict::Exact: return "exact";
    case Verdict::Rounding: return "rounding";
    case Verdict::Beyond: return "beyond-rounding";
    case Verdict::Gross: return "gross";
    case Verdict::Refused: return "refused";
    case Verdict::Threw: return "threw";
    case Verdict::Crashed: return "crashed";
    case Verdict::TimedOut: return "timed-out";
    case Verdict::Unjudged: return "cannot-judge";
  }
  return "?";
}
// One letter per failure kind in the tables.
const char* letter(Verdict v) {
  switch (v) {
    case Verdict::Beyond: return "b";
    case Verdict::Gross: return "g";
    case Verdict::Refused: return "r";
    case Verdict::Threw: return "t";
    case Verdict::Crashed: return "c";
    case Verdict::TimedOut: return "h";
    case Verdict::Unjudged: return "u";
    default: return "";
  }
}
bool failing(Verdict v) {
  return v != Verdict::Exact && v != Verdict::Rounding && v != Verdict::Refused && v != Verdict::Unjudged;
}

struct Case {
  Region subject, clip, result;
  int seed = 0;
  std::size_t size = 0;
  double relative = 0;
  std::string message;
  Verdict verdict = Verdict::Exact;
};

struct Cell {
  std::map<Verdict, int> counts;
  int total = 0;
  double worstRelative = 0;  // over answers judged beyond rounding or gross
  bool hasFailure = false;
  Case smallest;  // the smallest failing case (then the larger error)
  int correct() const {
    auto get = [&](Verdict v) { auto it = counts.find(v); return it == counts.end() ? 0 : it->second; };
    return get(Verdict::Exact) + get(Verdict::Rounding);
  }
  int count(Verdict v) const { auto it = counts.find(v); return it == counts.end() ? 0 : it->second; }
};

std::string fmt(double v, int precision = 2) {
  std::ostringstream s;
  s << std::setprecision(precision) << v;
  return s.str();
}

std::string percent(int part, int whole) {
  if (whole == 0) return "–";
  if (part == whole) return "100%";
  std::ostringstream s;
  s << std::fixed << std::setprecision(1) << 100.0 * part / whole << "%";
  return s.str();
}

Verdict verdictOf(Outcome outcome) {
  switch (outcome) {
    case Outcome::Exact: return Verdict::Exact;
    case Outcome::Rounding: return Verdict::Rounding;
    case Outcome::BeyondRounding: return Verdict::Beyond;
    default: return Verdict::Gross;
  }
}

Verdict judgeAnswer(const Region& s, const Region& c, Op op, const Region& r, double& relative, std::string& message) {
  try {
    return verdictOf(experiments::judgeAnswer(s, c, op, r, relative));
  } catch (const oracle::CannotJudge& e) {
    message = std::string("cannot judge: ") + e.what();
    return Verdict::Unjudged;
  } catch (const std::exception& e) {
    // An answer the oracle cannot even read (non-finite coordinates) is as wrong as it gets.
    relative = std::numeric_limits<double>::infinity();
    message = std::string("unreadable answer: ") + e.what();
    return Verdict::Gross;
  }
}

std::string cellText(const Cell& cell) {
  if (cell.total == 0) return "n/a";
  std::string text = percent(cell.correct(), cell.total);
  std::string marks;
  for (Verdict v : kVerdicts) {
    if (const int k = cell.count(v); k > 0 && *letter(v)) marks += " " + std::string(letter(v)) + std::to_string(k);
  }
  if (!marks.empty()) text += marks;
  if (cell.worstRelative > 0) text += " · " + fmt(cell.worstRelative);
  return text;
}

using Cells = std::map<Op, std::map<std::string, std::map<std::string, Cell>>>;  // [op][class][method]

// Regions exactly as they are (every vertex, every double: nlohmann-json round-trips them).
nlohmann::json regionJson(const Region& region) {
  nlohmann::json rings = nlohmann::json::array();
  for (const Ring& ring : region) {
    nlohmann::json points = nlohmann::json::array();
    for (const Point& p : ring) points.push_back({p.x, p.y});
    rings.push_back(std::move(points));
  }
  return rings;
}
Region regionOf(const nlohmann::json& rings) {
  Region region;
  for (const nlohmann::json& ring : rings) {
    Ring r;
    for (const nlohmann::json& p : ring) r.push_back({p.at(0).get<double>(), p.at(1).get<double>()});
    region.push_back(std::move(r));
  }
  return region;
}

// Shards: the raw cells of a part of the seeds, with each cell's smallest failing case whole.
nlohmann::json shardJson(const Cells& cells, int cases, double seconds, int shard, int shards) {
  nlohmann::json j;
  j["shard"] = shard;
  j["shards"] = shards;
  j["cases_per_class"] = cases;
  j["seconds"] = seconds;
  j["cells"] = nlohmann::json::array();
  for (const auto& [op, byClass] : cells) {
    for (const auto& [cls, byMethod] : byClass) {
      for (const auto& [method, cell] : byMethod) {
        nlohmann::json c{{"op", std::string(name(op))}, {"class", cls}, {"method", method}, {"total", cell.total},
                         {"worst_relative", cell.worstRelative}, {"counts", nlohmann::json::object()}};
        for (const auto& [v, n] : cell.counts) c["counts"][key(v)] = n;
        if (cell.hasFailure) {
          const Case& f = cell.smallest;
          c["smallest"] = {{"seed", f.seed},          {"size", f.size},
                           {"relative", f.relative},  {"message", f.message},
                           {"verdict", key(f.verdict)}, {"subject", regionJson(f.subject)},
                           {"clip", regionJson(f.clip)}, {"result", regionJson(f.result)}};
        }
        j["cells"].push_back(std::move(c));
      }
    }
  }
  return j;
}

struct ShardFile {
  int shard = 1, shards = 1;
  int cases = 0;
  double seconds = 0;
  Cells cells;
};

ShardFile readShard(const std::string& file, const std::vector<Method>& methods) {
  ShardFile s;
  try {
    const nlohmann::json j = nlohmann::json::parse(io::readText(file));
    s.shard = j.at("shard").get<int>(), s.shards = j.at("shards").get<int>();
    s.cases = j.at("cases_per_class").get<int>();
    s.seconds = j.at("seconds").get<double>();
    auto verdictOf = [&](const std::string& text) {
      for (Verdict v : kVerdicts) {
        if (text == key(v)) return v;
      }
      throw tools::BadInput(file + ": unknown verdict '" + text + "'");
    };
    for (const nlohmann::json& c : j.at("cells")) {
      const auto op = parseOp(c.at("op").get<std::string>());
      const std::string method = c.at("method").get<std::string>();
      if (!op || std::none_of(methods.begin(), methods.end(), [&](const Method& m) { return m.name == method; })) {
        throw tools::BadInput(file + ": unknown operation or method");
      }
      Cell& cell = s.cells[*op][c.at("class").get<std::string>()][method];
      cell.total = c.at("total").get<int>();
      cell.worstRelative = c.at("worst_relative").get<double>();
      for (const auto& [v, n] : c.at("counts").items()) cell.counts[verdictOf(v)] = n.get<int>();
      if (c.contains("smallest")) {
        const nlohmann::json& f = c["smallest"];
        Case& k = cell.smallest;
        k.seed = f.at("seed").get<int>(), k.size = f.at("size").get<std::size_t>();
        k.relative = f.at("relative").get<double>(), k.message = f.at("message").get<std::string>();
        k.verdict = verdictOf(f.at("verdict").get<std::string>());
        k.subject = regionOf(f.at("subject")), k.clip = regionOf(f.at("clip")), k.result = regionOf(f.at("result"));
        cell.hasFailure = true;
      }
    }
  } catch (const nlohmann::json::exception& e) {
    throw tools::BadInput(file + ": not a robustness shard (" + e.what() + ")");
  } catch (const gh::InvalidInput& e) {
    throw tools::BadInput(file + ": " + e.what());
  }
  return s;
}

// The smallest failing case of a cell as one run picks it: the smallest input, then the larger
// error, then the earlier seed.
bool smallerFailure(const Case& a, const Case& b) {
  if (a.size != b.size) return a.size < b.size;
  if (a.relative != b.relative) return a.relative > b.relative;
  return a.seed < b.seed;
}

void mergeInto(Cells& into, const Cells& from) {
  for (const auto& [op, byClass] : from) {
    for (const auto& [cls, byMethod] : byClass) {
      for (const auto& [method, cell] : byMethod) {
        Cell& c = into[op][cls][method];
        c.total += cell.total;
        for (const auto& [v, n] : cell.counts) c.counts[v] += n;
        c.worstRelative = std::max(c.worstRelative, cell.worstRelative);
        if (cell.hasFailure && (!c.hasFailure || smallerFailure(cell.smallest, c.smallest))) {
          c.smallest = cell.smallest;
          c.hasFailure = true;
        }
      }
    }
  }
}

}  // namespace

int run(int argc, char** argv) {
  CLI::App app{"The robustness study: every method x input class x operation, judged by the exact oracle."};
  std::string outDir;
  int cases = 0;
  bool full = false;
  double timeout = 20;
  app.add_option("OUT_DIR", outDir, "directory for robustness.md/.svg/.json and counterexamples/")->required();
  app.add_option("--cases", cases, "cases per class (default 25, 200 with --full)")->check(CLI::PositiveNumber);
  app.add_flag("--full", full, "the large study");
  app.add_option("--timeout", timeout, "seconds before a case is killed")->check(CLI::PositiveNumber);
  std::string shardText;
  std::vector<std::string> mergeFiles;
  app.add_option("--shard", shardText,
                 "K/M: run only seeds s with (s - 1) mod M = K - 1 and write OUT_DIR/robustness-shard-K-of-M.json "
                 "instead of the report (run every K = 1..M, on any machines, then --merge)");
  app.add_option("--merge", mergeFiles, "shard JSON files: write the report of all of them together")
      ->excludes("--shard");
  std::vector<std::string> methodNames;
  app.add_option("--methods", methodNames, "only these methods, comma-separated (default: every variant and peer)")
      ->delimiter(',');
  if (const auto exitCode = tools::parseCommandLine(app, "robustness", argc, argv)) return *exitCode;
  if (cases == 0) cases = full ? 200 : 25;
  int shard = 1, shards = 1;
  if (!shardText.empty()) {
    const auto parsed = experiments::parseShard(shardText);
    if (!parsed) return tools::usageError("robustness", "--shard wants K/M with 1 <= K <= M, got '" + shardText + "'");
    shard = parsed->k, shards = parsed->m;
  }
  const fs::path out = outDir;
  std::vector<Method> methods = allMethods();
  if (!methodNames.empty()) {
    for (const std::string& wanted : methodNames) {
      if (std::none_of(methods.begin(), methods.end(), [&](const Method& m) { return m.name == wanted; })) {
        return tools::usageError("robustness", "--methods: unknown method '" + wanted + "'");
      }
    }
    methods.erase(std::remove_if(methods.begin(), methods.end(), [&](const Method& m) {
                    return std::find(methodNames.begin(), methodNames.end(), m.name) == methodNames.end();
                  }), methods.end());
  }
  IsolationLimits limits;
  limits.seconds = timeout;
  IsolatedRunner runner(methods, limits);

  Cells cells;
  const auto start = std::chrono::steady_clock::now();
  double seconds = 0;
  if (!mergeFiles.empty()) {
    cases = 0;
    std::set<int> seen;
    int of = 0;
    for (const std::string& file : mergeFiles) {
      const ShardFile s = readShard(file, methods);
      if (cases != 0 && (s.cases != cases || s.shards != of)) {
        throw tools::BadInput(file + ": a shard of another study (" + std::to_string(s.cases) + " cases in " +
                              std::to_string(s.shards) + " shards, not " + std::to_string(cases) + " in " + std::to_string(of) + ")");
      }
      if (!seen.insert(s.shard).second) throw tools::BadInput(file + ": shard " + std::to_string(s.shard) + " given twice");
      cases = s.cases, of = s.shards;
      seconds += s.seconds;
      mergeInto(cells, s.cells);
    }
    if (static_cast<int>(seen.size()) != of) {
      throw tools::BadInput("--merge: " + std::to_string(seen.size()) + " of " + std::to_string(of) + " shards given");
    }
  }
  for (const InputClass& k : kClasses) {
    if (!mergeFiles.empty()) break;
    for (int i = 1; i <= cases; ++i) {
      if ((i - 1) % shards != shard - 1) continue;
      const std::size_t n = k.minN + static_cast<std::size_t>(i) % (k.maxN - k.minN + 1);
      const work::Workload w = work::generate(k.name, n, static_cast<std::uint64_t>(i));
      const std::size_t size = vertexCount(w.subject) + vertexCount(w.clip);
      for (std::size_t mi = 0; mi < methods.size(); ++mi) {
        const Method& m = methods[mi];
        if (m.validInputOnly && !k.valid) continue;
        // The method's five answers first, then judged together in one arrangement (the same
        // verdicts as one by one; an answer the oracle cannot read or judge is judged alone).
        std::vector<IsolatedRun> runs;
        std::vector<oracle::Answer> answers;
        for (Op op : kAllOps) {
          runs.push_back(runner.run(mi, w.subject, w.clip, op));
          if (runs.back().status == IsolatedRun::Status::Answered) answers.push_back({op, runs.back().result});
        }
        std::vector<oracle::ExactVerdict> together;
        try {
          together = oracle::exactCheckAll(w.subject, w.clip, answers, {false, false, true});
        } catch (const std::exception&) {
          together.clear();
        }
        std::size_t answered = 0;
        for (std::size_t oi = 0; oi < std::size(kAllOps); ++oi) {
          const Op op = kAllOps[oi];
          const IsolatedRun& r = runs[oi];
          Cell& cell = cells[op][k.name][m.name];
          Case c;
          c.seed = i;
          c.size = size;
          switch (r.status) {
            case IsolatedRun::Status::Answered:
              if (!together.empty()) {
                c.verdict = verdictOf(experiments::outcomeOf(together[answered], c.relative));
              } else {
                c.verdict = judgeAnswer(w.subject, w.clip, op, r.result, c.relative, c.message);
              }
              ++answered;
              break;
            case IsolatedRun::Status::Refused: c.verdict = Verdict::Refused; break;
            case IsolatedRun::Status::Threw: c.verdict = Verdict::Threw; break;
            case IsolatedRun::Status::Crashed: c.verdict = Verdict::Crashed; break;
            case IsolatedRun::Status::TimedOut: c.verdict = Verdict::TimedOut; break;
          }
          if (c.message.empty()) c.message = r.message;
          ++cell.total;
          ++cell.counts[c.verdict];
          if (c.verdict == Verdict::Beyond || c.verdict == Verdict::Gross) {
            cell.worstRelative = std::max(cell.worstRelative, c.relative);
          }
          if (failing(c.verdict) &&
              (!cell.hasFailure || size < cell.smallest.size ||
               (size == cell.smallest.size && c.relative > cell.smallest.relative))) {
            c.subject = w.subject, c.clip = w.clip, c.result = r.result;
            cell.smallest = std::move(c);
            cell.hasFailure = true;
          }
        }
      }
    }
    std::cerr << "[robustness] " << k.name << " done ("
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s)\n";
  }
  if (mergeFiles.empty()) seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!shardText.empty()) {
    fs::create_directories(out);
    const fs::path file = out / ("robustness-shard-" + std::to_string(shard) + "-of-" + std::to_string(shards) + ".json");
    io::writeText(file.string(), shardJson(cells, cases, seconds, shard, shards).dump(1));
    std::cout << "wrote " << file.string() << "\n";
    return 0;
  }

  fs::create_directories(out);
  // Counterexamples: the smallest failing case of every failing cell, with the wrong faces.
  std::map<std::string, std::map<std::string, std::vector<std::string>>> failingCells;  // method -> verdict kind
  for (Op op : kAllOps) {
    for (const InputClass& k : kClasses) {
      for (const Method& m : methods) {
        const auto it = cells[op][k.name].find(m.name);
        if (it == cells[op][k.name].end() || !it->second.hasFailure) continue;
        const Case& f = it->second.smallest;
        const std::string id = "robustness-" + k.name + "-" + std::string(name(op));
        const fs::path dir = out / "counterexamples" / m.name;
        fs::create_directories(dir);
        std::ostringstream wkt;
        wkt << "# " << k.name << " seed " << f.seed << ", " << name(op) << " by " << m.name << ": " << key(f.verdict);
        if (!f.message.empty()) wkt << " (" << f.message << ")";
        if (f.verdict == Verdict::Beyond || f.verdict == Verdict::Gross) wkt << ", relative error area " << fmt(f.relative, 3);
        wkt << "\n# subject\n" << io::writeWkt(f.subject) << "\n# clip\n" << io::writeWkt(f.clip) << "\n";
        if (!f.result.empty() || f.verdict == Verdict::Beyond || f.verdict == Verdict::Gross) {
          wkt << "# result (" << m.name << "'s answer as it gave it)\n" << io::writeWkt(f.result) << "\n";
        }
        // The exact answer as `ghcheck --expected` writes it (the OGC layout of the oracle's answer),
        // judged as written like every answer a tool writes.
        try {
          const std::string expected = io::writeWkt(ogcLayout(oracle::exactAnswerLines(f.subject, f.clip, op)));
          const bool right = oracle::exactCheck(f.subject, f.clip, op, io::readWkt(expected), {false, false, false}).pass;
          wkt << "# expected (ghcheck --expected: the exact answer, OGC layout" << (right ? "" : "; FAILS the exact oracle")
              << ")\n" << expected << "\n";
        } catch (const std::exception& e) {
          wkt << "# expected: not written (" << e.what() << ")\n";
        }
        io::writeText((dir / (id + ".wkt")).string(), wkt.str());
        std::vector<io::SvgLayer> layers{{&f.subject, "#c6dbef", "#2171b5", "subject"},
                                         {&f.clip, "#fcbba1", "#cb181d", "clip"}};
        oracle::ExactVerdict v;
        std::vector<io::SvgMarker> marks;
        if (f.verdict == Verdict::Beyond || f.verdict == Verdict::Gross) {
          try {
            v = oracle::exactCheck(f.subject, f.clip, op, f.result);
            layers.push_back({&f.result, "#a1d99b", "#145214", m.name + " result"});
            layers.push_back({&v.wrong, "#ff0000", "#ff0000", "wrong faces (exact oracle)", 0.9});
            if (v.witness) marks.push_back({*v.witness, "#d00000", "witness"});
          } catch (const std::exception&) {
            // unreadable answer: the picture shows the operands only
          }
        }
        io::writeText((dir / (id + ".svg")).string(),
                      io::svgPicture(layers, m.name + ": " + id + " (" + key(f.verdict) + ")", marks));
        failingCells[m.name][key(f.verdict)].push_back(k.name + " " + std::string(name(op)));
      }
    }
  }

  // The heat map, in tiers a reader can trust: the colour is the worst tier in the cell (gross
  // errors, then failures to answer, then errors beyond rounding but within 1e-6 relative, then
  // refusals and cannot-judge, else all correct); the label is the share of correct answers
  // (exact or rounding-level) over all five operations and, below it, the largest other tier.
  std::ostringstream data;
  for (std::size_t row = 0; row < std::size(kClasses); ++row) {
    for (std::size_t col = 0; col < methods.size(); ++col) {
      Cell sum;
      for (Op op : kAllOps) {
        const auto& byMethod = cells[op][kClasses[row].name];
        const auto it = byMethod.find(methods[col].name);
        if (it == byMethod.end()) continue;
        for (Verdict v : kVerdicts) sum.counts[v] += it->second.count(v);
        sum.total += it->second.total;
      }
      if (sum.total == 0) {
        data << col << ' ' << row << " NaN \"n/a\"\n";
        continue;
      }
      const int gross = sum.count(Verdict::Gross);
      const int failed = sum.count(Verdict::Threw) + sum.count(Verdict::Crashed) + sum.count(Verdict::TimedOut);
      const int beyond = sum.count(Verdict::Beyond);
      const int notAnswered = sum.count(Verdict::Refused) + sum.count(Verdict::Unjudged);
      const int tier = gross ? 0 : failed ? 1 : beyond ? 2 : notAnswered ? 3 : 4;
      auto percent = [&](int n) { return fmt(std::floor(100.0 * n / sum.total), 3); };
      std::string detail;
      const std::pair<int, const char*> others[] = {{gross, "gross"}, {failed, "failed"}, {beyond, "<=1e-6"},
                                                    {notAnswered, "refused"}};
      int largest = 0;
      for (const auto& [n, label] : others) {
        if (n > largest) largest = n, detail = percent(n) + "% " + label;
      }
      data << col << ' ' << row << ' ' << tier << " \"" << percent(sum.correct()) << "%"
           << (detail.empty() ? "" : "\\n" + detail) << "\"\n";
    }
    data << "\n";
  }
  const std::string plotBase = (out / "robustness").string();
  io::writeText(plotBase + ".dat", data.str());
  std::ostringstream gp;
  gp << "set terminal svg size " << 260 + 120 * methods.size() << "," << 140 + 34 * std::size(kClasses)
     << " font 'sans,12' background '#ffffff'\n"
     << "set output '" << plotBase << ".svg'\n"
     << "set title 'Worst tier per cell (colour); correct answers, % of cases over all five operations (label)'\n"
     << "set xrange [-0.5:" << methods.size() - 0.5 << "]\nset yrange [" << std::size(kClasses) - 0.5 << ":-0.5]\n"
     << "set palette maxcolors 5\n"
     << "set palette defined (0 '#b2182b', 1 '#7f7f7f', 2 '#fddbc7', 3 '#d9d9d9', 4 '#2166ac')\n"
     << "set cbrange [-0.5:4.5]\n"
     << "set cbtics ('gross (> 1e-6 relative)' 0, 'threw, crashed or hung' 1, 'beyond rounding, <= 1e-6' 2, "
        "'refused or cannot judge' 3, 'all exact or rounding' 4)\nset xtics (";
  for (std::size_t col = 0; col < methods.size(); ++col) gp << (col ? ", " : "") << "'" << methods[col].name << "' " << col;
  gp << ") scale 0\nset ytics (";
  for (std::size_t row = 0; row < std::size(kClasses); ++row) gp << (row ? ", " : "") << "'" << kClasses[row].name << "' " << row;
  gp << ") scale 0\nunset key\nset datafile missing 'NaN'\n"
     << "plot '" << plotBase << ".dat' using 1:2:(0.5):(0.5):3 with boxxyerror fc palette fs solid 1.0 noborder, "
     << "'' using 1:2:4 with labels font 'sans,9'\n";
  io::writeText(plotBase + ".gp", gp.str());
  if (std::system(("gnuplot '" + plotBase + ".gp'").c_str()) != 0) throw std::runtime_error("gnuplot failed");
  fs::remove(plotBase + ".gp");
  fs::remove(plotBase + ".dat");

  // JSON: every count, for anyone who wants to plot it differently.
  nlohmann::json json;
  json["cases_per_class"] = cases;
  json["seconds"] = seconds;
  for (Op op : kAllOps) {
    for (const InputClass& k : kClasses) {
      for (const auto& [method, cell] : cells[op][k.name]) {
        nlohmann::json& j = json["cells"][std::string(name(op))][k.name][method];
        for (Verdict v : kVerdicts) j[key(v)] = cell.count(v);
        j["worst_relative_error"] = cell.worstRelative;
      }
    }
  }
  io::writeText(plotBase + ".json", json.dump(1) + "\n");

  // The report.
  std::ostringstream md;
  md << "# Robustness: which clipper is right on which inputs\n\n"
     << markdown(provenance(argc, argv)) << "\n"
     << cases << " seeded cases per input class (seeds 1.." << cases << "), each with all five operations, "
     << "each method run in a worker process (replaced when it crashes; killed after " << timeout << " s on one case; 8 GiB address space); "
     << "every answer judged by the exact CGAL-arrangement oracle: our variants' as ghclip writes them (the OGC "
        "layout as WKT, read back), the peers' as they give them. The study took "
     << fmt(seconds, 3) << " s.\n\n"
     << "**Cells**: share of correct answers (error area exactly 0, or every wrong face inside the rounding "
        "zones of the exact answer: each constructed vertex may be either double around its exact crossing, "
        "input vertices may not move; see the README's *Judges*), then the count of each other outcome: "
        "**b** beyond rounding (a wrong face outside the zones, relative error area <= 1e-6), **g** gross "
        "(> 1e-6, or an unreadable answer), **r** refused the input, **t** threw (gave up), **c** crashed, "
        "**h** hung (timed out), **u** the oracle could not judge (counted apart); then the worst relative "
        "error area (error area / largest of the operands', expected and result areas). *n/a*: "
        "GEOS, Boost.Geometry and CGAL take only valid polygons with holes and are run only on the "
        "classes marked valid. Clipper 6.4.2 runs with even-odd fill on every class.\n\n"
     << "![heat map](robustness.svg)\n\n"
     << "## Input classes\n\n| class | valid | n | what |\n|---|---|---|---|\n";
  for (const InputClass& k : kClasses) {
    md << "| " << k.name << " | " << (k.valid ? "yes" : "no") << " | " << k.minN;
    if (k.maxN != k.minN) md << "–" << k.maxN;
    md << " | " << k.description << " |\n";
  }
  for (Op op : kAllOps) {
    md << "\n## " << name(op) << "\n\n| class |";
    for (const Method& m : methods) md << " " << m.name << " |";
    md << "\n|---|";
    for (std::size_t i = 0; i < methods.size(); ++i) md << "---|";
    md << "\n";
    for (const InputClass& k : kClasses) {
      md << "| " << k.name << " |";
      for (const Method& m : methods) {
        const auto it = cells[op][k.name].find(m.name);
        md << " " << (it == cells[op][k.name].end() ? "n/a" : cellText(it->second)) << " |";
      }
      md << "\n";
    }
  }

  // Findings, read off the tables.
  md << "\n## Findings\n\n";
  for (const Method& m : methods) {
    int correct = 0, total = 0, gross = 0, beyond = 0, crashed = 0, hung = 0, threw = 0, refused = 0, unjudged = 0;
    double worst = 0;
    for (Op op : kAllOps) {
      for (const auto& [cls, byMethod] : cells[op]) {
        const auto it = byMethod.find(m.name);
        if (it == byMethod.end()) continue;
        const Cell& c = it->second;
        correct += c.correct(), total += c.total, gross += c.count(Verdict::Gross), beyond += c.count(Verdict::Beyond);
        crashed += c.count(Verdict::Crashed), hung += c.count(Verdict::TimedOut), threw += c.count(Verdict::Threw);
        refused += c.count(Verdict::Refused), unjudged += c.count(Verdict::Unjudged);
        worst = std::max(worst, c.worstRelative);
      }
    }
    md << "- **" << m.name << "**: " << percent(correct, total) << " of " << total << " answers correct";
    if (gross + beyond + crashed + hung + threw + refused + unjudged == 0) {
      md << "; no failure of any kind.\n";
      continue;
    }
    md << "; " << gross << " gross, " << beyond << " beyond rounding (worst relative error " << fmt(worst) << "), "
       << threw << " gave up, " << refused << " refused, " << crashed << " crashed, " << hung << " hung, "
       << unjudged << " the oracle could not judge.";
    const auto& byKind = failingCells[m.name];
    for (const char* kind : {"gross", "beyond-rounding", "threw", "crashed", "timed-out"}) {
      const auto it = byKind.find(kind);
      if (it == byKind.end()) continue;
      std::set<std::string> classes;
      for (const std::string& cell : it->second) classes.insert(cell.substr(0, cell.find(' ')));
      md << " Cells whose smallest failure is *" << kind << "*: " << it->second.size() << ", in classes ";
      bool first = true;
      for (const std::string& c : classes) md << (first ? "" : ", ") << c, first = false;
      md << ".";
    }
    md << " Smallest failing cases: [counterexamples/" << m.name << "/](counterexamples/" << m.name << "/).\n";
  }
  // Peers that accepted an input (no refusal) and then crashed or answered grossly wrong: the
  // smallest such case per peer and class, inline, as the minimal input of a bug report.
  md << "\n### Suspected bugs in peer libraries\n\n"
     << "A peer that accepts an input and then crashes, or returns an answer off by more than 1e-6 of "
        "the problem's area, fails its own contract; the smallest such case per peer and class:\n\n";
  bool anySuspect = false;
  for (const Method& m : methods) {
    if (m.name == "naive" || m.name == "sweep" || m.name == "exact") continue;
    for (const InputClass& k : kClasses) {
      const Case* smallest = nullptr;
      Op smallestOp = Op::Intersection;
      int count = 0, total = 0;
      for (Op op : kAllOps) {
        const auto it = cells[op][k.name].find(m.name);
        if (it == cells[op][k.name].end()) continue;
        count += it->second.count(Verdict::Gross) + it->second.count(Verdict::Crashed);
        total += it->second.total;
        const Case& c = it->second.smallest;
        if (it->second.hasFailure && (c.verdict == Verdict::Gross || c.verdict == Verdict::Crashed) &&
            (!smallest || c.size < smallest->size)) {
          smallest = &c, smallestOp = op;
        }
      }
      if (!smallest) continue;
      anySuspect = true;
      md << "- **" << m.name << "** on " << k.name << " (" << count << " of " << total << " answers): "
         << name(smallestOp) << ", seed " << smallest->seed << ", " << key(smallest->verdict);
      if (smallest->verdict == Verdict::Gross) md << " (relative error area " << fmt(smallest->relative, 3) << ")";
      if (!smallest->message.empty()) md << " (" << smallest->message << ")";
      md << ":\n  subject `" << io::writeWkt(smallest->subject) << "`,\n  clip `" << io::writeWkt(smallest->clip) << "`\n";
    }
  }
  if (!anySuspect) md << "None.\n";

  md << "\n## Gross errors, cell by cell\n\n";
  bool anyGross = false;
  for (Op op : kAllOps) {
    for (const InputClass& k : kClasses) {
      for (const Method& m : methods) {
        const auto it = cells[op][k.name].find(m.name);
        if (it == cells[op][k.name].end() || it->second.count(Verdict::Gross) == 0) continue;
        anyGross = true;
        md << "- " << m.name << ", " << k.name << ", " << name(op) << ": " << it->second.count(Verdict::Gross) << "/"
           << it->second.total << " gross, worst relative error " << fmt(it->second.worstRelative)
           << " ([smallest failing case](counterexamples/" << m.name << "/robustness-" << k.name << "-" << name(op)
           << ".svg))\n";
      }
    }
  }
  if (!anyGross) md << "None.\n";
  io::writeText((out / "robustness.md").string(), md.str());
  std::cout << "wrote " << (out / "robustness.md").string() << " in " << fmt(seconds, 3) << " s\n";
  return 0;
}

int main(int argc, char** argv) { return tools::guardedMain("robustness", argc, argv, run); }
