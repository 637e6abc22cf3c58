#include "verification/suite/stability_scenes.hpp"

#include <cmath>
#include <numbers>

#include "verification/bench/workloads.hpp"
#include "verification/suite/scene_builders.hpp"

namespace gp::verification {

namespace {

constexpr double kDt = 1.0 / 60;
constexpr double kDuration = 10.0;
constexpr double kFriction = 0.6;
// Cards 1 m by 4 cm: twice Box2D's two polygon skins (1 cm each), so that it keeps their shape.
constexpr double kCardLength = 1.0;
constexpr double kCardThick = 0.04;

Scene empty(const Vec2& gravity) {
  return make_scene(gravity, kDt, kDuration);
}

// A static box w × h [m] centred at `center`.
BodyDef ground(const std::string& name, const Vec2& center, double width, double height) {
  BodyDef g = box(name, center, width, height, kFriction);
  g.type = BodyType::Static;
  return g;
}

// A dynamic convex polygon through `vertices` [m, world], density 1 kg/m².
BodyDef polygon(const std::string& name, const std::vector<Vec2>& vertices) {
  BodyDef b;
  b.name = name;
  b.shapes.push_back({Shape::polygon(vertices), 0.0, kFriction, 1.0});
  return b;
}

// Box2D's pyramid of its mass-ratio sample: `base` rows of 2 m boxes, touching, the bottom row on
// a ground whose top is y = 0, centred on x = `x`; its top box is bodies.back().
void pyramid(Scene& s, double x, int base) {
  s.bodies.push_back(ground("ground", {x, -1.0}, 4.0 * base, 2.0));
  for (int row = 0; row < base; ++row) {
    for (int i = 0; i < base - row; ++i) {
      const double bx = x + 2.0 * i - (base - row - 1);
      s.bodies.push_back(box("box" + std::to_string(row) + "_" + std::to_string(i),
                             {bx, 1.0 + 2.0 * row}, 2.0, 2.0, kFriction));
    }
  }
}

StabilityCase capped_pyramid(int ratio) {
  Scene s = empty({0.0, -10.0});
  pyramid(s, 0.0, 10);
  // The cap rests on the top box, so that drift is the solver's doing, not a fall.
  const Vec2 top = s.bodies.back().position;
  s.bodies.push_back(box("cap", top + Vec2(0.0, 2.0), 2.0, 2.0, kFriction, ratio));
  return {"pyramid capped by a box " + std::to_string(ratio) + "× denser", s,
          StabilityMetric::Drift, "a resting stack should not move; a soft solver lets it sink"};
}

StabilityCase box_on_triangles() {
  Scene s = empty({0.0, -10.0});
  s.bodies.push_back(ground("ground", {0.0, -1.0}, 60.0, 2.0));
  for (const double x : {-9.5, 9.5}) {
    s.bodies.push_back(
        polygon("triangle" + std::to_string(x > 0), {{x - 0.5, 0.0}, {x + 0.5, 0.0}, {x, 1.0}}));
  }
  s.bodies.push_back(box("big box", {0.0, 11.0}, 20.0, 20.0, kFriction));
  return {"20 m box on two small triangles", s, StabilityMetric::Overlap,
          "a 400 kg box on 0.5 kg points: the light bodies are pushed into"};
}

StabilityCase overlap_recovery() {
  Scene s = empty({0.0, -10.0});
  s.bodies.push_back(ground("ground", {0.0, -1.0}, 40.0, 2.0));
  constexpr int kBase = 4;
  for (int row = 0; row < kBase; ++row) {
    for (int i = 0; i < kBase - row; ++i) {
      // 1 m boxes 0.5 m apart: each overlaps its neighbours by half its size.
      s.bodies.push_back(box("box" + std::to_string(row) + "_" + std::to_string(i),
                             {0.5 * i - 0.25 * (kBase - row - 1), 0.5 + 0.5 * row}, 1.0, 1.0,
                             kFriction));
    }
  }
  return {"overlap recovery", s, StabilityMetric::Speed,
          "boxes pushed apart faster than they need are given energy"};
}

// A card leaning by `lean` [rad] from the vertical, its inner face from its foot on y = `floor` to
// its top at (`apex_x`, floor + length cos lean); `side` −1 leans it right from the left of the
// apex, +1 left from the right.
BodyDef card(const std::string& name, double apex_x, double floor, double lean, double side) {
  const Vec2 foot(apex_x + side * kCardLength * std::sin(lean), floor);
  const Vec2 top(apex_x, floor + kCardLength * std::cos(lean));
  const Vec2 out(side * std::cos(lean), std::sin(lean));
  return polygon(name, {foot, top, top + kCardThick * out, foot + kCardThick * out});
}

StabilityCase card_house() {
  constexpr double kLean = 25.0 * std::numbers::pi / 180;
  // Where a flat card rests on an A-frame standing on `floor`: the top of its outer corners.
  const auto frame_top = [&](double floor) {
    return floor + kCardLength * std::cos(kLean) + kCardThick * std::sin(kLean);
  };
  Scene s = empty({0.0, -10.0});
  s.bodies.push_back(ground("ground", {0.0, -1.0}, 20.0, 2.0));
  const auto frame = [&](const std::string& name, double apex_x, double floor) {
    s.bodies.push_back(card(name + " left", apex_x, floor, kLean, -1.0));
    s.bodies.push_back(card(name + " right", apex_x, floor, kLean, 1.0));
  };
  frame("frame 1", -0.45, 0.0);
  frame("frame 2", 0.45, 0.0);
  const double deck = frame_top(0.0);
  s.bodies.push_back(box("deck", {0.0, deck + kCardThick / 2}, kCardLength, kCardThick, kFriction));
  frame("frame 3", 0.0, deck + kCardThick);
  return {"card house", s, StabilityMetric::Drift,
          "cards leaning on their corners should stay put by friction alone"};
}

StabilityCase arch() {
  Scene s = empty({0.0, -10.0});
  s.bodies.push_back(ground("ground", {0.0, -1.0}, 30.0, 2.0));
  constexpr int kBlocks = 9;
  constexpr double kInner = 4.0;
  constexpr double kOuter = 5.0;
  const auto at = [](double r, double phi) { return Vec2(r * std::cos(phi), r * std::sin(phi)); };
  for (int k = 0; k < kBlocks; ++k) {
    // A semicircular arch: block k spans the angles [k, k + 1]·π/9, its faces radial, so that
    // neighbours meet face to face and the end blocks stand on the ground.
    const double a = std::numbers::pi * k / kBlocks;
    const double b = std::numbers::pi * (k + 1) / kBlocks;
    s.bodies.push_back(polygon("block" + std::to_string(k),
                               {at(kInner, a), at(kOuter, a), at(kOuter, b), at(kInner, b)}));
  }
  return {"arch of trapezoids", s, StabilityMetric::Drift,
          "an arch stands by friction between its blocks; a slipping solver lets it sag"};
}

StabilityCase confined() {
  Scene s = empty(Vec2::Zero());
  s.bodies.push_back(ground("floor", {0.0, -5.5}, 12.0, 1.0));
  s.bodies.push_back(ground("ceiling", {0.0, 5.5}, 12.0, 1.0));
  s.bodies.push_back(ground("left wall", {-5.5, 0.0}, 1.0, 10.0));
  s.bodies.push_back(ground("right wall", {5.5, 0.0}, 1.0, 10.0));
  constexpr int kSide = 12;
  for (int i = 0; i < kSide; ++i) {
    for (int j = 0; j < kSide; ++j) {
      // 144 discs of 0.785 m² in a 100 m² box: 113 m², more than any packing holds.
      BodyDef d =
          disc("disc" + std::to_string(kSide * i + j),
               {0.8 * j - 0.4 * (kSide - 1), 0.8 * i - 0.4 * (kSide - 1)}, Vec2::Zero(), 0.5, 0.0);
      d.shapes.front().friction = kFriction;
      s.bodies.push_back(d);
    }
  }
  return {"discs confined in a box, more than fit", s, StabilityMetric::Overlap,
          "they cannot all fit: a stable solver spreads the overlap, an unstable one piles it up "
          "(no gravity, at rest: every engine ends with no kinetic energy, so energy tells none "
          "apart)"};
}

StabilityCase rain() {
  Scene s = bench::rain(1000);
  s.duration = kDuration;
  return {"rain of 1000 discs into a box", s, StabilityMetric::Overlap,
          "discs falling up to 35 m onto a pile 16 deep: a solver that lets a fast disc through "
          "the pile, or cannot hold its load, lets them sink into each other"};
}

StabilityCase far_pyramid(double x, const std::string& where) {
  Scene s = empty({0.0, -10.0});
  pyramid(s, x, 10);
  return {"pyramid of base 10, " + where, s, StabilityMetric::Drift,
          "a resting stack should not move; far from the origin, precision decides"};
}

}  // namespace

std::vector<StabilityCase> stability_cases() {
  return {capped_pyramid(100),
          capped_pyramid(200),
          capped_pyramid(300),
          box_on_triangles(),
          overlap_recovery(),
          card_house(),
          arch(),
          confined(),
          rain(),
          far_pyramid(0.0, "at the origin"),
          far_pyramid(1e4, "10 km from the origin")};
}

}  // namespace gp::verification
