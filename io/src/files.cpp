#include <cctype>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "ghclip/errors.h"
#include "ghio/formats.h"
#include "ghclip/ogc_layout.h"

namespace gh::io {

Region readAuto(std::string_view text) {
  for (char c : text) {
    if (std::isspace(static_cast<unsigned char>(c))) continue;
    return c == '{' ? readGeoJson(text) : readWkt(text);
  }
  throw InvalidInput("empty input (expected WKT or GeoJSON)");
}

std::string write(const std::vector<PolygonWithHoles>& polygons, Format format) {
  return format == Format::GeoJson ? writeGeoJson(polygons) : writeWkt(polygons);
}

std::string write(const Region& region, Format format, Layout layout) {
  if (layout == Layout::Ogc) return write(ogcLayout(region), format);
  return format == Format::GeoJson ? writeGeoJson(region) : writeWkt(region);
}

std::string readText(const std::string& path) {
  // Whole reads into one buffer: a stream's rdbuf copy grows its buffer again and again (a
  // quarter of ghclip's time on 10^6 vertices went to those copies).
  const int fd = path == "-" ? STDIN_FILENO : ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw InvalidInput(std::string("cannot open for reading: ") + std::strerror(errno));
  struct stat st {};
  if (::fstat(fd, &st) == 0 && S_ISDIR(st.st_mode)) {
    ::close(fd);
    throw InvalidInput("is a directory");
  }
  std::string text;
  std::size_t used = 0;
  text.resize(S_ISREG(st.st_mode) ? static_cast<std::size_t>(st.st_size) + 1 : std::size_t{1} << 16);
  for (;;) {
    if (used == text.size()) text.resize(text.size() * 2);
    const ssize_t n = ::read(fd, text.data() + used, text.size() - used);
    if (n < 0) {
      if (errno == EINTR) continue;
      const int error = errno;
      if (fd != STDIN_FILENO) ::close(fd);
      throw InvalidInput(std::string("read error: ") + std::strerror(error));
    }
    if (n == 0) break;
    used += static_cast<std::size_t>(n);
  }
  if (fd != STDIN_FILENO) ::close(fd);
  text.resize(used);
  return text;
}

}  // namespace gh::io
