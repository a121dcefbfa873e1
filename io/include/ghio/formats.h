// Reading and writing regions: WKT (POLYGON, MULTIPOLYGON) and GeoJSON.
//
// Readers pool every ring of every polygon into one region under the even-odd rule: OGC's
// shell/hole structure is not needed (a hole is a ring inside another ring) and is not checked.
// Writers emit one polygon per ring (MULTIPOLYGON / GeoJSON MultiPolygon), closed as WKT
// requires; read back with these readers, that is the same region.
// Bad text throws gh::InvalidInput with a one-line message.
#pragma once

#include <string>
#include <string_view>

#include "ghclip/region.h"

namespace gh::io {

enum class Format { Wkt, GeoJson };

Region readWkt(std::string_view text);
Region readGeoJson(std::string_view text);
// GeoJSON when the first non-blank character is '{', WKT otherwise.
Region readAuto(std::string_view text);

std::string writeWkt(const Region& region);
std::string writeGeoJson(const Region& region);
std::string write(const Region& region, Format format);
// A FeatureCollection of two features, {"name": "subject"} and {"name": "clip"}.
std::string writeGeoJsonPair(const Region& subject, const Region& clip);
// Reads a pair written by ghgen: two WKT lines, or a two-feature FeatureCollection.
struct RegionPair {
  Region subject, clip;
};
RegionPair readPair(std::string_view text);

// Reads a whole file ("-" is standard input) as text; InvalidInput if it cannot be read.
std::string readText(const std::string& path);

// Writes text to path atomically (temporary file, then rename), so a failure leaves no
// half-written file; "-" writes standard output.
void writeText(const std::string& path, const std::string& text);

}  // namespace gh::io
