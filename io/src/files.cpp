#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <unistd.h>

#include "ghclip/errors.h"
#include "ghio/formats.h"

namespace gh::io {

Region readAuto(std::string_view text) {
  for (char c : text) {
    if (std::isspace(static_cast<unsigned char>(c))) continue;
    return c == '{' ? readGeoJson(text) : readWkt(text);
  }
  throw InvalidInput("empty input (expected WKT or GeoJSON)");
}

std::string write(const Region& region, Format format) {
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

void writeText(const std::string& path, const std::string& text) {
  if (path == "-") {
    std::cout << text << '\n';
    std::cout.flush();
    return;
  }
  const std::string tmp = path + ".tmp" + std::to_string(::getpid());
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot write " + path);
    out << text << '\n';
    out.close();
    if (!out) {
      std::remove(tmp.c_str());
      throw std::runtime_error("cannot write " + path);
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::remove(tmp.c_str());
    throw std::runtime_error("cannot write " + path + ": " + ec.message());
  }
}

}  // namespace gh::io
