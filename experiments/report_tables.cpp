// results/table1.md, results/table2.md and the Table 1 plot, from table_benchmark's JSON only.
//   report_tables BENCH.json RESULTS_DIR
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "common/bench_json.h"
#include "common/provenance.h"
#include "ghclip/operation.h"
#include "ghio/formats.h"
#include "tool_main.h"

using namespace gh::experiments;
namespace fs = std::filesystem;

namespace {

// "12.3 [11.9–13.0]" and a mark when an answer was wrong.
std::string cell(const BenchRow* r) {
  if (!r) return "–";
  std::string s = timeRange(*r);
  if (r->counters.count("wrong") && r->counters.at("wrong") > 0) {
    s += " **wrong " + reportNumber(r->counters.at("wrong")) + "/" + reportNumber(r->counters.at("checked")) + "**";
  }
  return s;
}

std::string header(const BenchFile& f, int argc, char** argv, const std::string& title) {
  std::ostringstream md;
  md << "# " << title << "\n\n" << markdown(provenance(argc, argv)) << "\n"
     << "Made from `" << argv[1] << "` (Google Benchmark JSON; host " << f.context.at("host_name") << ", "
     << f.context.at("num_cpus") << " CPUs, run " << f.context.at("date") << "). Times are medians over the "
     << "repetitions in ms, [min–max] beside them. Each timed iteration clips the next of 16 seeded pairs "
     << "(seeds 1000–1015), as the paper averaged over fresh random polygons. Every answer of the last round "
     << "through the pool is checked outside the timed region (exact oracle when the case has at most 400 "
     << "vertices, sampling oracle otherwise); a wrong one is marked **wrong k/16**.\n\n";
  return md.str();
}

}  // namespace

