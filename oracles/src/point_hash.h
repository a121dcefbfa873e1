// Hashing points by their exact coordinates (for sets of input vertices).
#pragma once

#include <functional>

#include "ghclip/region.h"

namespace gh::oracle {

struct PointHash {
  std::size_t operator()(const Point& p) const {
    return std::hash<double>()(p.x) * 31 + std::hash<double>()(p.y);
  }
};

}  // namespace gh::oracle
