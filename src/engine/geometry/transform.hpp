#pragma once
// Rigid placement of a body frame in the world: where shapes given in body coordinates end up.

#include <cmath>
#include <numbers>

#include "gamephysics/models/types.hpp"

namespace gp {

/// `angle` [rad] less the whole turns that bring it within half a turn of 0: the turn between two
/// angles kept in [0, 2π), where a body rocking about 0 wraps by a whole turn. std::remainder,
/// which costs tens of nanoseconds, only past half a turn: within it, it gives the angle back.
inline double within_half_turn(double angle) {
  return std::abs(angle) <= std::numbers::pi ? angle
                                             : std::remainder(angle, 2.0 * std::numbers::pi);
}

/// A rotation by an angle (rad, counter-clockwise), kept as its cosine and sine so that turning
/// many vectors by it costs no trigonometry per vector.
class Rotation {
 public:
  /// The identity.
  Rotation() = default;
  explicit Rotation(double angle) : cos_(std::cos(angle)), sin_(std::sin(angle)) {}
  /// The rotation that turns the x axis onto `x_axis` (a unit vector, as x_axis() gives).
  static Rotation with_x_axis(const Vec2& x_axis) {
    Rotation r;
    r.cos_ = x_axis.x();
    r.sin_ = x_axis.y();
    return r;
  }

  /// A direction (e.g. a unit normal) turned from body to world axes.
  Vec2 rotate(const Vec2& v) const {
    return {cos_ * v.x() - sin_ * v.y(), sin_ * v.x() + cos_ * v.y()};
  }
  /// The body's x and y axes in world axes: the columns of the rotation matrix.
  Vec2 x_axis() const { return {cos_, sin_}; }
  Vec2 y_axis() const { return {-sin_, cos_}; }
  /// A direction turned from world to body axes: the inverse of rotate().
  Vec2 unrotate(const Vec2& v) const {
    return {cos_ * v.x() + sin_ * v.y(), -sin_ * v.x() + cos_ * v.y()};
  }

  /// The largest turn [rad] turned() takes.
  static constexpr double kLargestSeriesTurn = 0.1;

  /// This rotation turned further by `turn` (rad, |turn| ≤ kLargestSeriesTurn) without
  /// trigonometry: sin and cos of the turn from their Taylor series, each erring by at most 1e-13,
  /// to third order up to 1e-3 rad (error t⁴/24) and beyond to seventh and eighth (t⁹/9!, 3e-15
  /// at 0.1).
  Rotation turned(double turn) const {
    double c = 0.0;
    double s = 0.0;
    if (std::abs(turn) <= 1e-3) {
      c = 1.0 - 0.5 * turn * turn;
      s = turn - turn * turn * turn / 6.0;
    } else {
      const double t2 = turn * turn;
      c = 1.0 -
          0.5 * t2 * (1.0 - t2 * (1.0 / 12) * (1.0 - t2 * (1.0 / 30) * (1.0 - t2 * (1.0 / 56))));
      s = turn * (1.0 - t2 * (1.0 / 6) * (1.0 - t2 * (1.0 / 20) * (1.0 - t2 * (1.0 / 42))));
    }
    Rotation r;
    r.cos_ = cos_ * c - sin_ * s;
    r.sin_ = sin_ * c + cos_ * s;
    return r;
  }

 private:
  double cos_ = 1.0;
  double sin_ = 0.0;
};

/// Rotation by `angle` (rad, counter-clockwise) followed by a translation to `position` (m).
/// The engine puts a body frame's origin at the body's centre of mass, so `position` is the
/// centre of mass in world coordinates and shape coordinates are relative to it.
class Transform {
 public:
  /// The identity.
  Transform() = default;
  /// A translation to `position` (m) alone, without trigonometry: enough for a shape that turning
  /// leaves in place (a disc about its centre).
  explicit Transform(const Vec2& position) : position_(position) {}
  Transform(const Vec2& position, double angle) : Transform(position, angle, Rotation(angle)) {}

  /// m, world.
  const Vec2& position() const { return position_; }
  /// rad, counter-clockwise.
  double angle() const { return angle_; }

  /// A direction (e.g. a unit normal) turned from body to world axes; no translation. As the
  /// axes scaled and summed, the same values as Rotation::rotate: a pair built from two scalars
  /// goes through the stack, and the wide load of it stalls on the narrow stores.
  Vec2 rotate(const Vec2& v) const { return x_axis_ * v.x() + y_axis_ * v.y(); }
  /// A direction turned from world to body axes: the inverse of rotate(), its components the
  /// axes' dot products with v (the same values as Rotation::unrotate).
  Vec2 unrotate(const Vec2& v) const {
    return {x_axis_.x() * v.x() + x_axis_.y() * v.y(), y_axis_.x() * v.x() + y_axis_.y() * v.y()};
  }
  /// A point (m) mapped from body to world coordinates.
  Vec2 apply(const Vec2& p) const { return position_ + rotate(p); }

 private:
  Transform(const Vec2& position, double angle, const Rotation& rotation)
      : position_(position),
        angle_(angle),
        x_axis_(rotation.x_axis()),
        y_axis_(rotation.y_axis()) {}

  Vec2 position_ = Vec2::Zero();
  double angle_ = 0.0;
  // The rotation's columns: the body's axes in world axes.
  Vec2 x_axis_ = Vec2::UnitX();
  Vec2 y_axis_ = Vec2::UnitY();
};

}  // namespace gp
