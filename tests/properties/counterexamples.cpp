#include "counterexamples.h"

#include <cstdlib>
#include <fstream>
#include <functional>
#include <sstream>

#include "ghclip/clip.h"
#include "ghclip/errors.h"
#include "ghio/formats.h"
#include "ghio/svg.h"

namespace gh::props {
namespace fs = std::filesystem;

namespace {

std::string bits(const std::vector<bool>& v) {
  std::string s;
  for (bool b : v) s += b ? '1' : '0';
  return s;
}

std::vector<bool> unbits(const std::string& s) {
  std::vector<bool> v;
  for (char c : s) v.push_back(c == '1');
  return v;
}

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r");
  const auto b = s.find_last_not_of(" \t\r");
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

}  // namespace

fs::path counterexampleDir() {
  const char* dir = std::getenv("GHCLIP_COUNTEREXAMPLES");
  return dir && *dir ? fs::path(dir) : fs::path("counterexamples");
}

fs::path writeCounterexample(const Counterexample& c) {
  std::ostringstream body;
  body << "# property: " << c.property << "\n# family: " << c.family << "\n# variant: " << c.variant
       << "\n# op: " << name(c.input.op) << "\n";
  if (c.bitset) {
    body << "# bitset: " << c.bitset->grid.size << ' ' << bits(c.bitset->grid.subject) << ' '
         << bits(c.bitset->grid.clip) << "\n";
  }
  std::string violation = c.violation;
  for (char& ch : violation) {
    if (ch == '\n') ch = ' ';
  }
  body << "# violation: " << violation << "\n"
       << io::writeWkt(c.input.subject) << "\n" << io::writeWkt(c.input.clip) << "\n";
  std::ostringstream hash;
  hash << std::hex << (std::hash<std::string>()(io::writeWkt(c.input.subject) + io::writeWkt(c.input.clip) +
                                                std::string(name(c.input.op))) & 0xffffffffu);
  const fs::path dir = counterexampleDir() / c.variant;
  fs::create_directories(dir);
  const fs::path wkt = dir / (c.property + "-" + c.family + "-" + hash.str() + ".wkt");
  io::writeText(wkt.string(), body.str());

  Region result;
  std::string label = std::string(name(c.input.op)) + " by " + c.variant;
  try {
    Options o = optionsOf(*parseVariant(c.variant));
    result = clip(c.input.subject, c.input.clip, c.input.op, o);
  } catch (const std::exception& e) {
    label += " (failed: " + std::string(e.what()) + ")";
  }
  fs::path svg = wkt;
  svg.replace_extension(".svg");
  io::writeText(svg.string(), io::svgPicture({{&c.input.subject, "#c6dbef", "#2171b5", "subject"},
                                              {&c.input.clip, "#fcbba1", "#cb181d", "clip"},
                                              {&result, "#a1d99b", "#145214", label}},
                                             c.property + " (" + c.family + "): " + violation.substr(0, 120)));
  return wkt;
}

Counterexample readCounterexample(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw InvalidInput(file.string() + ": cannot open");
  Counterexample c;
  std::vector<std::string> geometry;
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("# ", 0) == 0) {
      const auto colon = line.find(':');
      if (colon == std::string::npos) continue;
      const std::string key = trim(line.substr(2, colon - 2)), value = trim(line.substr(colon + 1));
      if (key == "property") c.property = value;
      if (key == "family") c.family = value;
      if (key == "variant") c.variant = value;
      if (key == "violation") c.violation = value;
      if (key == "op") c.input.op = parseOp(value).value_or(Op::Intersection);
      if (key == "bitset") {
        std::istringstream s(value);
        BitsetCase b;
        std::string sb, cb;
        s >> b.grid.size >> sb >> cb;
        b.grid.subject = unbits(sb);
        b.grid.clip = unbits(cb);
        c.bitset = b;
      }
    } else if (!trim(line).empty()) {
      geometry.push_back(line);
    }
  }
  if (geometry.size() != 2) throw InvalidInput(file.string() + ": expected two WKT lines");
  c.input.subject = io::readWkt(geometry[0]);
  c.input.clip = io::readWkt(geometry[1]);
  if (c.bitset) c.bitset->op = c.input.op;
  return c;
}

std::vector<ExpectedFailure> expectedFailures(const fs::path& file) {
  std::vector<ExpectedFailure> out;
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    if (trim(line).empty() || trim(line)[0] == '#') continue;
    const auto bar = line.find('|');
    std::istringstream head(line.substr(0, bar));
    ExpectedFailure e;
    head >> e.variant >> e.property >> e.family;
    e.reason = bar == std::string::npos ? "" : trim(line.substr(bar + 1));
    out.push_back(e);
  }
  return out;
}

const ExpectedFailure* findExpected(const std::vector<ExpectedFailure>& list, const std::string& variant,
                                    const std::string& property, const std::string& family) {
  for (const ExpectedFailure& e : list) {
    if (e.variant == variant && e.property == property && e.family == family) return &e;
  }
  return nullptr;
}

}  // namespace gh::props
