// I/O at the speed of the clip: our WKT and GeoJSON readers and writers against GEOS's readers
// and writers (its C API, 3.11) on the same text, and ghclip's own end-to-end split (read, clip,
// write) on the 10^6-vertex circles pair. Throughput in MB/s of text; medians of repetitions run
// interleaved in random order, in one process.
//   io_speed OUT.md [google benchmark flags]
#include <benchmark/benchmark.h>
#include <geos_c.h>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>

#include "common/bench_json.h"
#include "common/bench_run.h"
#include "common/provenance.h"
#include "ghclip/clip.h"
#include "ghio/formats.h"
#include "ghwork/generators.h"
#include "tool_main.h"

using namespace gh;
using namespace gh::experiments;
namespace fs = std::filesystem;

namespace {

constexpr int kRepetitions = 5;
constexpr std::size_t kVertices = 1000000;

// The circles pair of 10^6 vertices per operand, its exact union, and their texts.
struct Texts {
  Region subject, answer;
  std::string wkt, geojson, answerWkt;
  std::string subjectFile, clipFile, outFile;  // the pair as ghclip reads it, and where it writes
};
const Texts& texts() {
  static const Texts t = [] {
    Texts x;
    const auto w = work::generate("circles", kVertices, 1);
    x.subject = w.subject;
    x.wkt = io::writeWkt(w.subject);
    x.geojson = io::writeGeoJson(w.subject);
    Options o;
    x.answer = clip(w.subject, w.clip, Op::Union, o);
    x.answerWkt = io::writeWkt(x.answer);
    const auto dir = fs::temp_directory_path();
    x.subjectFile = (dir / "ghclip-io-speed-subject.wkt").string();
    x.clipFile = (dir / "ghclip-io-speed-clip.wkt").string();
    x.outFile = (dir / "ghclip-io-speed-out.wkt").string();
    io::writeText(x.subjectFile, x.wkt);
    io::writeText(x.clipFile, io::writeWkt(w.clip));
    return x;
  }();
  return t;
}

struct GeosHandle {
  GEOSContextHandle_t h = GEOS_init_r();
  ~GeosHandle() { GEOS_finish_r(h); }
};

void bytes(benchmark::State& s, std::size_t n) {
  s.SetBytesProcessed(static_cast<std::int64_t>(n) * static_cast<std::int64_t>(s.iterations()));
}

void registerAll() {
  auto add = [](const char* name, auto body) {
    benchmark::RegisterBenchmark(name, body)->Arg(static_cast<long>(kVertices))->Unit(benchmark::kMillisecond)->Repetitions(kRepetitions)->MinTime(0.5);
  };
  add("read-wkt/ghclip", [](benchmark::State& s) {
    for (auto _ : s) benchmark::DoNotOptimize(io::readWkt(texts().wkt));
    bytes(s, texts().wkt.size());
  });
  add("read-wkt/geos", [](benchmark::State& s) {
    GeosHandle g;
    GEOSWKTReader* r = GEOSWKTReader_create_r(g.h);
    for (auto _ : s) GEOSGeom_destroy_r(g.h, GEOSWKTReader_read_r(g.h, r, texts().wkt.c_str()));
    GEOSWKTReader_destroy_r(g.h, r);
    bytes(s, texts().wkt.size());
  });
  add("read-geojson/ghclip", [](benchmark::State& s) {
    for (auto _ : s) benchmark::DoNotOptimize(io::readGeoJson(texts().geojson));
    bytes(s, texts().geojson.size());
  });
  add("read-geojson/geos", [](benchmark::State& s) {
    GeosHandle g;
    GEOSGeoJSONReader* r = GEOSGeoJSONReader_create_r(g.h);
    for (auto _ : s) GEOSGeom_destroy_r(g.h, GEOSGeoJSONReader_readGeometry_r(g.h, r, texts().geojson.c_str()));
    GEOSGeoJSONReader_destroy_r(g.h, r);
    bytes(s, texts().geojson.size());
  });
  add("write-wkt/ghclip", [](benchmark::State& s) {
    for (auto _ : s) benchmark::DoNotOptimize(io::writeWkt(texts().subject));
    bytes(s, texts().wkt.size());
  });
  add("write-wkt/geos", [](benchmark::State& s) {
    GeosHandle g;
    GEOSWKTReader* r = GEOSWKTReader_create_r(g.h);
    GEOSGeometry* geometry = GEOSWKTReader_read_r(g.h, r, texts().wkt.c_str());
    GEOSWKTWriter* w = GEOSWKTWriter_create_r(g.h);
    GEOSWKTWriter_setTrim_r(g.h, w, 1);
    GEOSWKTWriter_setRoundingPrecision_r(g.h, w, 17);
    for (auto _ : s) GEOSFree_r(g.h, GEOSWKTWriter_write_r(g.h, w, geometry));
    GEOSWKTWriter_destroy_r(g.h, w);
    GEOSGeom_destroy_r(g.h, geometry);
    GEOSWKTReader_destroy_r(g.h, r);
    bytes(s, texts().wkt.size());
  });
  add("write-geojson/ghclip", [](benchmark::State& s) {
    for (auto _ : s) benchmark::DoNotOptimize(io::writeGeoJson(texts().subject));
    bytes(s, texts().geojson.size());
  });
  // What `ghclip --variant exact --threads 1 --op union S C -o OUT` does, step by step: read and
  // parse both files, clip, lay out and write the answer.
  add("end-to-end/ghclip", [](benchmark::State& s) {
    double read = 0, clipped = 0, written = 0;
    for (auto _ : s) {
      using Clock = std::chrono::steady_clock;
      const auto t0 = Clock::now();
      const Region a = io::readAuto(io::readText(texts().subjectFile)), b = io::readAuto(io::readText(texts().clipFile));
      const auto t1 = Clock::now();
      Options o;
      o.threads = 1;
      const Region r = clip(a, b, Op::Union, o);
      const auto t2 = Clock::now();
      io::writeText(texts().outFile, io::write(r, io::Format::Wkt, io::Layout::Ogc));
      const auto t3 = Clock::now();
      read += std::chrono::duration<double>(t1 - t0).count(), clipped += std::chrono::duration<double>(t2 - t1).count();
      written += std::chrono::duration<double>(t3 - t2).count();
    }
    const double n = static_cast<double>(s.iterations());
    s.counters["read_s"] = read / n, s.counters["clip_s"] = clipped / n, s.counters["write_s"] = written / n;
  });
  add("write-ogc-wkt/ghclip", [](benchmark::State& s) {  // the layout included
    for (auto _ : s) benchmark::DoNotOptimize(io::write(texts().answer, io::Format::Wkt, io::Layout::Ogc));
    bytes(s, texts().answerWkt.size());
  });
}

}  // namespace

