#include "verdict_json.h"

#include <sstream>

namespace gh::tools {

nlohmann::json verdictJson(const oracle::ExactVerdict& v) {
  nlohmann::json j = {{"oracle", "exact"},
                      {"verdict", v.pass ? "pass" : "fail"},
                      {"expected_area", v.expectedArea},
                      {"result_area", v.resultArea},
                      {"error_area", v.errorArea},
                      {"error_area_exact", v.errorAreaExact.empty() ? nlohmann::json() : nlohmann::json(v.errorAreaExact)},
                      {"relative_error", v.relativeError()},
                      {"beyond_rounding_area", v.beyondRoundingArea},
                      {"beyond_rounding_area_exact", v.beyondRoundingAreaExact.empty() ? nlohmann::json() : nlohmann::json(v.beyondRoundingAreaExact)},
                      {"relative_beyond_rounding", v.relativeBeyondRounding()},
                      {"rounding_zones", v.zones},
                      {"faces", v.faces},
                      {"vertices", v.vertices},
                      {"edges", v.edges},
                      {"seconds", v.seconds}};
  j["witness"] = v.witness ? nlohmann::json::array({v.witness->x, v.witness->y}) : nlohmann::json();
  return j;
}

nlohmann::json verdictJson(const oracle::SampleVerdict& v) {
  nlohmann::json j = {{"oracle", "sample"},       {"verdict", v.pass() ? "pass" : "fail"},
                      {"checked", v.checked},     {"skipped", v.skipped},
                      {"mismatched", v.mismatched}, {"delta", v.delta},
                      {"seconds", v.seconds}};
  j["first_mismatch"] = v.firstMismatch
                            ? nlohmann::json::array({v.firstMismatch->x, v.firstMismatch->y})
                            : nlohmann::json();
  return j;
}

std::string verdictText(const oracle::ExactVerdict& v) {
  std::ostringstream s;
  s.precision(17);
  s << "verdict: " << (v.pass ? "pass" : "fail") << " (exact oracle)\n"
    << "expected area: " << v.expectedArea << "\n"
    << "result area: " << v.resultArea << "\n"
    << "error area: " << v.errorArea
    << (v.errorAreaExact.size() <= 60 ? " (exactly " + v.errorAreaExact + ")"
                                      : " (an exact rational of " +
                                            std::to_string(v.errorAreaExact.size()) +
                                            " characters; --json prints it)")
    << "\n"
    << "relative error: " << v.relativeError() << "\n"
    << "beyond rounding: " << v.beyondRoundingArea
    << (v.pass ? (v.errorArea > 0 ? " (every wrong face lies in the rounding zones of the exact answer's constructed vertices)" : "")
               : " (wrong faces outside every rounding zone)")
    << "\n";
  if (v.witness) s << "witness: " << v.witness->x << ' ' << v.witness->y << "\n";
  s << "arrangement: " << v.faces << " faces, " << v.vertices << " vertices, " << v.edges
    << " edges in " << v.seconds << " s\n";
  return s.str();
}

std::string verdictText(const oracle::SampleVerdict& v) {
  std::ostringstream s;
  s.precision(17);
  s << "verdict: " << (v.pass() ? "pass" : "fail") << " (sampling oracle)\n"
    << "checked: " << v.checked << ", skipped: " << v.skipped << " (within " << v.delta
    << " of an edge of S or C, or on an edge of R), mismatched: " << v.mismatched << "\n";
  if (v.firstMismatch) s << "first mismatch: " << v.firstMismatch->x << ' ' << v.firstMismatch->y << "\n";
  s << "time: " << v.seconds << " s\n";
  return s.str();
}

}  // namespace gh::tools
