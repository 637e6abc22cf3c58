#include "verification/bench/workloads.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace gp::bench {

namespace {

constexpr double kGameStep = 1.0 / 60.0;  // s
const Vec2 kGravity{0.0, -9.81};          // m/s²
constexpr int kRunSteps = 1000;
constexpr int kFreeFallSteps = 600;

std::string numbered(const char* prefix, std::size_t i) {
  char text[32];
  std::snprintf(text, sizeof text, "%s%04zu", prefix, i);
  return text;
}

}  // namespace

Scene free_fall(std::size_t bodies) {
  Scene scene;
  scene.settings.gravity = kGravity;
  scene.dt = kGameStep;
  scene.duration = kFreeFallSteps * kGameStep;
  scene.output_dt = scene.duration;
  const auto side = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(bodies))));
  for (std::size_t i = 0; i < bodies; ++i) {
    BodyDef body;
    body.name = numbered("point", i);
    const auto column = static_cast<double>(i % side);
    const auto row = static_cast<double>(i / side);
    body.position = {column, row};
    // Distinct velocities, so that no engine can fold bodies together.
    body.velocity = {0.01 * column, 5.0 + 0.01 * row};
    body.mass = 1.0;
    scene.bodies.push_back(body);
  }
  return scene;
}

Scene rain(std::size_t balls) {
  constexpr std::size_t rows = 25;
  constexpr double pitch = 1.5, radius = 0.5, friction = 0.6;   // m, m, 1
  constexpr double floor_per_column = 2.0, wall_height = 60.0;  // m
  if (balls == 0 || balls % rows != 0) {
    throw std::invalid_argument("rain: the number of balls must be a positive multiple of 25");
  }
  const std::size_t columns = balls / rows;
  const double half_width = floor_per_column * static_cast<double>(columns) / 2.0;
  Scene scene;
  scene.settings.gravity = kGravity;
  scene.dt = kGameStep;
  scene.duration = 8.0;
  scene.output_dt = 0.1;
  BodyDef box;
  box.name = "box";
  box.type = BodyType::Static;
  for (const auto& [a, b] : {std::pair{Vec2(-half_width, 0), Vec2(half_width, 0)},
                             std::pair{Vec2(-half_width, 0), Vec2(-half_width, wall_height)},
                             std::pair{Vec2(half_width, 0), Vec2(half_width, wall_height)}}) {
    box.shapes.push_back({Shape::segment(a, b), 0.0, friction});
  }
  scene.bodies.push_back(box);
  for (std::size_t row = 0; row < rows; ++row) {
    const double offset = row % 2 ? pitch / 2 : 0.0;
    for (std::size_t column = 0; column < columns; ++column) {
      BodyDef ball;
      ball.name = numbered("ball", row * columns + column);
      // The same operations, in the same order, as generate.py: the positions are equal doubles.
      ball.position = {
          (static_cast<double>(column) - static_cast<double>(columns - 1) / 2.0) * pitch + offset,
          5.0 + static_cast<double>(row) * pitch};
      ball.shapes.push_back({Shape::circle(radius), 0.0, friction});
      scene.bodies.push_back(ball);
    }
  }
  return scene;
}

BodyId highest_body(const Scene& scene) {
  BodyId top = 0;
  for (BodyId id = 1; id < scene.bodies.size(); ++id) {
    if (scene.bodies[id].position.y() > scene.bodies[top].position.y()) top = id;
  }
  return top;
}

std::vector<Workload> headline_workloads(const std::filesystem::path& scenes_dir) {
  std::vector<Workload> list;
  list.push_back({"free10000", free_fall(10000), kFreeFallSteps, std::nullopt});
  list.push_back({"rain1000", load_scene(scenes_dir / "rain1000.json"), kRunSteps, std::nullopt});
  Scene pyramid = load_scene(scenes_dir / "pyramid20.json");
  const BodyId top = highest_body(pyramid);
  list.push_back({"pyramid20", std::move(pyramid), kRunSteps, top});
  return list;
}

std::vector<Workload> box2d_workloads(const std::filesystem::path& bench_scenes_dir, bool quick) {
  std::vector<Workload> list;
  const auto watched = [&](const char* name, int steps) {
    Scene scene = load_scene(bench_scenes_dir / (std::string(name) + ".json"));
    const BodyId top = highest_body(scene);
    list.push_back({name, std::move(scene), steps, top});
  };
  watched("large_pyramid", 500);
  watched("large_pyramid_coloured", 500);
  if (!quick) watched("many_pyramids", 200);
  list.push_back({"tumbler", load_scene(bench_scenes_dir / "tumbler.json"), 750, std::nullopt});
  return list;
}

Workload sleeping(Workload w) {
  w.name += "_sleep";
  w.scene.settings.sleep = true;
  return w;
}

std::vector<Workload> workloads(const std::filesystem::path& scenes_dir,
                                const std::filesystem::path& bench_scenes_dir, bool quick) {
  std::vector<Workload> list = headline_workloads(scenes_dir);
  // rain1000's pile colour by colour: its one-point contacts four at a time where the CPU has AVX2.
  list.push_back({"rain1000_coloured", load_scene(bench_scenes_dir / "rain1000_coloured.json"),
                  kRunSteps, std::nullopt});
  list.push_back({"rain4000", rain(4000), kRunSteps, std::nullopt});
  if (!quick) list.push_back({"rain16000", rain(16000), kRunSteps, std::nullopt});
  for (Workload& w : box2d_workloads(bench_scenes_dir, quick)) list.push_back(std::move(w));
  // Settled piles with sleeping on (ours; the peers sleep as their configuration says).
  for (std::size_t i = 0, n = list.size(); i < n; ++i) {
    if (list[i].name == "pyramid20" || list[i].name == "many_pyramids") {
      list.push_back(sleeping(list[i]));
    }
  }
  return list;
}

}  // namespace gp::bench
