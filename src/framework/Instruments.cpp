#include "Instruments.hpp"

#include "Arrows.hpp"
#include "Lines.hpp"
#include "Measure.hpp"
#include "Overlay.hpp"
#include "Trails.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

namespace physim {
namespace {

constexpr float kTickPixels = 7.f;    // half-length of the tape's end ticks
constexpr float kArcPixels = 36.f;    // the protractor's arc radius (less for shorter arms)
constexpr int kArcSegments = 32;
constexpr float kTrailPixels = 1.5f;  // trail width
constexpr double kArrowPixels = 90.0;  // the longest arrow's length, at most
const sf::Color kTape(210, 90, 0), kProtractor(150, 40, 170), kTrail(20, 60, 150);
const sf::Color kVelocityArrow(0, 140, 0), kWeightArrow(200, 30, 30), kContactArrow(30, 60, 220),
    kJointArrow(230, 130, 0);

float length(sf::Vector2f d) { return std::hypot(d.x, d.y); }

}  // namespace

void drawTrails(sf::RenderTarget& target, const View& view, const Trails& trails) {
    const sf::Transform toPixels = view.worldToPixels(target.getSize());
    Lines lines(kTrailPixels);
    for (const Trails::Entry& e : trails.entries()) {
        const Trail& trail = e.trail;
        const std::size_t n = trail.size();
        if (n < 2) continue;
        sf::Color older = kTrail, newer = kTrail;
        sf::Vector2f from = toPixels.transformPoint(static_cast<float>(trail[0].x()), static_cast<float>(trail[0].y()));
        for (std::size_t i = 1; i < n; ++i) {
            const sf::Vector2f to =
                toPixels.transformPoint(static_cast<float>(trail[i].x()), static_cast<float>(trail[i].y()));
            older.a = static_cast<sf::Uint8>(220 * (i - 1) / (n - 1));
            newer.a = static_cast<sf::Uint8>(220 * i / (n - 1));
            lines.add(from, to, older, newer);
            from = to;
        }
    }
    lines.draw(target);
}

std::string arrowsLegendText(double velocityPerMetre, double forcePerMetre) {
    char text[160];
    std::snprintf(text, sizeof text,
                  "arrows: velocity (green) 1 m = %g m/s, weight (red), contact (blue) and joint (orange) 1 m = %g N",
                  velocityPerMetre, forcePerMetre);
    return text;
}

std::string drawArrows(sf::RenderTarget& target, const View& view, const World& world, double dt,
                       ArrowScale& velocityScale, ArrowScale& forceScale) {
    const std::vector<BodyArrows> arrows = bodyArrows(world, dt);
    const std::vector<JointArrows> joints = jointArrows(world);
    double fastest = 0.0, strongest = 0.0;
    for (const BodyArrows& a : arrows) {
        fastest = std::max(fastest, a.velocity.norm());
        strongest = std::max({strongest, a.weight.norm(), a.contact.norm()});
    }
    for (const JointArrows& j : joints) strongest = std::max(strongest, j.onB.norm());
    const double longest = kArrowPixels / view.pixelsPerMetre;  // m
    const double perVelocity = velocityScale.update(fastest, longest), perForce = forceScale.update(strongest, longest);
    const sf::Transform toPixels = view.worldToPixels(target.getSize());
    const auto pixel = [&](const Vec2& p) {
        return toPixels.transformPoint(static_cast<float>(p.x()), static_cast<float>(p.y()));
    };
    Lines lines;
    for (const BodyArrows& a : arrows) {
        const sf::Vector2f from = pixel(a.at);
        lines.arrow(from, pixel(a.at + a.weight / perForce), kWeightArrow);
        lines.arrow(from, pixel(a.at + a.contact / perForce), kContactArrow);
        lines.arrow(from, pixel(a.at + a.velocity / perVelocity), kVelocityArrow);
    }
    for (const JointArrows& j : joints) {
        lines.arrow(pixel(j.atB), pixel(j.atB + j.onB / perForce), kJointArrow);
        if (!j.toWorld) lines.arrow(pixel(j.atA), pixel(j.atA - j.onB / perForce), kJointArrow);
    }
    lines.draw(target);
    return arrowsLegendText(perVelocity, perForce);
}

void drawMeasurement(sf::RenderTarget& target, const View& view, const Measurement& measurement,
                     const Overlay& overlay) {
    if (measurement.kind() == Measurement::Kind::None) return;
    const sf::Transform toPixels = view.worldToPixels(target.getSize());
    std::vector<sf::Vector2f> px;
    for (const Vec2& p : measurement.points())
        px.push_back(toPixels.transformPoint(static_cast<float>(p.x()), static_cast<float>(p.y())));
    Lines lines;
    char text[64];
    if (const std::optional<double> metres = measurement.length()) {
        const sf::Vector2f d = px[1] - px[0];
        lines.add(px[0], px[1], kTape);
        if (const float len = length(d); len > 0.f) {
            const sf::Vector2f n = (kTickPixels / len) * sf::Vector2f(-d.y, d.x);
            lines.add(px[0] - n, px[0] + n, kTape);
            lines.add(px[1] - n, px[1] + n, kTape);
        }
        lines.draw(target);
        std::snprintf(text, sizeof text, "%.3f m", *metres);
        overlay.drawLabel(target, 0.5f * (px[0] + px[1]) + sf::Vector2f(8.f, 8.f), text);
        return;
    }
    // The protractor: its arms, and an arc between them the short way round.
    for (std::size_t i = 1; i < px.size(); ++i) lines.add(px[0], px[i], kProtractor);
    const std::optional<double> degrees = measurement.angle();
    if (degrees) {
        const sf::Vector2f u = px[1] - px[0], v = px[2] - px[0];
        const float radius = std::min({kArcPixels, 0.8f * length(u), 0.8f * length(v)});
        const float from = std::atan2(u.y, u.x);
        const float sweep = std::remainder(std::atan2(v.y, v.x) - from, 2.f * static_cast<float>(M_PI));
        sf::Vector2f last = px[0] + radius * sf::Vector2f(std::cos(from), std::sin(from));
        for (int i = 1; i <= kArcSegments; ++i) {
            const float a = from + sweep * static_cast<float>(i) / kArcSegments;
            const sf::Vector2f next = px[0] + radius * sf::Vector2f(std::cos(a), std::sin(a));
            lines.add(last, next, kProtractor);
            last = next;
        }
    }
    lines.draw(target);
    if (degrees) std::snprintf(text, sizeof text, "%.1f\u00b0", *degrees);
    else std::snprintf(text, sizeof text, "angle: drag an arm, then click");
    overlay.drawLabel(target, px[0] + sf::Vector2f(10.f, 10.f), text);
}

}  // namespace physim
