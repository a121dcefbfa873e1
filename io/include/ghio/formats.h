// Reading and writing regions: WKT (POLYGON, MULTIPOLYGON) and GeoJSON.
//
// Readers pool every ring of every polygon into one region under the even-odd rule: OGC's
// shell/hole structure is not needed (a hole is a ring inside another ring) and is not checked.
// Writers emit a MultiPolygon in one of two layouts: `Ogc` (the default of the tools), polygons
// with holes as the library lays them out (ghclip/ogc_layout.h), or `Rings`, one polygon per ring,
// the raw Greiner-Hormann rings, which only an even-odd reader reads right. Either reads back with
// these readers as the same region. An empty answer is MULTIPOLYGON EMPTY / an empty MultiPolygon.
// Every coordinate is written as the shortest text that reads back as the same double.
// WKT may carry Z, M or ZM (ignored); untagged 3-number points are refused.
// Bad text throws gh::InvalidInput with a one-line message.
#pragma once

#include <string>
#include <string_view>

#include <vector>

#include "ghclip/polygons_with_holes.h"
#include "ghclip/region.h"
#include "ghio/output_files.h"

namespace gh::io {

enum class Format { Wkt, GeoJson };
enum class Layout { Ogc, Rings };

Region readWkt(std::string_view text);
Region readGeoJson(std::string_view text);
// GeoJSON when the first non-blank character is '{', WKT otherwise.
Region readAuto(std::string_view text);

std::string writeWkt(const Region& region);  // one polygon per ring
std::string writeGeoJson(const Region& region);
std::string writeWkt(const std::vector<PolygonWithHoles>& polygons);
std::string writeGeoJson(const std::vector<PolygonWithHoles>& polygons);
std::string write(const std::vector<PolygonWithHoles>& polygons, Format format);
// Rings: one polygon per ring; Ogc: the rings laid out by gh::ogcLayout (which knows nothing of
// where they came from: a clip's own polygons, Clipping::polygons, are what the tools write).
std::string write(const Region& region, Format format, Layout layout = Layout::Rings);
// A FeatureCollection of two features, {"name": "subject"} and {"name": "clip"}.
std::string writeGeoJsonPair(const Region& subject, const Region& clip);
// Reads a pair written by ghgen: two WKT lines, or a two-feature FeatureCollection.
struct RegionPair {
  Region subject, clip;
};
RegionPair readPair(std::string_view text);

// Reads a whole file ("-" is standard input) as text; InvalidInput if it cannot be read.
std::string readText(const std::string& path);


}  // namespace gh::io
