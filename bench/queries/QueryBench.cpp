// query_bench: ray casts and box queries in the large_pyramid scene (bench/peers' description), in physim and, when
// the build found it, Box2D 2.4 (Debian's libbox2d-dev), on the same rays and boxes after the same steps. Prints a
// table and the engines' agreement, and with --json writes [{"query": "ray" | "aabb", "physim_us": x, "box2d_us": y}]
// (microseconds per query, the least of --repeats timed passes; box2d_us null without Box2D).
//
// Rays: closest hit (physim castRayClosest; Box2D b2World::RayCast with a callback that clips to each hit). Boxes:
// physim overlapAabb's callback form, which reports the shapes whose tight box overlaps; Box2D's QueryAABB reports
// every fat (proxy) box that overlaps, so its counts are higher. Both count what they are given.
//
// Box2D 2.4 rounds polygons by a 1 cm skin and casts rays against the core: its boxes are made one skin smaller (as
// peer_bench does, so the pyramid stands the same), so its ray hits lie about 1 cm farther than physim's.

#include "../peers/PhysimScene.hpp"
#include "../peers/Scenes.hpp"

#include "physim/core/World.hpp"

#include "QueryPeer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

struct Options {
    int rays = 10000;
    int boxes = 10000;
    int steps = 60;
    int repeats = 5;
    std::string scene = "large_pyramid";
    std::string json;
};

[[noreturn]] void usage(const std::string& problem) {
    std::cerr << "query_bench: " << problem << "\n"
              << "usage: query_bench [--rays N] [--boxes N] [--steps N] [--repeats N] [--scene NAME] [--json FILE]\n";
    std::exit(2);
}

int positive(const std::string& flag, const char* text) {
    char* end = nullptr;
    const long v = std::strtol(text, &end, 10);
    if (end == text || *end != '\0' || v < 1 || v > 100000000)
        usage(flag + " takes a positive count, got '" + text + "'");
    return static_cast<int>(v);
}

Options parse(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&]() -> const char* {
            if (i + 1 >= argc) usage(a + " needs a value");
            return argv[++i];
        };
        if (a == "--rays") o.rays = positive(a, next());
        else if (a == "--boxes") o.boxes = positive(a, next());
        else if (a == "--steps") o.steps = positive(a, next());
        else if (a == "--repeats") o.repeats = positive(a, next());
        else if (a == "--scene") o.scene = next();
        else if (a == "--json") o.json = next();
        else usage("unknown option '" + a + "'");
    }
    return o;
}

struct Ray {
    double ox, oy, dx, dy;
};

struct Box {
    double x0, y0, x1, y1;
};

// Rays and boxes over the scene's extent (its bodies' centres grown by 5 m): origins anywhere there, directions
// uniform, lengths 1 to 40 m; boxes 0.2 to 6 m wide.
void makeQueries(const peers::Scene& scene, int rayCount, int boxCount, std::vector<Ray>& rays,
                 std::vector<Box>& boxes) {
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    for (const peers::ShapeSpec& s : scene.dynamics) {
        x0 = std::min(x0, s.x), y0 = std::min(y0, s.y), x1 = std::max(x1, s.x), y1 = std::max(y1, s.y);
    }
    x0 -= 5.0, y0 -= 5.0, x1 += 5.0, y1 += 5.0;
    std::mt19937_64 rng(54);
    std::uniform_real_distribution<double> ux(x0, x1), uy(y0, y1), angle(-M_PI, M_PI), length(1.0, 40.0),
        half(0.1, 3.0);
    for (int i = 0; i < rayCount; ++i) {
        const double a = angle(rng), l = length(rng);
        rays.push_back({ux(rng), uy(rng), l * std::cos(a), l * std::sin(a)});
    }
    for (int i = 0; i < boxCount; ++i) {
        const double cx = ux(rng), cy = uy(rng), hx = half(rng), hy = half(rng);
        boxes.push_back({cx - hx, cy - hy, cx + hx, cy + hy});
    }
}

struct Agreement {
    double physimHitShare = 0.0, peerHitShare = 0.0, physimMeanFraction = 0.0, peerMeanFraction = 0.0;
    std::size_t outside = 0;  // rays that start outside every shape (physim's)
    double alikeShare = 0.0;  // of those, both miss or both hit within 1.5 cm across the surface
};

