// WKT through Boost.Geometry's reader and writer.
#include <boost/geometry.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/io/wkt/wkt.hpp>
#include <cctype>
#include <sstream>

#include "ghclip/errors.h"
#include "ghio/formats.h"

namespace gh::io {
namespace bg = boost::geometry;
namespace {

using BPoint = bg::model::d2::point_xy<double>;
using BPolygon = bg::model::polygon<BPoint, /*ClockWise=*/false, /*Closed=*/true>;
using BMulti = bg::model::multi_polygon<BPolygon>;

Ring toRing(const bg::model::ring<BPoint, false, true>& r) {
  Ring ring;
  ring.reserve(r.size());
  for (const BPoint& p : r) ring.push_back({p.x(), p.y()});
  return ring;
}

void append(const BPolygon& poly, Region& out) {
  if (!poly.outer().empty()) out.push_back(toRing(poly.outer()));
  for (const auto& inner : poly.inners()) out.push_back(toRing(inner));
}

std::string leadingKeyword(std::string_view text) {
  std::string word;
  std::size_t i = 0;
  while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
  while (i < text.size() && std::isalpha(static_cast<unsigned char>(text[i]))) {
    word += static_cast<char>(std::toupper(static_cast<unsigned char>(text[i++])));
  }
  return word;
}

}  // namespace

Region readWkt(std::string_view text) {
  const std::string keyword = leadingKeyword(text);
  // Boost's tokenizer splits on ' ' only: turn other blanks (newlines, tabs) into spaces and
  // trim, so multi-line WKT and files ending in a newline read as expected.
  std::string s(text);
  for (char& c : s) {
    if (std::isspace(static_cast<unsigned char>(c))) c = ' ';
  }
  s.erase(0, s.find_first_not_of(' '));
  s.erase(s.find_last_not_of(' ') + 1);
  Region out;
  try {
    if (keyword == "POLYGON") {
      BPolygon poly;
      bg::read_wkt(s, poly);
      append(poly, out);
    } else if (keyword == "MULTIPOLYGON") {
      BMulti multi;
      bg::read_wkt(s, multi);
      for (const BPolygon& poly : multi) append(poly, out);
    } else {
      throw InvalidInput("WKT: expected POLYGON or MULTIPOLYGON, found '" +
                         keyword.substr(0, 40) + "'");
    }
  } catch (const bg::read_wkt_exception& e) {
    std::string what = e.what();
    for (char& c : what) {
      if (c == '\n' || c == '\r') c = ' ';
    }
    throw InvalidInput("WKT: " + what.substr(0, 200));
  } catch (const boost::bad_lexical_cast&) {
    throw InvalidInput("WKT: a coordinate is not a number");
  }
  return out;
}

std::string writeWkt(const Region& region) {
  BMulti multi;
  for (const Ring& ring : region) {
    BPolygon poly;
    for (const Point& p : ring) poly.outer().push_back(BPoint(p.x, p.y));
    if (!ring.empty()) poly.outer().push_back(BPoint(ring.front().x, ring.front().y));
    multi.push_back(std::move(poly));
  }
  std::ostringstream s;
  s.precision(17);  // round-trips every double
  s << bg::wkt(multi);
  return s.str();
}

}  // namespace gh::io
