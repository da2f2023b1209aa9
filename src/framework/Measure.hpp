#pragma once
// The window's tape measure (M + left drag) and protractor (A + left drag from the vertex along one arm, then a
// click ends the other arm): points in world coordinates (m), so a measurement stays on the bodies it was laid on
// through pans and zooms, and reads in metres and degrees whatever the zoom. Internal to the runner; window-free,
// so it can be tested headless.

#include "physim/core/Math.hpp"

#include <optional>
#include <vector>

namespace physim {

/// Angle (degrees, in [0, 180]) at `vertex` between the rays to `a` and to `b`. Throws std::invalid_argument for
/// a non-finite point or a ray of zero length (no direction).
double protractorAngle(const Vec2& vertex, const Vec2& a, const Vec2& b);

class Measurement {
public:
    enum class Kind { None, Tape, Protractor };

    /// The left button went down at `point` (m). With Kind::Tape or Kind::Protractor (the instrument's key held) a
    /// new measurement starts there, the tape's start or the protractor's vertex. While the protractor waits for
    /// its second arm (awaitingClick) any press ends that arm, whatever `kind`. Kind::None clears. Returns whether
    /// the press was the instrument's (the body under it is then not grabbed).
    bool press(Kind kind, const Vec2& point);
    /// The cursor moved: the end being laid follows it.
    void move(const Vec2& point);
    /// The left button came up: the tape ends there; the protractor's first arm ends there, and its second arm
    /// follows the cursor until the next press.
    void release(const Vec2& point);
    void clear();

    Kind kind() const { return kind_; }
    bool awaitingClick() const { return awaiting_; }
    /// Tape: start and end. Protractor: vertex, first arm's end, then the second arm's end once begun.
    const std::vector<Vec2>& points() const { return points_; }
    /// The tape's length (m); nullopt for no tape.
    std::optional<double> length() const;
    /// The protractor's angle (degrees); nullopt before its second arm is begun or while an arm has zero length.
    std::optional<double> angle() const;

private:
    Kind kind_ = Kind::None;
    std::vector<Vec2> points_;
    bool dragging_ = false;  // the button is down: the last point follows the cursor
    bool awaiting_ = false;  // protractor: the second arm follows the cursor until a press
};

}  // namespace physim