// Hit shares and mean fractions over all rays; and of the rays from outside every shape, how many the two answer
// alike. Rays from inside the pile meet the next box within millimetres, where a skin decides.
Agreement agree(const physim::World& world, const std::vector<Ray>& rays, const std::vector<double>& physim,
                const std::vector<double>& peer) {
    Agreement a;
    std::size_t physimHits = 0, peerHits = 0, alike = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const Ray& r = rays[i];
        if (physim[i] >= 0.0) ++physimHits, a.physimMeanFraction += physim[i];
        if (peer[i] >= 0.0) ++peerHits, a.peerMeanFraction += peer[i];
        if (!world.overlapPoint({r.ox, r.oy}).empty()) continue;
        ++a.outside;
        bool same = physim[i] < 0.0 && peer[i] < 0.0;
        if (physim[i] >= 0.0 && peer[i] >= 0.0) {
            const auto hit = world.castRayClosest({r.ox, r.oy}, {r.dx, r.dy});
            same = std::abs((peer[i] - physim[i]) * hit->normal.dot(physim::Vec2(r.dx, r.dy))) <= 0.015;
        }
        if (same) ++alike;
    }
    a.physimHitShare = double(physimHits) / rays.size();
    a.peerHitShare = double(peerHits) / rays.size();
    a.physimMeanFraction = physimHits ? a.physimMeanFraction / physimHits : 0.0;
    a.peerMeanFraction = peerHits ? a.peerMeanFraction / peerHits : 0.0;
    a.alikeShare = a.outside ? double(alike) / a.outside : 0.0;
    return a;
}

physim::World buildPhysim(const peers::Scene& scene) {
    physim::World world(peers::physimSettings(1));  // as peer_bench's physim: defaults, no sleep, one thread
    peers::buildPhysim(world, scene);
    return world;
}

template <class F>
double seconds(F&& pass) {
    const auto start = std::chrono::steady_clock::now();
    pass();
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
    return elapsed.count();
}

std::string number(double v) {
    if (!std::isfinite(v)) return "null";
    char text[64];
    std::snprintf(text, sizeof text, "%.4f", v);
    return text;
}

}  // namespace

