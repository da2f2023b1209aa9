// Box2D 2.4 as query_bench's peer: the scene's boxes as peer_bench builds them (Box2dEngine.cpp: one 1 cm skin
// smaller, density raised to keep the mass, 8 velocity and 3 position iterations, no sleep), then
// b2World::RayCast with a callback that clips the ray to each hit (the closest hit), and b2World::QueryAABB with a
// callback that counts.

#include "QueryPeer.hpp"

#include <box2d/box2d.h>

#include <cstddef>

namespace {

class ClosestHit final : public b2RayCastCallback {
public:
    float ReportFixture(b2Fixture*, const b2Vec2&, const b2Vec2&, float fraction) override {
        best = fraction;
        return fraction;  // clip: only closer hits come after
    }
    float best = -1.0f;
};

class Counter final : public b2QueryCallback {
public:
    bool ReportFixture(b2Fixture*) override {
        ++count;
        return true;
    }
    std::size_t count = 0;
};

class Box2dQueryPeer final : public QueryPeer {
public:
    Box2dQueryPeer(const peers::Scene& scene, int steps) : world_(b2Vec2(0.0f, static_cast<float>(peers::kGravity))) {
        world_.SetAllowSleeping(false);
        for (const peers::ShapeSpec& s : scene.statics) add(s, b2_staticBody);
        for (const peers::ShapeSpec& s : scene.dynamics) add(s, b2_dynamicBody);
        for (int i = 0; i < steps; ++i) world_.Step(static_cast<float>(peers::kTimeStep), 8, 3);
    }
    std::string name() const override { return "box2d-" PEERS_BOX2D_VERSION; }
    double castRayClosest(double ox, double oy, double dx, double dy) override {
        ClosestHit hit;
        const b2Vec2 p1(static_cast<float>(ox), static_cast<float>(oy));
        const b2Vec2 p2(static_cast<float>(ox + dx), static_cast<float>(oy + dy));
        world_.RayCast(&hit, p1, p2);
        return hit.best;
    }
    std::size_t countAabb(double x0, double y0, double x1, double y1) override {
        Counter counter;
        b2AABB box;
        box.lowerBound.Set(static_cast<float>(x0), static_cast<float>(y0));
        box.upperBound.Set(static_cast<float>(x1), static_cast<float>(y1));
        world_.QueryAABB(&counter, box);
        return counter.count;
    }

private:
    void add(const peers::ShapeSpec& s, b2BodyType type) {
        b2BodyDef bd;
        bd.type = type;
        bd.position.Set(static_cast<float>(s.x), static_cast<float>(s.y));
        b2Body* body = world_.CreateBody(&bd);  // owned by world_
        const double hx = s.halfWidth - b2_polygonRadius, hy = s.halfHeight - b2_polygonRadius;
        b2PolygonShape box;
        box.SetAsBox(static_cast<float>(hx), static_cast<float>(hy));
        b2FixtureDef fd;
        fd.shape = &box;
        fd.density = static_cast<float>(peers::kDensity * (s.halfWidth * s.halfHeight) / (hx * hy));
        fd.friction = static_cast<float>(peers::kFriction);
        body->CreateFixture(&fd);
    }

    b2World world_;
};

}  // namespace

std::unique_ptr<QueryPeer> makeQueryPeer(const peers::Scene& scene, int steps) {
    return std::make_unique<Box2dQueryPeer>(scene, steps);
}

std::string queryPeerMissing() { return ""; }
