#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <unistd.h>

#include "ghclip/errors.h"
#include "ghio/formats.h"
#include "ghio/ogc_layout.h"

namespace gh::io {

Region readAuto(std::string_view text) {
  for (char c : text) {
    if (std::isspace(static_cast<unsigned char>(c))) continue;
    return c == '{' ? readGeoJson(text) : readWkt(text);
  }
  throw InvalidInput("empty input (expected WKT or GeoJSON)");
}

std::string write(const Region& region, Format format, Layout layout) {
  if (layout == Layout::Ogc) {
    const auto polygons = ogcPolygons(region);
    return format == Format::GeoJson ? writeGeoJson(polygons) : writeWkt(polygons);
  }
  return format == Format::GeoJson ? writeGeoJson(region) : writeWkt(region);
}

std::string readText(const std::string& path) {
  std::ostringstream s;
  if (path == "-") {
    s << std::cin.rdbuf();
    return s.str();
  }
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InvalidInput("is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InvalidInput("cannot open for reading");
  s << in.rdbuf();
  if (in.bad()) throw InvalidInput("read error");
  return s.str();
}

}  // namespace gh::io
