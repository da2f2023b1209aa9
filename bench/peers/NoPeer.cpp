// Built when CMake found no Box2D 2.4 at configure time: peer_bench then measures physim alone.

#include "Engine.hpp"

namespace peers {

Peers peerEngines() {
    return {{}, "Box2D 2.4 was not found when this build was configured (Debian: libbox2d-dev, "
                "scripts/setup.sh installs it; then reconfigure): running physim alone"};
}

}  // namespace peers
