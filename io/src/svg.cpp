// Plain SVG text: paths with fill-rule="evenodd", coordinates mapped to a fixed-size frame.
#include "ghio/svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

namespace gh::io {
namespace {

std::string escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '&': out += "&amp;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace

std::string svgPicture(const std::vector<SvgLayer>& layers, const std::string& title,
                       const std::vector<SvgMarker>& markers) {
  double minX = std::numeric_limits<double>::infinity(), minY = minX;
  double maxX = -minX, maxY = -minX;
  auto grow = [&](Point p) {
    minX = std::min(minX, p.x), maxX = std::max(maxX, p.x);
    minY = std::min(minY, p.y), maxY = std::max(maxY, p.y);
  };
  for (const SvgLayer& layer : layers) {
    for (const Ring& ring : *layer.region) {
      for (const Point& p : ring) grow(p);
    }
  }
  for (const SvgMarker& m : markers) grow(m.at);
  if (!(minX <= maxX)) minX = minY = 0, maxX = maxY = 1;
  // Extents are computed as halves so that coordinates near the double limit do not overflow.
  double extent = std::max(maxX / 2 - minX / 2, maxY / 2 - minY / 2) * 2;
  if (!(extent > 0)) extent = std::max({std::abs(maxX), std::abs(maxY), 1.0});

  const double size = 640, margin = 24, legend = 22.0 * static_cast<double>(layers.size() + 1);
  const double width = size + 2 * margin;
  const double scaleX = (maxX / 2 - minX / 2) * 2 / extent, scaleY = (maxY / 2 - minY / 2) * 2 / extent;
  const double drawW = std::max(scaleX * size, 1.0), drawH = std::max(scaleY * size, 1.0);
  const double height = drawH + 2 * margin + legend;
  auto px = [&](Point p) {
    return std::pair<double, double>{margin + (p.x - minX) / extent * size,
                                     margin + drawH - (p.y - minY) / extent * size};
  };

  std::ostringstream s;
  s.precision(7);
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << std::max(width, drawW + 2 * margin)
    << "\" height=\"" << height << "\" font-family=\"sans-serif\" font-size=\"13\">\n";
  s << "<title>" << escaped(title) << "</title>\n";
  s << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  for (const SvgLayer& layer : layers) {
    s << "<path fill-rule=\"evenodd\" fill=\"" << layer.fill << "\" fill-opacity=\""
      << layer.fillOpacity << "\" stroke=\"" << layer.stroke
      << "\" stroke-width=\"1.5\" stroke-linejoin=\"round\" d=\"";
    for (const Ring& ring : *layer.region) {
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const auto [x, y] = px(ring[i]);
        s << (i ? " L" : "M") << x << ',' << y;
      }
      if (!ring.empty()) s << " Z ";
    }
    s << "\"/>\n";
  }
  for (const SvgMarker& m : markers) {
    const auto [x, y] = px(m.at);
    s << "<circle cx=\"" << x << "\" cy=\"" << y << "\" r=\"5\" fill=\"none\" stroke=\"" << m.color
      << "\" stroke-width=\"2\"/>\n";
  }
  double ly = drawH + 2 * margin;
  s << "<text x=\"" << margin << "\" y=\"" << ly << "\">" << escaped(title) << "</text>\n";
  for (const SvgLayer& layer : layers) {
    ly += 20;
    s << "<rect x=\"" << margin << "\" y=\"" << ly - 11 << "\" width=\"14\" height=\"12\" fill=\""
      << layer.fill << "\" fill-opacity=\"" << layer.fillOpacity << "\" stroke=\"" << layer.stroke
      << "\"/><text x=\"" << margin + 20 << "\" y=\"" << ly << "\">" << escaped(layer.label)
      << "</text>\n";
  }
  s << "</svg>\n";
  return s.str();
}

}  // namespace gh::io