int run(int argc, char** argv) {
  if (argc != 3) return gh::tools::usageError("report_tables", "usage: report_tables BENCH.json RESULTS_DIR");
  const BenchFile f = readBenchJson(argv[1]);
  const fs::path out = argv[2];

  // ---- Table 1 -------------------------------------------------------------------------------
  std::ostringstream t1;
  const std::string cores = f.context.at("num_cpus");
  t1 << header(f, argc, argv, "Table 1, reproduced: Greiner-Hormann against Vatti on the paper's workload")
     << "Two random n-gons in the unit square (the paper's Section 6), intersection. Vatti's algorithm is "
        "Clipper 6.4.2 with even-odd fill. GEOS, Boost.Geometry and CGAL take only valid simple polygons, so "
        "they are not in this table (see table2.md).\n\n"
        "- **Floor**: the all-pairs loop alone that tests every pair with the paper's test and constructs "
        "every crossing point: no ordering, no graph, no tracing (clipper/src/crossing_floor.h), pair by pair "
        "(scalar) and through the vectorized pair test (AVX2, what the clip's rows use where the processor has "
        "it). The scalar floor is the paper's phase 1 without its ordering: naive / scalar floor says what "
        "everything else of the clip costs on top of finding the crossings.\n"
        "- **GH naive, GH exact**: one thread, and on every core (" + cores + " here; `Options::threads = 0`); "
        "the answers are the same bit for bit. **Improvement** = Vatti / GH naive (the paper's column), on one "
        "thread and on every core.\n"
        "- **Exact / naive**: the cost of exact predicates and certified constructions, same threads (the "
        "exact variant picks all pairs here, like naive). **GMP per pair**: the exact variant's predicates "
        "decided in rational arithmetic per candidate pair. Intersections: average crossings per pair; trials: "
        "timed iterations summed over the repetitions.\n\n"
     << "| n | Vatti (Clipper 6.4.2) ms | floor, scalar ms | floor, vectorized ms | GH naive ms | naive / scalar floor | "
        "improvement | GH naive, all cores ms | improvement, all cores | GH sweep ms | GH exact ms | exact / naive | "
        "GH exact, all cores ms | exact / naive, all cores | exact: GMP per pair | intersections | trials (Vatti / naive) |\n"
     << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  const std::string ti = "t1-random-intersection/";
  std::vector<long> sizes;
  if (f.rows.count(ti + "naive")) {
    for (const auto& [n, r] : f.rows.at(ti + "naive")) sizes.push_back(n);
  }
  auto ratio = [](const BenchRow* a, const BenchRow* b) { return a && b ? reportNumber(a->medianMs / b->medianMs) : std::string("–"); };
  for (long n : sizes) {
    const BenchRow* v = findRow(f, ti + "clipper6", n);
    const BenchRow* floor = findRow(f, ti + "crossings", n);
    const BenchRow* nv = findRow(f, ti + "naive", n);
    const BenchRow* nvAll = findRow(f, ti + "naive@all", n);
    const BenchRow* ex = findRow(f, ti + "exact", n);
    const BenchRow* exAll = findRow(f, ti + "exact@all", n);
    const double pairs = counterOf(ex, "candidate_pairs");
    t1 << "| " << n << " | " << cell(v) << " | " << cell(floor) << " | " << cell(findRow(f, ti + "crossings-simd", n)) << " | "
       << cell(nv) << " | " << ratio(nv, floor) << " | " << ratio(v, nv) << " | " << cell(nvAll) << " | " << ratio(v, nvAll)
       << " | " << cell(findRow(f, ti + "sweep", n)) << " | " << cell(ex) << " | " << ratio(ex, nv) << " | " << cell(exAll)
       << " | " << ratio(exAll, nvAll) << " | " << (pairs > 0 ? reportNumber(counterOf(ex, "filter_failures") / pairs) : "–")
       << " | " << reportNumber(counterOf(nv, "intersections")) << " | " << (v ? std::to_string(v->iterations) : "–") << " / "
       << (nv ? std::to_string(nv->iterations) : "–") << " |\n";
  }
  t1 << "\n### Every operation: improvement of GH naive over Vatti (Vatti time / naive time)\n\n| n |";
  for (gh::Op op : gh::kAllOps) t1 << " " << gh::name(op) << " |";
  t1 << "\n|---|---|---|---|---|---|\n";
  for (long n : sizes) {
    t1 << "| " << n << " |";
    for (gh::Op op : gh::kAllOps) {
      const std::string fam = "t1-random-" + std::string(gh::name(op)) + "/";
      const BenchRow* v = findRow(f, fam + "clipper6", n);
      const BenchRow* nv = findRow(f, fam + "naive", n);
      t1 << " " << (v && nv ? reportNumber(v->medianMs / nv->medianMs) : "–") << " |";
    }
    t1 << "\n";
  }
  t1 << "\n![time against n, log-log](table1.svg)\n";
  gh::io::writeText((out / "table1.md").string(), t1.str());

  // The plot of Table 1.
  const char* methods[] = {"clipper6", "naive", "naive@all", "sweep", "exact", "crossings", "crossings-simd"};
  const std::string allCores = "GH naive, " + cores + " cores";
  const char* labels[] = {"Vatti (Clipper 6.4.2)", "GH naive", allCores.c_str(), "GH sweep", "GH exact",
                          "floor: every pair tested and crossing made", "floor, vectorized pair test"};
  std::ostringstream data, gp;
  for (const char* m : methods) {
    data << "# " << m << "\n";
    if (f.rows.count(ti + m)) {
      for (const auto& [n, r] : f.rows.at(ti + m)) data << n << ' ' << r.medianMs << '\n';
    }
    data << "\n\n";
  }
  const std::string base = (out / "table1").string();
  gh::io::writeText(base + ".dat", data.str());
  gp << "set terminal svg size 800,560 font 'sans,12'\nset output '" << base << ".svg'\nset logscale xy\n"
     << "set xlabel 'n (vertices per polygon)'\nset ylabel 'median time per intersection (ms)'\n"
     << "set title \"The paper's random workload\"\nset key top left\nset grid\nplot ";
  for (std::size_t i = 0; i < std::size(methods); ++i) {
    gp << (i ? ", " : "") << "'" << base << ".dat' index " << i << " using 1:2 with linespoints title '" << labels[i] << "'";
  }
  gp << "\n";
  gh::io::writeText(base + ".gp", gp.str());
  if (std::system(("gnuplot '" + base + ".gp'").c_str()) != 0) throw std::runtime_error("gnuplot failed");
  fs::remove(base + ".gp"), fs::remove(base + ".dat");

  // ---- Table 2 -------------------------------------------------------------------------------
  std::ostringstream t2;
  t2 << header(f, argc, argv, "Table 2, beyond the paper: valid polygons, every variant and every peer")
     << "Workloads: `simple` (random simple polygons), `holes` (a shell with 2–5 holes against another), and the "
        "realistic `circles` (two perturbed circles crossing twice) and `coastline` (fractal outlines). All are "
        "valid polygons with holes, so GEOS, Boost.Geometry and CGAL run on them; peers convert their operands "
        "before the timed loop. The naive variant (all pairs) is not run at 10^5 vertices. Output vertices: "
        "average over the pool, from the exact variant.\n";
  const char* all[] = {"naive", "sweep", "exact", "clipper6", "geos", "boost", "cgal"};
  const char* allLabels[] = {"GH naive", "GH sweep", "GH exact", "Clipper 6.4.2", "GEOS 3.11", "Boost.Geometry 1.74", "CGAL 5.5"};
  for (const char* workload : {"simple", "holes", "circles", "coastline"}) {
    for (gh::Op op : {gh::Op::Intersection, gh::Op::Union}) {
      const std::string prefix = "t2-" + std::string(workload) + "-" + std::string(gh::name(op)) + "/";
      t2 << "\n## " << workload << ", " << gh::name(op) << "\n\n| n |";
      for (const char* l : allLabels) t2 << " " << l << " |";
      t2 << " output vertices |\n|---|";
      for (std::size_t i = 0; i <= std::size(all); ++i) t2 << "---|";
      t2 << "\n";
      std::vector<long> ns;
      if (f.rows.count(prefix + "exact")) {
        for (const auto& [n, r] : f.rows.at(prefix + "exact")) ns.push_back(n);
      }
      for (long n : ns) {
        t2 << "| " << n << " |";
        for (const char* m : all) t2 << " " << cell(findRow(f, prefix + m, n)) << " |";
        t2 << " " << reportNumber(counterOf(findRow(f, prefix + "exact", n), "output_vertices")) << " |\n";
      }
    }
  }
  gh::io::writeText((out / "table2.md").string(), t2.str());
  std::cout << "wrote table1.md, table1.svg and table2.md in " << out.string() << "\n";
  return 0;
}

int main(int argc, char** argv) { return gh::tools::guardedMain("report_tables", argc, argv, run); }
