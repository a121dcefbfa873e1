// GeoJSON through nlohmann-json: Polygon, MultiPolygon, GeometryCollection, Feature,
// FeatureCollection; every ring of every polygon is pooled into one even-odd region.
#include <nlohmann/json.hpp>

#include "ghclip/errors.h"
#include "ghio/formats.h"

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

std::string writeGeoJson(const Region& region) {
  json polys = json::array();
  for (const Ring& ring : region) {
    json coords = json::array();
    for (const Point& p : ring) coords.push_back({p.x, p.y});
    if (!ring.empty()) coords.push_back({ring.front().x, ring.front().y});
    polys.push_back(json::array({coords}));
  }
  return json{{"type", "MultiPolygon"}, {"coordinates", polys}}.dump();
}

}  // namespace gh::io
