// One input of the property suite: two regions and an operation. Printed as WKT so that a
// shrunk counterexample can be pasted into ghclip.
#pragma once

#include <ostream>

#include "ghclip/operation.h"
#include "ghclip/region.h"
#include "ghio/formats.h"

namespace gh::props {

struct PropertyCase {
  Region subject;
  Region clip;
  Op op = Op::Intersection;
};

inline void showValue(const PropertyCase& c, std::ostream& os) {
  os << "op " << name(c.op) << "\nsubject " << io::writeWkt(c.subject) << "\nclip    "
     << io::writeWkt(c.clip);
}

}  // namespace gh::props
