// The hand-checked clipping cases of tests/data/hand_cases.txt (each expected area is worked out
// by hand in the file), read for the clipper, oracle and peer tests.
#pragma once

#include <string>
#include <vector>

#include "ghclip/operation.h"
#include "ghclip/region.h"

namespace gh::test {

struct HandCase {
  std::string name;
  Region subject, clip;
  double areaSubject = 0, areaClip = 0;
  // Expected even-odd areas of intersection, union, difference, reverse difference, xor
  // (the order of kAllOps).
  double expected[5] = {};
  int intersectionRings = -1;  // expected ring count of the intersection, -1 if not given
};

// Reads the data file once; a malformed file fails loudly (std::runtime_error naming the line).
const std::vector<HandCase>& handCases();

// The case of that name (std::out_of_range if there is none).
const HandCase& handCase(const std::string& name);

}  // namespace gh::test
