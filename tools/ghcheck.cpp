// ghcheck: judge a candidate result of op(SUBJECT, CLIP) with an oracle, or write the exact answer.
// Exit codes: 0 pass, 1 fail, 2 bad input or usage, 3 cannot judge.
#include <CLI/CLI.hpp>
#include <iostream>

#include "ghclip/ogc_layout.h"
#include "ghio/formats.h"
#include "ghio/svg.h"
#include "ghoracle/exact_oracle.h"
#include "ghoracle/sampling_oracle.h"
#include "tool_main.h"
#include "verdict_json.h"

namespace {

constexpr const char* kDescription =
    "Judge RESULT as the answer to op(SUBJECT, CLIP), or with --expected write the exact answer.\n"
    "Regions are read like ghclip reads them (WKT or GeoJSON, all rings pooled, even-odd rule).\n"
    "exact: CGAL arrangement with rational arithmetic; exact error area and a witness point.\n"
    "Pass: every wrong face lies in the rounding zones of the exact answer's constructed vertices\n"
    "(each may round to either double around it: --ulps widens that).\n"
    "sample: seeded points, exact even-odd tests, points within an edge's delta of S or C skipped.\n"
    "Exit codes: 0 pass, 1 fail, 2 bad input, usage or an unwritable output, 3 cannot judge.";

int run(int argc, char** argv) {
  CLI::App app{kDescription, "ghcheck"};
  std::string opName, oracleName = "exact", subjectPath, clipPath, resultPath, svgPath,
                      outPath = "-", formatName = "wkt", layoutName = "ogc";
  bool json = false, expectedOnly = false;
  std::uint64_t seed = 1;
  int ulps = 1;
  app.add_option("--op", opName, "intersection | union | difference | reverse-difference | xor")
      ->required();
  app.add_option("--oracle", oracleName, "exact | sample")->capture_default_str();
  app.add_option("SUBJECT", subjectPath, "subject region")->required();
  app.add_option("CLIP", clipPath, "clip region")->required();
  app.add_option("RESULT", resultPath, "candidate result (not with --expected)");
  app.add_flag("--json", json, "print the verdict as JSON");
  app.add_option("--svg", svgPath, "draw S, C, R and the wrong faces (red)");
  app.add_option("--seed", seed, "sampling oracle seed")->capture_default_str();
  app.add_option("--ulps", ulps,
                 "how far a constructed vertex may be from its exact crossing: 1 = a faithful rounding, "
                 "k = k - 1 more ulps of its own coordinates on each side")
      ->capture_default_str()
      ->check(CLI::Range(1, 1 << 20));
  app.add_flag("--expected", expectedOnly, "write the exact answer's rings instead of judging");
  app.add_option("-o,--output", outPath, "with --expected: output file")->capture_default_str();
  app.add_option("--format", formatName, "with --expected: wkt | geojson")->capture_default_str();
  app.add_option("--layout", layoutName, "with --expected: ogc (valid polygons with holes) | rings")->capture_default_str();
  if (const auto exitCode = gh::tools::parseCommandLine(app, "ghcheck", argc, argv)) return *exitCode;
  const auto op = gh::parseOp(opName);
  if (!op) return gh::tools::usageError("ghcheck", "unknown --op '" + opName + "'");
  if (oracleName != "exact" && oracleName != "sample") {
    return gh::tools::usageError("ghcheck", "unknown --oracle '" + oracleName + "'");
  }
  if (expectedOnly == !resultPath.empty()) {
    return gh::tools::usageError("ghcheck", "give either RESULT or --expected");
  }
  const gh::Region subject = gh::tools::readValidRegion(subjectPath);
  const gh::Region clip = gh::tools::readValidRegion(clipPath);

  if (expectedOnly) {
    if (layoutName != "ogc" && layoutName != "rings") {
      return gh::tools::usageError("ghcheck", "unknown --layout '" + layoutName + "'");
    }
    const auto format = formatName == "geojson" ? gh::io::Format::GeoJson : gh::io::Format::Wkt;
    // The exact answer's boundary knows the lines of S and C it runs along: its layout nodes it at
    // their exact crossings, as the clip's does (ghclip/ogc_layout.h).
    std::string text;
    if (layoutName == "ogc") {
      gh::LayoutStats layout;
      text = gh::io::write(gh::ogcLayout(gh::oracle::exactAnswerLines(subject, clip, *op), &layout), format);
      if (layout.snapRounded) gh::tools::requireWithinRounding(subject, clip, *op, text);
    } else {
      text = gh::io::write(gh::oracle::exactAnswer(subject, clip, *op), format);
    }
    gh::io::writeText(outPath, text);
    return 0;
  }

  // A candidate's rings of fewer than 3 distinct vertices bound nothing: dropped, not refused.
  const gh::Region result = gh::tools::readValidRegion(resultPath, gh::OnBadRing::Drop);
  bool pass;
  std::vector<gh::io::SvgMarker> markers;
  gh::Region wrong;
  if (oracleName == "exact") {
    gh::oracle::ExactOptions options;
    options.constructionUlps = ulps;
    options.exactAreas = true;
    const auto v = gh::oracle::exactCheck(subject, clip, *op, result, options);
    pass = v.pass;
    std::cout << (json ? gh::tools::verdictJson(v).dump() + "\n" : gh::tools::verdictText(v));
    wrong = v.wrong;
    if (v.witness) markers.push_back({*v.witness, "#d00000", "witness"});
  } else {
    gh::oracle::SampleOptions options;
    options.seed = seed;
    options.constructionUlps = ulps;
    const auto v = gh::oracle::sampleCheck(subject, clip, *op, result, options);
    pass = v.pass();
    std::cout << (json ? gh::tools::verdictJson(v).dump() + "\n" : gh::tools::verdictText(v));
    if (v.firstMismatch) markers.push_back({*v.firstMismatch, "#d00000", "first mismatch"});
  }
  if (!svgPath.empty()) {
    gh::io::writeText(svgPath,
                      gh::io::svgPicture({{&subject, "#c6dbef", "#2171b5", "subject"},
                                          {&clip, "#fcbba1", "#cb181d", "clip"},
                                          {&result, "#a1d99b", "#145214", "result"},
                                          {&wrong, "#ff0000", "#ff0000", "wrong faces", 0.9}},
                                         std::string("ghcheck ") + gh::name(*op).data() + ": " +
                                             (pass ? "pass" : "FAIL"),
                                         markers));
  }
  return pass ? 0 : gh::tools::kExitFailed;
}

}  // namespace

int main(int argc, char** argv) { return gh::tools::guardedMain("ghcheck", argc, argv, run); }
