// Peer clippers behind one small interface: region in, region out, operation.
//
// Peers: clipper6 (Clipper 6.4.2, Vatti's algorithm, the paper's comparator), geos (GEOS 3.11
// OverlayNG, C API), boost (Boost.Geometry 1.74), cgal (CGAL 5.5 Boolean_set_operations_2,
// exact kernel). GEOS, Boost and CGAL take only valid simple polygons with holes: their adapters
// convert our even-odd regions with toPolygonsWithHoles() and refuse (PeerRefusal, with the
// reason) whatever has no exact form. Clipper takes anything, with even-odd fill.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "ghclip/errors.h"
#include "ghclip/operation.h"
#include "ghclip/region.h"

namespace gh::peers {

// The peer cannot take this input; the message says why. Bad input, not a wrong answer.
class PeerRefusal : public InvalidInput {
 public:
  using InvalidInput::InvalidInput;
};

// An operand converted to the peer's own representation (done outside any timed region).
class Prepared {
 public:
  virtual ~Prepared() = default;
};

class Peer {
 public:
  virtual ~Peer() = default;
  virtual std::string_view name() const = 0;
  // What the peer is, and what it accepts (one line each, for tables and --help).
  virtual std::string_view description() const = 0;
  virtual std::string_view accepts() const = 0;
  virtual bool validInputOnly() const = 0;

  // Throws PeerRefusal for input the peer cannot take exactly.
  virtual std::unique_ptr<Prepared> prepare(const Region& region) const = 0;
  // The operation itself, on prepared operands; returns an even-odd region.
  virtual Region run(const Prepared& subject, const Prepared& clip, Op op) const = 0;

  Region clip(const Region& subject, const Region& clip, Op op) const {
    const auto s = prepare(subject);
    const auto c = prepare(clip);
    return run(*s, *c, op);
  }
};

// Every peer, in a fixed order: clipper6, geos, boost, cgal.
const std::vector<const Peer*>& allPeers();
// nullptr when there is no peer of that name.
const Peer* findPeer(std::string_view name);

}  // namespace gh::peers
