// query_bench without a peer: the build found no Box2D 2.4 (libbox2d-dev), so only physim is measured.

#include "QueryPeer.hpp"

std::unique_ptr<QueryPeer> makeQueryPeer(const peers::Scene&, int) { return nullptr; }

std::string queryPeerMissing() { return "Box2D 2.4 not found at configure time (install libbox2d-dev)"; }
