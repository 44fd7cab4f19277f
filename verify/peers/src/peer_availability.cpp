// Whether the FCL and Bullet peers are in this build (peer_detectors.hpp). In a build
// without them (RECODE_WITH_PEERS=OFF) their factories exist all the same and say how to get
// them, so the bench and the command line link in every configuration.
#include <memory>
#include <stdexcept>
#include <vector>

#include "recode/verify/closed_peers.hpp"
#include "recode/verify/peer_detectors.hpp"

namespace recode::verify {

#if RECODE_HAVE_PEERS
bool peersBuilt() {
  return true;
}
#else
bool peersBuilt() {
  return false;
}

namespace {

[[noreturn]] void noPeers() {
  throw std::runtime_error(
      "this build has no FCL/Bullet peers: configure with RECODE_WITH_PEERS=ON after "
      "installing libfcl-dev and libbullet-dev");
}

}  // namespace

std::unique_ptr<SceneDetector> makeFclGjkDetector(const std::vector<core::ObjectTree>&) {
  noPeers();
}
std::unique_ptr<SceneDetector> makeFclObbrssDetector(const std::vector<core::ObjectTree>&) {
  noPeers();
}
std::unique_ptr<SceneDetector> makeBulletDetector(const std::vector<core::ObjectTree>&) {
  noPeers();
}
std::unique_ptr<ClosedPairPeer> makeFclObbrssClosedPeer(const core::TriangleMesh&,
                                                        const core::TriangleMesh&, bool) {
  noPeers();
}
std::unique_ptr<ClosedPairPeer> makeBulletGImpactClosedPeer(const core::TriangleMesh&,
                                                            const core::TriangleMesh&) {
  noPeers();
}
#endif

}  // namespace recode::verify
