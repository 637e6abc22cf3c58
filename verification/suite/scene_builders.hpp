#pragma once
// Small scenes built in code for the hard cases and the work-precision runs.

#include <string>

#include "scene/scene.hpp"

namespace gp::verification {

/// An empty scene with gravity g [m/s²], step dt [s] and duration [s] (output every step).
Scene make_scene(const Vec2& gravity, double dt, double duration);
/// A disc of radius r [m] and density [kg/m²] at `position` moving at `velocity`.
BodyDef disc(const std::string& name, const Vec2& position, const Vec2& velocity, double radius,
             double restitution, double density = 1.0);
/// A box w × h [m] of density [kg/m²].
BodyDef box(const std::string& name, const Vec2& position, double width, double height,
            double friction, double density = 1.0);
/// A static segment from a to b [m].
BodyDef wall(const std::string& name, const Vec2& a, const Vec2& b, double restitution = 0.0,
             double friction = 0.0);
/// 100 discs (r = 0.5) on a 10 × 10 grid, 2 m apart, falling from 5 m to 23 m onto a floor,
/// C_R = 0.9, frictionless: isolated impacts only, within the oracle's domain, for 1.5 s.
Scene rain100();

}  // namespace gp::verification