int main(int argc, char** argv) {
    const Options o = parse(argc, argv);
    peers::Scene scene;
    try {
        scene = peers::makeScene(o.scene);
    } catch (const std::invalid_argument& e) {
        usage(e.what());
    }
    for (const peers::ShapeSpec& s : scene.statics)
        if (s.radius > 0.0) usage("scene '" + o.scene + "' has shapes other than boxes; query_bench builds boxes only");
    for (const peers::ShapeSpec& s : scene.dynamics)
        if (s.radius > 0.0) usage("scene '" + o.scene + "' has shapes other than boxes; query_bench builds boxes only");

    std::vector<Ray> rays;
    std::vector<Box> boxes;
    makeQueries(scene, o.rays, o.boxes, rays, boxes);

    physim::World world = buildPhysim(scene);
    for (int i = 0; i < o.steps; ++i) world.step(peers::kTimeStep);
    const std::unique_ptr<QueryPeer> peer = makeQueryPeer(scene, o.steps);

    // Each pass times physim's rays, the peer's, physim's boxes and the peer's in turn, so a change in the machine's
    // load falls on both engines; each figure is the least over the passes.
    std::vector<double> physimFraction(rays.size(), -1.0), peerFraction(rays.size(), -1.0);
    std::size_t physimFound = 0, peerFound = 0;
    const physim::QueryFilter all;
    const physim::OverlapCallback count = [&](physim::ShapeId) {
        ++physimFound;
        return true;
    };
    double physimRays = 1e300, physimBoxes = 1e300, peerRays = peer ? 1e300 : NAN, peerBoxes = peer ? 1e300 : NAN;
    for (int pass = 0; pass < o.repeats; ++pass) {
        physimRays = std::min(physimRays, seconds([&] {
            for (std::size_t i = 0; i < rays.size(); ++i) {
                const Ray& r = rays[i];
                const auto hit = world.castRayClosest({r.ox, r.oy}, {r.dx, r.dy});
                physimFraction[i] = hit ? hit->fraction : -1.0;
            }
        }));
        if (peer)
            peerRays = std::min(peerRays, seconds([&] {
                for (std::size_t i = 0; i < rays.size(); ++i) {
                    const Ray& r = rays[i];
                    peerFraction[i] = peer->castRayClosest(r.ox, r.oy, r.dx, r.dy);
                }
            }));
        physimBoxes = std::min(physimBoxes, seconds([&] {
            physimFound = 0;
            for (const Box& b : boxes) world.overlapAabb(physim::Aabb{{b.x0, b.y0}, {b.x1, b.y1}}, all, count);
        }));
        if (peer)
            peerBoxes = std::min(peerBoxes, seconds([&] {
                peerFound = 0;
                for (const Box& b : boxes) peerFound += peer->countAabb(b.x0, b.y0, b.x1, b.y1);
            }));
    }

    const double us = 1e6;
    const double rayUs = us * physimRays / rays.size(), boxUs = us * physimBoxes / boxes.size();
    const double peerRayUs = us * peerRays / rays.size(), peerBoxUs = us * peerBoxes / boxes.size();
    std::printf("query_bench: %s, %zu bodies, %d steps, %zu rays, %zu boxes, least of %d passes\n", o.scene.c_str(),
                scene.statics.size() + scene.dynamics.size(), o.steps, rays.size(), boxes.size(), o.repeats);
    std::printf("| query | physim_us | %s_us | ratio |\n|---|---|---|---|\n", peer ? peer->name().c_str() : "box2d");
    std::printf("| ray | %.4f | %s | %s |\n", rayUs, number(peerRayUs).c_str(), number(rayUs / peerRayUs).c_str());
    std::printf("| aabb | %.4f | %s | %s |\n", boxUs, number(peerBoxUs).c_str(), number(boxUs / peerBoxUs).c_str());
    if (!peer) std::printf("no peer: %s\n", queryPeerMissing().c_str());

    const Agreement settled = agree(world, rays, physimFraction, peerFraction);
    std::printf("after %d steps, rays hitting: physim %.4f (mean fraction %.5f)", o.steps, settled.physimHitShare,
                settled.physimMeanFraction);
    if (peer)
        std::printf(", %s %.4f (mean fraction %.5f)", peer->name().c_str(), settled.peerHitShare,
                    settled.peerMeanFraction);
    // The same rays before any step, where both engines hold the same boxes (Box2D's a skin smaller): the share
    // answered alike checks the queries themselves, free of the piles' different sag.
    Agreement unsettled;
    if (peer) {
        const physim::World still = buildPhysim(scene);
        const std::unique_ptr<QueryPeer> stillPeer = makeQueryPeer(scene, 0);
        std::vector<double> a(rays.size()), b(rays.size());
        for (std::size_t i = 0; i < rays.size(); ++i) {
            const Ray& r = rays[i];
            const auto hit = still.castRayClosest({r.ox, r.oy}, {r.dx, r.dy});
            a[i] = hit ? hit->fraction : -1.0;
            b[i] = stillPeer->castRayClosest(r.ox, r.oy, r.dx, r.dy);
        }
        unsettled = agree(still, rays, a, b);
        std::printf("\nbefore stepping, of the %zu rays from outside every box, answered alike by both (both miss, or "
                    "hits within 1.5 cm across the surface, Box2D's skin being 1 cm): %.4f",
                    unsettled.outside, unsettled.alikeShare);
    }
    std::printf("\nshapes per box: physim %.3f (tight boxes)", double(physimFound) / boxes.size());
    if (peer) std::printf(", %s %.3f (fat boxes)", peer->name().c_str(), double(peerFound) / boxes.size());
    std::printf("\n");

    if (!o.json.empty()) {
        std::ofstream out(o.json);
        out << "[\n  {\"query\": \"ray\", \"physim_us\": " << number(rayUs) << ", \"box2d_us\": " << number(peerRayUs)
            << ", \"hit_share_physim\": " << number(settled.physimHitShare)
            << ", \"hit_share_box2d\": " << (peer ? number(settled.peerHitShare) : "null")
            << ", \"mean_fraction_physim\": " << number(settled.physimMeanFraction)
            << ", \"mean_fraction_box2d\": " << (peer ? number(settled.peerMeanFraction) : "null")
            << ", \"unsettled_alike_share\": " << (peer ? number(unsettled.alikeShare) : "null") << "},\n"
            << "  {\"query\": \"aabb\", \"physim_us\": " << number(boxUs) << ", \"box2d_us\": " << number(peerBoxUs)
            << ", \"shapes_per_box_physim\": " << number(double(physimFound) / boxes.size())
            << ", \"shapes_per_box_box2d\": " << (peer ? number(double(peerFound) / boxes.size()) : "null")
            << "}\n]\n";
        if (!out) {
            std::cerr << "query_bench: cannot write " << o.json << "\n";
            return 1;
        }
    }
    return 0;
}
