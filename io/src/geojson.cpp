// GeoJSON through nlohmann-json: Polygon, MultiPolygon, GeometryCollection, Feature,
// FeatureCollection; every ring of every polygon is pooled into one even-odd region.
#include <nlohmann/json.hpp>

#include "ghclip/errors.h"
#include "ghio/formats.h"

#include <vector>

namespace gh::io {
namespace {

using nlohmann::json;

Ring readRing(const json& coords) {
  if (!coords.is_array()) throw InvalidInput("GeoJSON: a ring is not an array of positions");
  Ring ring;
  ring.reserve(coords.size());
  for (const json& pos : coords) {
    if (!pos.is_array() || pos.size() < 2 || !pos[0].is_number() || !pos[1].is_number()) {
      throw InvalidInput("GeoJSON: a position is not an array of two numbers");
    }
    ring.push_back({pos[0].get<double>(), pos[1].get<double>()});
  }
  return ring;
}

void readPolygon(const json& rings, Region& out) {
  if (!rings.is_array()) throw InvalidInput("GeoJSON: Polygon coordinates are not an array");
  for (const json& r : rings) out.push_back(readRing(r));
}

void readGeometry(const json& g, Region& out, int depth) {
  if (depth > 64) throw InvalidInput("GeoJSON: nesting too deep");
  if (!g.is_object() || !g.contains("type") || !g["type"].is_string()) {
    throw InvalidInput("GeoJSON: expected an object with a \"type\"");
  }
  const std::string type = g["type"].get<std::string>();
  auto member = [&](const char* key) -> const json& {
    if (!g.contains(key)) throw InvalidInput("GeoJSON: " + type + " without \"" + key + "\"");
    return g[key];
  };
  if (type == "Polygon") {
    readPolygon(member("coordinates"), out);
  } else if (type == "MultiPolygon") {
    const json& polys = member("coordinates");
    if (!polys.is_array()) throw InvalidInput("GeoJSON: MultiPolygon coordinates are not an array");
    for (const json& p : polys) readPolygon(p, out);
  } else if (type == "GeometryCollection") {
    const json& gs = member("geometries");
    if (!gs.is_array()) throw InvalidInput("GeoJSON: geometries is not an array");
    for (const json& x : gs) readGeometry(x, out, depth + 1);
  } else if (type == "Feature") {
    const json& geometry = member("geometry");
    if (!geometry.is_null()) readGeometry(geometry, out, depth + 1);
  } else if (type == "FeatureCollection") {
    const json& fs = member("features");
    if (!fs.is_array()) throw InvalidInput("GeoJSON: features is not an array");
    for (const json& f : fs) readGeometry(f, out, depth + 1);
  } else {
    throw InvalidInput("GeoJSON: unsupported type '" + type.substr(0, 40) +
                       "' (Polygon, MultiPolygon, GeometryCollection, Feature, FeatureCollection)");
  }
}

}  // namespace

Region readGeoJson(std::string_view text) {
  json doc;
  try {
    doc = json::parse(text.begin(), text.end());
  } catch (const json::exception& e) {
    throw InvalidInput(std::string("GeoJSON: ") + e.what());
  }
  Region out;
  try {
    readGeometry(doc, out, 0);
  } catch (const json::exception& e) {
    throw InvalidInput(std::string("GeoJSON: ") + e.what());
  }
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
    json doc;
    try {
      doc = json::parse(text.begin(), text.end());
    } catch (const json::exception& e) {
      throw InvalidInput(std::string("GeoJSON: ") + e.what());
    }
    if (!doc.is_object() || !doc.contains("features") || !doc["features"].is_array() ||
        doc["features"].size() != 2) {
      throw InvalidInput("GeoJSON pair: expected a FeatureCollection of two features");
    }
    RegionPair p;
    readGeometry(doc["features"][0], p.subject, 0);
    readGeometry(doc["features"][1], p.clip, 0);
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
