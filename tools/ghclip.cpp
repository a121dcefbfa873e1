// ghclip: clip two regions read from files (WKT or GeoJSON) and write the result.
// Exit codes: 0 done, 1 the algorithm (or --check) failed on valid input, 2 bad input or usage,
// 3 --check cannot judge.
#include <CLI/CLI.hpp>
#include <chrono>
#include <iostream>
#include <nlohmann/json.hpp>

#include "ghclip/clip.h"
#include "ghclip/clipping.h"
#include "ghclip/ogc_layout.h"
#include "ghclip/ogc_validity.h"
#include "ghclip/errors.h"
#include "ghclip/measure.h"
#include "ghio/formats.h"
#include "ghio/svg.h"
#include "ghoracle/exact_oracle.h"
#include "ghpeers/peer.h"
#include "ghoracle/sampling_oracle.h"
#include "stats_json.h"
#include "verdict_json.h"
#include "written_answer.h"
#include "peer_in_child.h"
#include "tool_main.h"

namespace {

constexpr const char* kDescription =
    "Clip two polygonal regions with the Greiner-Hormann algorithm.\n"
    "Input: WKT POLYGON/MULTIPOLYGON (also in a GEOMETRYCOLLECTION, after PostGIS's SRID=n;) or\n"
    "GeoJSON (Polygon, MultiPolygon, Feature...), '-' for stdin. All rings of an input are\n"
    "pooled and its interior is the even-odd rule over all of them: holes are rings inside\n"
    "rings, and OGC shell/hole roles are ignored.\n"
    "Output: a MULTIPOLYGON (GeoJSON MultiPolygon) of valid OGC polygons with holes (--layout ogc,\n"
    "the default: noded and nested exactly, vertices input vertices or faithfully rounded crossings\n"
    "of input edges), or of one polygon per raw ring (--layout rings).\n"
    "Arithmetic: exact by default (exact predicates, Simulation of Simplicity: no input vertex\n"
    "moves); --variant naive or --arithmetic paper runs the paper's doubles and perturbation.\n"
    "Exit codes: 0 done, 1 clipping or --check failed on valid input, 2 bad input, usage or an\n"
    "output that cannot be written (no output file is left), 3 --check cannot judge.";

int run(int argc, char** argv) {
  CLI::App app{kDescription, "ghclip"};
  std::string opName, variantName, arithmeticName, searchName, subjectPath, clipPath, outPath = "-",
                      formatName = "wkt", layoutName = "ogc", svgPath;
  std::string checkName, peerName;
  bool wantStats = false, sanitize = false;
  unsigned threads = 0;
  app.add_option("--op", opName,
                 "intersection | union | difference | reverse-difference | xor")
      ->required();
  app.add_option("--variant", variantName,
                 "a named combination of the two options below: exact (the default: exact, auto) | naive (the "
                 "paper as published: paper, all-pairs) | sweep (paper, sweep)");
  app.add_option("--arithmetic", arithmeticName,
                 "exact (default: exact predicates, Simulation of Simplicity) | paper (doubles, the paper's "
                 "perturbation)");
  app.add_option("--search", searchName,
                 "auto (default: all pairs for paper, the cheaper for exact) | all-pairs | sweep");
  app.add_option("--peer", peerName,
                 "clip with a peer library instead: clipper6 | geos | boost | cgal (geos, boost "
                 "and cgal take only simple polygons with holes and refuse the rest, exit 2)");
  app.add_option("SUBJECT", subjectPath, "subject region file, '-' for stdin")->required();
  app.add_option("CLIP", clipPath, "clip region file, '-' for stdin")->required();
  app.add_option("-o,--output", outPath, "result file ('-' = stdout)")->capture_default_str();
  app.add_option("--format", formatName, "output format: wkt | geojson")->capture_default_str();
  app.add_option("--layout", layoutName,
                 "ogc (valid OGC polygons with holes, exact: what GIS tools read) | rings (one polygon per raw "
                 "Greiner-Hormann ring: only an even-odd reader reads it right)")
      ->capture_default_str();
  app.add_option("--svg", svgPath, "also draw subject, clip and result to this SVG file");
  app.add_flag("--stats", wantStats,
               "print statistics as JSON (stdout when -o names a file, else stderr)");
  app.add_option("--check", checkName,
                 "judge the answer as written (the output's bytes read back) with an oracle: exact | sample (exit 1 "
                 "if it fails)");
  app.add_flag("--sanitize", sanitize, "drop rings with fewer than 3 distinct vertices");
  app.add_option("--threads", threads, "threads for the clip, 0 = every core (the answer is the same on any number)")
      ->capture_default_str();
  if (const auto exitCode = gh::tools::parseCommandLine(app, "ghclip", argc, argv)) return *exitCode;

  const auto op = gh::parseOp(opName);
  if (!op) return gh::tools::usageError("ghclip", "unknown --op '" + opName + "'");
  gh::Options options;
  if (!variantName.empty()) {
    const auto variant = gh::parseVariant(variantName);
    if (!variant) return gh::tools::usageError("ghclip", "unknown --variant '" + variantName + "'");
    if (!arithmeticName.empty() || !searchName.empty()) {
      return gh::tools::usageError("ghclip", "--variant names both --arithmetic and --search: give one or the others");
    }
    options = gh::optionsOf(*variant);
  }
  if (!arithmeticName.empty()) {
    const auto arithmetic = gh::parseArithmetic(arithmeticName);
    if (!arithmetic) return gh::tools::usageError("ghclip", "unknown --arithmetic '" + arithmeticName + "'");
    options.arithmetic = *arithmetic;
  }
  if (!searchName.empty()) {
    const auto search = gh::parseSearch(searchName);
    if (!search) return gh::tools::usageError("ghclip", "unknown --search '" + searchName + "'");
    options.search = *search;
  }
  if (formatName != "wkt" && formatName != "geojson") {
    return gh::tools::usageError("ghclip", "unknown --format '" + formatName + "'");
  }
  if (layoutName != "ogc" && layoutName != "rings") {
    return gh::tools::usageError("ghclip", "unknown --layout '" + layoutName + "'");
  }
  if (!checkName.empty() && checkName != "exact" && checkName != "sample") {
    return gh::tools::usageError("ghclip", "unknown --check '" + checkName + "'");
  }
  if (subjectPath == "-" && clipPath == "-") {
    return gh::tools::usageError("ghclip", "only one of SUBJECT and CLIP can be stdin");
  }

  using Clock = std::chrono::steady_clock;
  auto secondsSince = [](Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); };
  const auto readStart = Clock::now();
  // gh::clip validates its operands itself; the peers get them validated here, exactly as the
  // clip would (a copy the clip's own path need not pay for).
  const gh::OnBadRing onBadRing = sanitize ? gh::OnBadRing::Drop : gh::OnBadRing::Throw;
  const gh::Region subject = peerName.empty() ? gh::tools::readRegion(subjectPath)
                                              : gh::tools::readValidRegion(subjectPath, onBadRing);
  const gh::Region clip = peerName.empty() ? gh::tools::readRegion(clipPath)
                                           : gh::tools::readValidRegion(clipPath, onBadRing);
  const double readSeconds = secondsSince(readStart);
  options.sanitize = sanitize;
  options.threads = threads;
  const gh::peers::Peer* peer = nullptr;
  if (!peerName.empty()) {
    peer = gh::peers::findPeer(peerName);
    if (!peer) return gh::tools::usageError("ghclip", "unknown --peer '" + peerName + "'");
  }
  const bool ogc = layoutName == "ogc";
  const auto format = formatName == "geojson" ? gh::io::Format::GeoJson : gh::io::Format::Wkt;
  const auto layout = ogc ? gh::io::Layout::Ogc : gh::io::Layout::Rings;
  gh::tools::WrittenAnswer answer;
  const auto clipStart = Clock::now();
  try {
    if (peer) {
      // In a child process: a peer that crashes (CGAL has) is reported, never takes ghclip down.
      gh::tools::PeerOutcome outcome = gh::tools::clipInChild(*peer, subject, clip, *op);
      if (outcome.kind == gh::tools::PeerOutcome::Kind::Refused) throw gh::InvalidInput(outcome.message);  // exit 2
      if (outcome.kind == gh::tools::PeerOutcome::Kind::Failed) {
        std::cerr << "ghclip: " << peer->name() << " failed: " << outcome.message << std::endl;  // one line, exit 1
        return gh::tools::kExitFailed;
      }
      const double seconds = secondsSince(clipStart);
      const std::size_t rings = outcome.result.size(), vertices = gh::vertexCount(outcome.result);
      answer = gh::tools::writtenAnswer(std::move(outcome.result), subject, clip, *op, format, layout);
      answer.stats.phase1Seconds = seconds;
      answer.stats.outputRings = rings;
      answer.stats.outputVertices = vertices;
    } else {
      gh::Clipping clipping(subject, clip, options);
      answer = gh::tools::writtenAnswer(clipping, subject, clip, *op, format, layout);
    }
  } catch (const gh::InvalidInput& e) {
    // Name the file the refused operand came from; a peer's refusal may concern either.
    if (e.operand() == "subject") throw gh::tools::BadInput(subjectPath + ": " + e.problem());
    if (e.operand() == "clip") throw gh::tools::BadInput(clipPath + ": " + e.problem());
    throw gh::tools::BadInput(subjectPath + " / " + clipPath + ": " + e.what());
  }
  const gh::Stats& stats = answer.stats;
  const gh::LayoutStats& layoutStats = answer.layout;
  const std::string& text = answer.text;
  const auto writeStart = Clock::now();
  // --check judges what is written: the bytes read back, as any reader of the file gets them, and
  // (--layout ogc) the polygons' validity, exactly.
  nlohmann::json check;
  bool checkPassed = true;
  if (!checkName.empty()) {
    const gh::Region written = gh::io::readAuto(text);
    if (checkName == "exact") {
      const auto v = gh::oracle::exactCheck(subject, clip, *op, written, {false, false, false});
      checkPassed = v.pass;
      check = gh::tools::verdictJson(v);
    } else {
      const auto v = gh::oracle::sampleCheck(subject, clip, *op, written);
      checkPassed = v.pass();
      check = gh::tools::verdictJson(v);
    }
    if (ogc) {
      const auto invalid = gh::ogcInvalidity(answer.polygons);
      check["ogc_valid"] = !invalid;
      if (invalid) check["ogc_invalidity"] = *invalid, checkPassed = false;
    }
  }
  // The answer and its picture together, or neither (a failing --svg leaves no -o file).
  gh::io::OutputFiles files;
  files.add(outPath, text);
  if (!svgPath.empty()) {
    const std::string title = std::string(gh::name(*op)) + " (" + (peer ? peerName : gh::name(options)) +
                              "), even-odd area " + std::to_string(gh::evenOddArea(answer.rings));
    files.add(svgPath, gh::io::svgPicture({{&subject, "#c6dbef", "#2171b5", "subject"},
                                           {&clip, "#fcbba1", "#cb181d", "clip"},
                                           {&answer.rings, "#2ca02c", "#145214", "result", 0.6}},
                                          title));
  }
  files.commit();
  const double writeSeconds = secondsSince(writeStart);
  if (wantStats) {
    nlohmann::json j = gh::tools::statsJson(stats);
    j["op"] = gh::name(*op);
    if (peer) {
      j = {{"peer", peer->name()}, {"seconds", stats.phase1Seconds}, {"output_rings", stats.outputRings},
           {"output_vertices", stats.outputVertices}};
    } else {
      j["variant"] = gh::name(options);
      j["arithmetic"] = gh::name(options.arithmetic);
      j["search"] = gh::name(options.search);
      j["threads"] = threads == 0 ? gh::availableThreads() : threads;
    }
    j["read_seconds"] = readSeconds;    // reading and validating both operands
    if (ogc) {
      j["layout"] = {{"seconds", layoutStats.seconds},   {"nodes", layoutStats.nodes},
                     {"new_nodes", layoutStats.newNodes}, {"pieces", layoutStats.pieces},
                     {"merged", layoutStats.merged},      {"rerounded", layoutStats.rerounded},
                     {"snap_rounded", layoutStats.snapRounded}, {"routed", layoutStats.routed},
                     {"polygons", layoutStats.polygons},  {"holes", layoutStats.holes}};
    }
    j["format_seconds"] = answer.formatSeconds;  // the text of the answer
    j["write_seconds"] = writeSeconds;            // --check, the picture and writing every output
    if (!check.is_null()) j["check"] = check;
    (outPath == "-" ? std::cerr : std::cout) << j.dump() << std::endl;
  } else if (!check.is_null()) {
    std::cerr << "ghclip: check " << check.dump() << std::endl;
  }
  return checkPassed ? 0 : gh::tools::kExitFailed;
}

}  // namespace

int main(int argc, char** argv) { return gh::tools::guardedMain("ghclip", argc, argv, run); }
