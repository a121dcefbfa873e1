#include "ghpeers/peer.h"

namespace gh::peers {

const Peer& clipper6Peer();
const Peer& geosPeer();
const Peer& boostPeer();
const Peer& cgalPeer();

const std::vector<const Peer*>& allPeers() {
  static const std::vector<const Peer*> list{&clipper6Peer(), &geosPeer(), &boostPeer(), &cgalPeer()};
  return list;
}

const Peer* findPeer(std::string_view name) {
  for (const Peer* p : allPeers()) {
    if (p->name() == name) return p;
  }
  return nullptr;
}

}  // namespace gh::peers
