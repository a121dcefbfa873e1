// SVG pictures of regions, filled with the even-odd rule, so a person can look at an answer.
#pragma once

#include <string>
#include <vector>

#include "ghclip/region.h"

namespace gh::io {

struct SvgLayer {
  const Region* region;
  std::string fill;    // CSS colour, "none" for outline only
  std::string stroke;  // CSS colour
  std::string label;   // shown in the legend
  double fillOpacity = 0.35;
};

struct SvgMarker {
  Point at;
  std::string color;
  std::string label;
};

// Layers are drawn in order, in one frame fitting all of them (y up), with a legend.
std::string svgPicture(const std::vector<SvgLayer>& layers, const std::string& title,
                       const std::vector<SvgMarker>& markers = {});

}  // namespace gh::io
