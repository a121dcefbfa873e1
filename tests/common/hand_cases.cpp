#include "hand_cases.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "ghio/formats.h"

namespace gh::test {
namespace {

std::vector<HandCase> read(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::vector<HandCase> out;
  std::string line;
  int lineNumber = 0;
  auto fail = [&](const std::string& why) {
    throw std::runtime_error(path + ":" + std::to_string(lineNumber) + ": " + why);
  };
  while (std::getline(in, line)) {
    ++lineNumber;
    if (line.empty() || line[0] == '#') continue;
    const auto colon = line.find(": ");
    if (colon == std::string::npos) fail("expected 'key: value'");
    const std::string key = line.substr(0, colon), value = line.substr(colon + 2);
    if (key == "case") {
      out.emplace_back();
      out.back().name = value;
      continue;
    }
    if (out.empty()) fail("'" + key + "' before the first case");
    HandCase& c = out.back();
    if (key == "subject") {
      c.subject = io::readWkt(value);
    } else if (key == "clip") {
      c.clip = io::readWkt(value);
    } else if (key == "areas") {
      std::istringstream s(value);
      std::string bar;
      if (!(s >> c.areaSubject >> c.areaClip >> bar) || bar != "|") fail("areas: expected 'S C | ...'");
      for (double& a : c.expected) {
        if (!(s >> a)) fail("areas: expected five operation areas after '|'");
      }
    } else if (key == "rings") {
      c.intersectionRings = std::stoi(value);
    } else {
      fail("unknown key '" + key + "'");
    }
  }
  if (out.empty()) throw std::runtime_error(path + ": no cases");
  return out;
}

}  // namespace

const std::vector<HandCase>& handCases() {
  static const std::vector<HandCase> cases = read(GHCLIP_HAND_CASES);
  return cases;
}

const HandCase& handCase(const std::string& name) {
  for (const HandCase& c : handCases()) {
    if (c.name == name) return c;
  }
  throw std::out_of_range("no hand case named " + name);
}

}  // namespace gh::test
