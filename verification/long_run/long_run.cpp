#include "verification/long_run/long_run.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>

#include "engine/geometry/world_shape.hpp"
#include "engine/numerical_error.hpp"
#include "engine/scene/scene_space.hpp"

namespace gp::verification {

bool Box::contains(const Vec2& point) const {
  return (point.array() >= lower.array()).all() && (point.array() <= upper.array()).all();
}

Box starting_box(const Scene& scene, double margin) {
  Box box{Vec2::Constant(INFINITY), Vec2::Constant(-INFINITY)};
  const auto include = [&box](const Vec2& point) {
    box.lower = box.lower.cwiseMin(point);
    box.upper = box.upper.cwiseMax(point);
  };
  for (const BodyDef& body : scene.bodies) {
    include(body.position);
    if (body.type != BodyType::Static) continue;
    for (const ShapeDef& shape : body.shapes) {
      const Aabb bounds = to_world(shape.shape, Transform(body.position, body.angle)).bounds;
      include(bounds.min);
      include(bounds.max);
    }
  }
  box.lower -= Vec2::Constant(margin);
  box.upper += Vec2::Constant(margin);
  return box;
}

double resident_mib() {
  std::ifstream statm("/proc/self/statm");
  long size = 0;
  long resident = 0;
  statm >> size >> resident;
  return static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGESIZE)) / (1 << 20);
}

double LongRunResult::memory_growth_mib() const {
  const auto settled = std::find_if(memory.begin(), memory.end(), [this](const MemorySample& m) {
    return m.step > 0 && 10 * m.step >= memory.back().step;
  });
  return settled == memory.end() ? 0.0 : memory.back().rss_mib - settled->rss_mib;
}

LongRunResult long_run(const Scene& scene, long steps, int samples, const Box& box,
                       const LongRunProgress& progress) {
  LongRunResult result;
  const auto space = build_space(scene);
  result.memory.push_back({0, resident_mib()});
  if (progress) progress(result.memory.back());
  const long interval = std::max(1L, steps / std::max(1, samples));
  const auto start = std::chrono::steady_clock::now();
  try {
    while (result.steps_done < steps) {
      space->step(scene.dt);
      ++result.steps_done;
      for (BodyId id = 0; id < space->body_count(); ++id) {
        if (space->type(id) != BodyType::Dynamic) continue;
        const Vec2 position = space->state(id).position;
        result.max_abs_coordinate =
            std::max(result.max_abs_coordinate, position.cwiseAbs().maxCoeff());
        if (result.first_outside.empty() && !box.contains(position)) {
          result.first_outside = "body '" + std::string(space->name(id)) + "' at step " +
                                 std::to_string(result.steps_done);
        }
      }
      if (result.steps_done % interval == 0 || result.steps_done == steps) {
        result.memory.push_back({result.steps_done, resident_mib()});
        if (progress) progress(result.memory.back());
      }
    }
  } catch (const NumericalError& e) {
    result.non_finite = e.what();
  }
  result.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

std::vector<Check> long_run_rows(const std::string& label, const LongRunResult& r) {
  CheckList list("long runs");
  const std::string srs = "NFR:Correctness FR:Calculate-Translation-Over-Time";
  list.check(label + ": every state finite", srs,
             r.non_finite.empty() ? "finite over " + std::to_string(r.steps_done) + " steps"
                                  : r.non_finite,
             "no NaN or infinity", r.non_finite.empty());
  list.check(label + ": no body leaves the box it starts in",
             srs + " FR:Determine-Collision-Response-Over-Time",
             (r.first_outside.empty() ? "none left" : r.first_outside + " left") +
                 ", largest |x| or |y| " + figure(r.max_abs_coordinate) + " m",
             "within " + figure(kBoxMargin) + " m of the walls and starting heights",
             r.first_outside.empty());
  list.within(label + ": resident memory does not grow", "NFR:Performance",
              figure(r.memory.front().rss_mib) + " MiB at the start, " +
                  figure(r.memory.back().rss_mib) + " MiB at the end, growth " +
                  figure(r.memory_growth_mib()) + " MiB after the first tenth",
              "growth ≤ " + figure(kMaxMemoryGrowthMib) + " MiB",
              {{r.memory_growth_mib(), kMaxMemoryGrowthMib}},
              "the allocator may keep freed pages; a leak of 100 B a step would grow 95 MiB");
  list.report(label + ": wall time", "NFR:Performance",
              figure(r.wall_seconds) + " s, " +
                  figure(1e3 * r.wall_seconds / static_cast<double>(std::max(1L, r.steps_done))) +
                  " ms per step");
  return list.rows();
}

Scene first_bodies(Scene scene, std::size_t count) {
  if (scene.bodies.size() > count) scene.bodies.resize(count);
  return scene;
}

}  // namespace gp::verification
