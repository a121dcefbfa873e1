// GeoJSON read with simdjson, written with nlohmann-json: Polygon, MultiPolygon, GeometryCollection, Feature,
// FeatureCollection; every ring of every polygon is pooled into one even-odd region.
#include <nlohmann/json.hpp>
#include <simdjson.h>

#include "ghclip/errors.h"
#include "ghio/formats.h"

#include <vector>

namespace gh::io {
namespace {

using nlohmann::json;
namespace sj = simdjson::dom;

// Reading with simdjson (its DOM parser: several times nlohmann-json's speed and GEOS's), the
// same structure and messages as before.
[[noreturn]] void bad(const std::string& what) { throw InvalidInput("GeoJSON: " + what); }

double number(const sj::element& e) {
  switch (e.type()) {
    case sj::element_type::DOUBLE: return double(e);
    case sj::element_type::INT64: return static_cast<double>(int64_t(e));
    case sj::element_type::UINT64: return static_cast<double>(uint64_t(e));
    default: bad("a position is not an array of two numbers");
  }
}

Ring readRing(const sj::element& coords) {
  sj::array positions;
  if (coords.get(positions)) bad("a ring is not an array of positions");
  Ring ring;
  ring.reserve(positions.size());
  for (sj::element pos : positions) {
    sj::array xy;
    if (pos.get(xy) || xy.size() < 2) bad("a position is not an array of two numbers");
    ring.push_back({number(xy.at(0).value_unsafe()), number(xy.at(1).value_unsafe())});
  }
  return ring;
}

void readPolygon(const sj::element& rings, Region& out) {
  sj::array array;
  if (rings.get(array)) bad("Polygon coordinates are not an array");
  for (sj::element r : array) out.push_back(readRing(r));
}

void readGeometry(const sj::element& g, Region& out, int depth) {
  if (depth > 64) bad("nesting too deep");
  sj::object object;
  std::string_view type;
  if (g.get(object) || object["type"].get(type)) bad("expected an object with a \"type\"");
  auto member = [&](const char* key) {
    sj::element e;
    if (object[key].get(e)) bad(std::string(type) + " without \"" + key + "\"");
    return e;
  };
  if (type == "Polygon") {
    readPolygon(member("coordinates"), out);
  } else if (type == "MultiPolygon") {
    sj::array polys;
    if (member("coordinates").get(polys)) bad("MultiPolygon coordinates are not an array");
    for (sj::element p : polys) readPolygon(p, out);
  } else if (type == "GeometryCollection") {
    sj::array gs;
    if (member("geometries").get(gs)) bad("geometries is not an array");
    for (sj::element x : gs) readGeometry(x, out, depth + 1);
  } else if (type == "Feature") {
    const sj::element geometry = member("geometry");
    if (!geometry.is_null()) readGeometry(geometry, out, depth + 1);
  } else if (type == "FeatureCollection") {
    sj::array fs;
    if (member("features").get(fs)) bad("features is not an array");
    for (sj::element f : fs) readGeometry(f, out, depth + 1);
  } else {
    bad("unsupported type '" + std::string(type.substr(0, 40)) +
        "' (Polygon, MultiPolygon, GeometryCollection, Feature, FeatureCollection)");
  }
}

sj::element parse(sj::parser& parser, std::string_view text) {
  sj::element doc;
  if (const auto error = parser.parse(text.data(), text.size()).get(doc)) {
    throw InvalidInput(std::string("GeoJSON: ") + simdjson::error_message(error));
  }
  return doc;
}

}  // namespace

Region readGeoJson(std::string_view text) {
  // One parser per thread, kept: its buffers are reused (fresh ones cost a page fault per 4 KiB).
  thread_local sj::parser parser;
  Region out;
  readGeometry(parse(parser, text), out, 0);
  return out;
}

namespace {
json multiPolygon(const Region& region) {
  json polys = json::array();
  for (const Ring& ring : region) {
    json coords = json::array();
    for (const Point& p : ring) coords.push_back({p.x, p.y});
    if (!ring.empty()) coords.push_back({ring.front().x, ring.front().y});
    polys.push_back(json::array({coords}));
  }
  return json{{"type", "MultiPolygon"}, {"coordinates", polys}};
}
}  // namespace

std::string writeGeoJson(const Region& region) { return multiPolygon(region).dump(); }

std::string writeGeoJson(const std::vector<PolygonWithHoles>& polygons) {
  auto ring = [](const Ring& r) {
    json coords = json::array();
    for (const Point& p : r) coords.push_back({p.x, p.y});
    if (!r.empty()) coords.push_back({r.front().x, r.front().y});
    return coords;
  };
  json polys = json::array();
  for (const PolygonWithHoles& p : polygons) {
    json rings = json::array({ring(p.shell)});
    for (const Ring& h : p.holes) rings.push_back(ring(h));
    polys.push_back(std::move(rings));
  }
  return json{{"type", "MultiPolygon"}, {"coordinates", polys}}.dump();
}

std::string writeGeoJsonPair(const Region& subject, const Region& clip) {
  json features = json::array();
  for (const auto& [name, region] : {std::pair{"subject", &subject}, std::pair{"clip", &clip}}) {
    features.push_back(
        {{"type", "Feature"}, {"properties", {{"name", name}}}, {"geometry", multiPolygon(*region)}});
  }
  return json{{"type", "FeatureCollection"}, {"features", features}}.dump();
}

RegionPair readPair(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first != std::string_view::npos && text[first] == '{') {
    sj::parser parser;
    const sj::element doc = parse(parser, text);
    sj::array features;
    if (doc["features"].get(features) || features.size() != 2) {
      throw InvalidInput("GeoJSON pair: expected a FeatureCollection of two features");
    }
    RegionPair p;
    readGeometry(features.at(0).value_unsafe(), p.subject, 0);
    readGeometry(features.at(1).value_unsafe(), p.clip, 0);
    return p;
  }
  // Two WKT geometries, one per line.
  std::string_view rest = text;
  std::vector<std::string> lines;
  while (!rest.empty()) {
    const auto nl = rest.find('\n');
    const std::string line(rest.substr(0, nl));
    if (line.find_first_not_of(" \t\r") != std::string::npos) lines.push_back(line);
    if (nl == std::string_view::npos) break;
    rest.remove_prefix(nl + 1);
  }
  if (lines.size() != 2) throw InvalidInput("WKT pair: expected two non-empty lines");
  return {readWkt(lines[0]), readWkt(lines[1])};
}

}  // namespace gh::io
