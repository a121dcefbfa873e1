// The spacing of doubles at a magnitude, as the judges' tolerances count it.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace gh::oracle {

// The gap from m (>= 0) to the next double up, at least floor (the smallest ulp a caller
// judging a scaled copy stands for: judging_scale.h). NaN for an infinite or NaN m.
inline double ulpOf(double m, double floor = 0) {
  return std::max(std::nextafter(m, std::numeric_limits<double>::infinity()) - m, floor);
}

}  // namespace gh::oracle
