// WKT POLYGON and MULTIPOLYGON (read also inside a GEOMETRYCOLLECTION, and after PostGIS's
// "SRID=n;"): read and written with std::from_chars / std::to_chars (shortest round-trip form).
// Boost.Geometry's reader, used before, took 3x GEOS's time and read "POLYGON((0 0 1, ...))" as
// twice as many XY points; this one knows Z, M and ZM.
#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <string>

#include "ghclip/errors.h"
#include "ghio/formats.h"
#include "number_text.h"

namespace gh::io {
namespace {

class WktReader {
 public:
  explicit WktReader(std::string_view text) : s_(text) {}

  Region read() {
    srid();
    Region out;
    geometry(out, 0);
    skipBlanks();
    if (i_ != s_.size()) fail("unexpected text after the geometry");
    return out;
  }

 private:
  // Collections nest at most this deep: deeper text is refused, not followed down the stack.
  static constexpr int kMaxDepth = 64;

  // PostGIS's extended WKT starts "SRID=4326;": the reference system is not ours to use.
  void srid() {
    const std::size_t mark = i_;
    if (word() != "SRID" || !accept('=')) {
      i_ = mark;
      return;
    }
    skipBlanks();
    const std::size_t digits = i_;
    while (i_ < s_.size() && (std::isdigit(static_cast<unsigned char>(s_[i_])) || (i_ == digits && s_[i_] == '-'))) ++i_;
    if (i_ == digits) fail("expected the SRID's number");
    expect(';');
  }

  // A POLYGON, a MULTIPOLYGON, or a GEOMETRYCOLLECTION of them (PostGIS's ST_Collect writes
  // those), each with its own Z, M or ZM tag; all their rings pooled into out.
  void geometry(Region& out, int depth) {
    const std::string keyword = word();
    if (keyword != "POLYGON" && keyword != "MULTIPOLYGON" && keyword != "GEOMETRYCOLLECTION") {
      const char* expected = depth ? "expected POLYGON or MULTIPOLYGON in the collection" : "expected POLYGON or MULTIPOLYGON";
      fail(keyword.empty() ? expected : std::string(expected) + ", found '" + keyword.substr(0, 40) + "'");
    }
    if (keyword == "GEOMETRYCOLLECTION" && depth == kMaxDepth) {
      fail("collections nested more than " + std::to_string(kMaxDepth) + " deep");
    }
    dimensions_ = 2;
    std::size_t mark = i_;
    const std::string tag = word();
    if (tag == "Z" || tag == "M") {
      dimensions_ = 3;
    } else if (tag == "ZM") {
      dimensions_ = 4;
    } else {
      i_ = mark;  // not a tag: EMPTY or '('
    }
    tagged_ = dimensions_ != 2;
    if (empty()) return;
    if (keyword == "POLYGON") {
      polygon(out);
    } else if (keyword == "MULTIPOLYGON") {
      expect('(');
      do {
        if (!empty()) polygon(out);
      } while (accept(','));
      expect(')');
    } else {
      expect('(');
      do geometry(out, depth + 1);
      while (accept(','));
      expect(')');
    }
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw InvalidInput("WKT: " + what + " (at character " + std::to_string(i_ + 1) + ")");
  }
  void skipBlanks() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }
  std::string word() {
    skipBlanks();
    std::string w;
    while (i_ < s_.size() && std::isalpha(static_cast<unsigned char>(s_[i_]))) {
      w += static_cast<char>(std::toupper(static_cast<unsigned char>(s_[i_++])));
    }
    return w;
  }
  bool empty() {
    const std::size_t mark = i_;
    if (word() == "EMPTY") return true;
    i_ = mark;
    return false;
  }
  bool accept(char c) {
    skipBlanks();
    if (i_ < s_.size() && s_[i_] == c) {
      ++i_;
      return true;
    }
    return false;
  }
  void expect(char c) {
    if (!accept(c)) fail(std::string("expected '") + c + "'");
  }
  void polygon(Region& out) {
    expect('(');
    do {
      if (!empty()) ring(out);
    } while (accept(','));
    expect(')');
  }
  void ring(Region& out) {
    expect('(');
    Ring r;
    // Room for every point up to the ring's ')' at once: growing a 10^6-point ring by doubling
    // copied it about twenty times.
    const std::size_t close = s_.find(')', i_);
    const std::string_view body = s_.substr(i_, close == std::string_view::npos ? std::string_view::npos : close - i_);
    r.reserve(static_cast<std::size_t>(std::count(body.begin(), body.end(), ',')) + 1);
    do r.push_back(point());
    while (accept(','));
    expect(')');
    out.push_back(std::move(r));
  }
  Point point() {
    double c[4];
    int n = 0;
    for (;;) {
      skipBlanks();
      if (i_ >= s_.size() || s_[i_] == ',' || s_[i_] == ')') break;
      if (n == 4) fail("a point has more than 4 coordinates");
      const auto parsed = parseNumber(s_.substr(i_));
      if (!parsed) fail("a coordinate is not a number");
      c[n++] = parsed->value;
      i_ += parsed->length;
    }
    if (n != dimensions_) {
      if (!tagged_ && (n == 3 || n == 4)) {
        fail("a point has " + std::to_string(n) + " coordinates: tag the geometry Z, M or ZM (only x and y are used)");
      }
      fail("a point has " + std::to_string(n) + " coordinates, expected " + std::to_string(dimensions_));
    }
    return {c[0], c[1]};
  }

  std::string_view s_;
  std::size_t i_ = 0;
  int dimensions_ = 2;
  bool tagged_ = false;
};

void appendRing(std::string& out, const Ring& ring) {
  if (ring.empty()) {
    out += "EMPTY";
    return;
  }
  out += '(';
  for (const Point& p : ring) {
    appendNumber(out, p.x);
    out += ' ';
    appendNumber(out, p.y);
    out += ',';
  }
  appendNumber(out, ring.front().x);  // closed, as WKT requires
  out += ' ';
  appendNumber(out, ring.front().y);
  out += ')';
}

}  // namespace

Region readWkt(std::string_view text) { return WktReader(text).read(); }

std::string writeWkt(const Region& region) {
  std::vector<PolygonWithHoles> polygons;
  polygons.reserve(region.size());
  for (const Ring& ring : region) {
    if (!ring.empty()) polygons.push_back({ring, {}});
  }
  return writeWkt(polygons);
}

std::string writeWkt(const std::vector<PolygonWithHoles>& polygons) {
  if (polygons.empty()) return "MULTIPOLYGON EMPTY";
  std::string out;
  std::size_t vertices = 0;
  for (const auto& p : polygons) {
    vertices += p.shell.size() + 1;
    for (const Ring& h : p.holes) vertices += h.size() + 1;
  }
  out.reserve(16 + vertices * 40);
  out += "MULTIPOLYGON(";
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    if (i) out += ',';
    out += '(';
    appendRing(out, polygons[i].shell);
    for (const Ring& h : polygons[i].holes) {
      out += ',';
      appendRing(out, h);
    }
    out += ')';
  }
  out += ')';
  return out;
}

}  // namespace gh::io
