// GeoJSON read with simdjson, written with RapidJSON's streaming writer: Polygon, MultiPolygon, GeometryCollection, Feature,
// FeatureCollection; every ring of every polygon is pooled into one even-odd region.
#include <rapidjson/stringbuffer.h>
#include <rapidjson/writer.h>
#include <simdjson.h>

#include "ghclip/errors.h"
#include "ghio/formats.h"

#include <vector>

namespace gh::io {
namespace {

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
// Writing streams through RapidJSON's Writer: no document is built (nlohmann-json has no streaming
// writer, and its DOM of a million positions cost half the time of writing). Its doubles are
// Grisu2's, digits that read back to the same double. The text is reserved whole up front: a
// string grown by doubling spent a third of the time copying and faulting in pages.
class GeoJsonWriter {
 public:
  explicit GeoJsonWriter(std::size_t points) {
    constexpr std::size_t kMostCharactersPerPoint = 2 * 25 + 4;  // two doubles and "[,],"
    buffer_.Reserve(points * kMostCharactersPerPoint + 256);
  }

  void key(const char* k) { writer_.Key(k); }
  void string(const char* s) { writer_.String(s); }
  void startObject() { writer_.StartObject(); }
  void endObject() { writer_.EndObject(); }
  void startArray() { writer_.StartArray(); }
  void endArray() { writer_.EndArray(); }

  // Each inner list is one polygon: its shell, then its holes.
  void multiPolygon(const std::vector<std::vector<const Ring*>>& polygons) {
    startObject();
    key("type");
    string("MultiPolygon");
    key("coordinates");
    startArray();
    for (const auto& rings : polygons) {
      startArray();
      for (const Ring* r : rings) ring(*r);
      endArray();
    }
    endArray();
    endObject();
  }

  std::string text() const { return {buffer_.GetString(), buffer_.GetSize()}; }

 private:
  void ring(const Ring& r) {
    startArray();
    for (const Point& p : r) position(p);
    if (!r.empty()) position(r.front());  // GeoJSON closes its rings
    endArray();
  }

  void position(const Point& p) {
    startArray();
    number(p.x);
    number(p.y);
    endArray();
  }

  void number(double v) {
    // Regions hold finite coordinates; a writer that refuses one must not leave a half document.
    if (!writer_.Double(v)) throw InvalidInput("GeoJSON: cannot write the coordinate " + std::to_string(v));
  }

  rapidjson::StringBuffer buffer_;
  rapidjson::Writer<rapidjson::StringBuffer> writer_{buffer_};
};

std::size_t pointsIn(const Region& region) {
  std::size_t n = 0;
  for (const Ring& r : region) n += r.size() + 1;
  return n;
}

// The raw rings: each ring a polygon of its own (reading them even-odd is the reader's part).
std::vector<std::vector<const Ring*>> ringsAsPolygons(const Region& region) {
  std::vector<std::vector<const Ring*>> polygons;
  polygons.reserve(region.size());
  for (const Ring& r : region) polygons.push_back({&r});
  return polygons;
}
}  // namespace

std::string writeGeoJson(const Region& region) {
  GeoJsonWriter out(pointsIn(region));
  out.multiPolygon(ringsAsPolygons(region));
  return out.text();
}

std::string writeGeoJson(const std::vector<PolygonWithHoles>& polygons) {
  std::vector<std::vector<const Ring*>> rings;
  rings.reserve(polygons.size());
  std::size_t points = 0;
  for (const PolygonWithHoles& p : polygons) {
    rings.push_back({&p.shell});
    points += p.shell.size() + 1;
    for (const Ring& h : p.holes) {
      rings.back().push_back(&h);
      points += h.size() + 1;
    }
  }
  GeoJsonWriter out(points);
  out.multiPolygon(rings);
  return out.text();
}

std::string writeGeoJsonPair(const Region& subject, const Region& clip) {
  GeoJsonWriter out(pointsIn(subject) + pointsIn(clip));
  out.startObject();
  out.key("type");
  out.string("FeatureCollection");
  out.key("features");
  out.startArray();
  for (const auto& [name, region] : {std::pair{"subject", &subject}, std::pair{"clip", &clip}}) {
    out.startObject();
    out.key("type");
    out.string("Feature");
    out.key("properties");
    out.startObject();
    out.key("name");
    out.string(name);
    out.endObject();
    out.key("geometry");
    out.multiPolygon(ringsAsPolygons(*region));
    out.endObject();
  }
  out.endArray();
  out.endObject();
  return out.text();
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