int run(int argc, char** argv) {
  if (argc < 2 || std::string(argv[1]).rfind("--", 0) == 0) {
    return tools::usageError("io_speed", "usage: io_speed OUT.md [google benchmark flags]");
  }
  const std::string out = argv[1];
  const std::string json = std::filesystem::path(out).replace_extension(".json").string();
  registerAll();
  texts();  // generated and clipped before any timing
  const std::optional<BenchFile> ran = runInterleaved(argc, argv, 2, json);
  if (!ran) return 0;  // listed only
  const BenchFile& f = *ran;
  auto mbPerSecond = [&](const std::string& name, std::size_t size) -> double {
    const BenchRow* r = findRow(f, name, static_cast<long>(kVertices));
    return r ? static_cast<double>(size) / 1e6 / (r->medianMs / 1000) : 0;
  };
  const Texts& t = texts();
  std::ostringstream md;
  md << "# I/O speed: ghclip's readers and writers against GEOS's\n\n"
     << markdown(provenance(argc, argv)) << "\n"
     << "The subject of the circles workload at " << kVertices << " vertices (ghgen circles --n " << kVertices
     << " --seed 1): " << reportNumber(static_cast<double>(t.wkt.size()) / 1e6) << " MB of WKT, "
     << reportNumber(static_cast<double>(t.geojson.size()) / 1e6)
     << " MB of GeoJSON, the same text for both libraries. MB/s of text, medians of " << kRepetitions
     << " repetitions run interleaved in random order. GEOS 3.11's C API: GEOSWKTReader, GEOSGeoJSONReader, "
        "GEOSWKTWriter (trimmed, 17 digits). Targets (issue 18): reading at least 3x GEOS, writing at least 100 MB/s.\n\n"
     << "| what | ghclip MB/s | GEOS MB/s | ghclip / GEOS |\n|---|---|---|---|\n";
  auto row = [&](const char* what, const std::string& ours, const std::string& geos, std::size_t size) {
    const double a = mbPerSecond(ours, size), b = geos.empty() ? 0 : mbPerSecond(geos, size);
    md << "| " << what << " | " << reportNumber(a) << " | " << (b > 0 ? reportNumber(b) : "–") << " | "
       << (b > 0 ? reportNumber(a / b) : "–") << " |\n";
  };
  row("read WKT", "read-wkt/ghclip", "read-wkt/geos", t.wkt.size());
  row("read GeoJSON", "read-geojson/ghclip", "read-geojson/geos", t.geojson.size());
  row("write WKT", "write-wkt/ghclip", "write-wkt/geos", t.wkt.size());
  row("write GeoJSON", "write-geojson/ghclip", "", t.geojson.size());
  row("write the union's OGC layout as WKT (layout included)", "write-ogc-wkt/ghclip", "", t.answerWkt.size());
  if (const BenchRow* e = findRow(f, "end-to-end/ghclip", static_cast<long>(kVertices))) {
    md << "\n## End to end\n\nWhat `ghclip --variant exact --threads 1 --op union` does on the circles pair of "
       << kVertices << " vertices per operand (" << reportNumber(static_cast<double>(t.wkt.size()) * 2 / 1e6)
       << " MB of WKT in, the union's OGC layout out to a file): median " << reportNumber(e->medianMs / 1000)
       << " s, of which reading " << reportNumber(counterOf(e, "read_s")) << " s, clipping "
       << reportNumber(counterOf(e, "clip_s")) << " s and writing " << reportNumber(counterOf(e, "write_s"))
       << " s (the largest of each over the repetitions). Target (issue 18): 1 s.\n";
  }
  for (const std::string& file : {t.subjectFile, t.clipFile, t.outFile}) fs::remove(file);
  io::writeText(out, md.str());
  std::cout << "wrote " << out << "\n";
  return 0;
}

int main(int argc, char** argv) { return tools::guardedMain("io_speed", argc, argv, run); }
