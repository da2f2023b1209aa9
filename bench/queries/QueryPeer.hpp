#pragma once
// The peer engine as query_bench sees it: a world holding a scene of boxes, stepped, then asked. Box2dQueryPeer.cpp
// implements it when the build has Box2D; NoQueryPeer.cpp says why there is none.

#include "../peers/Scenes.hpp"

#include <cstddef>
#include <memory>
#include <string>

class QueryPeer {
public:
    virtual ~QueryPeer() = default;
    virtual std::string name() const = 0;
    /// The fraction of the closest hit of the ray (ox, oy) + f (dx, dy), f in [0, 1]; -1 when it hits nothing.
    virtual double castRayClosest(double ox, double oy, double dx, double dy) = 0;
    /// How many shapes the engine reports for the box.
    virtual std::size_t countAabb(double x0, double y0, double x1, double y1) = 0;
};

/// The scene built in the peer and stepped `steps` times at peers::kTimeStep; null when the build has no peer.
std::unique_ptr<QueryPeer> makeQueryPeer(const peers::Scene& scene, int steps);
/// Why makeQueryPeer gives nothing ("" when it gives a peer).
std::string queryPeerMissing();
