#include "verification/suite/trajectory.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <iterator>
#include <map>
#include <numbers>
#include <stdexcept>

#include "engine/output/output_times.hpp"
#include "engine/scene/run.hpp"
#include "engine/scene/scene_space.hpp"

namespace gp::verification {

double cpu_now() {
  return static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
}

namespace {

// |a − b| for two orientations, the shorter way round [rad].
double angle_difference(double a, double b) {
  const double d = std::fmod(std::abs(a - b), 2.0 * std::numbers::pi);
  return std::min(d, 2.0 * std::numbers::pi - d);
}

}  // namespace

Trajectory run_engine(const Scene& scene, IntegratorKind integrator, double dt) {
  Scene stepped = scene;
  stepped.settings.integrator = integrator;
  stepped.dt = dt;
  stepped.output_dt = dt;
  const auto space = build_space(stepped);
  Trajectory run;
  const double start = cpu_now();
  run_scene(*space, stepped, [&](double t) {
    run.times.push_back(t);
    std::vector<BodyState> states;
    for (BodyId id = 0; id < space->body_count(); ++id) states.push_back(space->state(id));
    run.states.push_back(std::move(states));
    run.impacts.insert(run.impacts.end(), space->impacts().begin(), space->impacts().end());
  });
  run.cpu_seconds = cpu_now() - start;
  return run;
}

double median_cpu_seconds(const std::function<double()>& timed_run) {
  std::vector<double> samples;
  double total = 0.0;
  while (samples.size() < 3 || total < 0.1) {
    samples.push_back(timed_run());
    total += samples.back();
  }
  std::nth_element(samples.begin(), samples.begin() + samples.size() / 2, samples.end());
  return samples[samples.size() / 2];
}

double time_engine(const Scene& scene, IntegratorKind integrator, double dt) {
  Scene stepped = scene;
  stepped.settings.integrator = integrator;
  stepped.dt = dt;
  stepped.output_dt = std::max(scene.duration, dt);
  return median_cpu_seconds([&stepped] {
    const auto space = build_space(stepped);
    const double start = cpu_now();
    run_scene(*space, stepped, [](double) {});
    return cpu_now() - start;
  });
}

Trajectory sample_at(const Trajectory& run, const std::vector<double>& instants) {
  Trajectory picked;
  picked.impacts = run.impacts;
  picked.cpu_seconds = run.cpu_seconds;
  std::size_t k = 0;
  for (double t : instants) {
    while (k + 1 < run.times.size() && run.times[k] < t - 1e-9) ++k;
    picked.times.push_back(run.times[k]);
    picked.states.push_back(run.states[k]);
  }
  return picked;
}

Scales scales_of(const Trajectory& run) {
  Scales s;
  for (const auto& states : run.states) {
    for (const BodyState& b : states) {
      s.position = std::max(s.position, b.position.norm());
      s.velocity = std::max(s.velocity, b.velocity.norm());
    }
  }
  return s;
}

std::vector<double> output_instants(double duration, double step) {
  const OutputTimes output(duration, step);
  std::vector<double> times;
  for (std::size_t k = 0; k < output.size(); ++k) times.push_back(output[k]);
  return times;
}

Trajectory first_instants(const Trajectory& t, std::size_t n) {
  Trajectory part;
  part.times.assign(t.times.begin(), t.times.begin() + static_cast<std::ptrdiff_t>(n));
  part.states.assign(t.states.begin(), t.states.begin() + static_cast<std::ptrdiff_t>(n));
  const double end = part.times.back();
  std::copy_if(t.impacts.begin(), t.impacts.end(), std::back_inserter(part.impacts),
               [end](const Impact& i) { return i.time <= end; });
  part.cpu_seconds = t.cpu_seconds;
  return part;
}

Differences compare(const Trajectory& run, const Trajectory& reference) {
  if (run.times.size() != reference.times.size()) {
    throw std::invalid_argument("compare: the runs have different output instants");
  }
  Differences d;
  for (std::size_t k = 0; k < run.times.size(); ++k) {
    const bool last = k + 1 == run.times.size();
    // At an instant on a reference impact (within 1e-9 s) the velocities jump: which side each
    // run reports there is a matter of t_c, which the collision-time figure judges.
    const bool on_impact =
        std::any_of(reference.impacts.begin(), reference.impacts.end(),
                    [&](const Impact& i) { return std::abs(i.time - run.times[k]) <= 1e-9; });
    for (std::size_t b = 0; b < run.states[k].size(); ++b) {
      const BodyState& x = run.states[k][b];
      const BodyState& y = reference.states[k][b];
      const double dp = (x.position - y.position).norm();
      const double dv = (x.velocity - y.velocity).norm();
      d.position = std::max(d.position, dp);
      d.orientation = std::max(d.orientation, angle_difference(x.angle, y.angle));
      if (!on_impact) {
        d.velocity = std::max(d.velocity, dv);
        d.angular_velocity =
            std::max(d.angular_velocity, std::abs(x.angular_velocity - y.angular_velocity));
      }
      if (last) {
        d.end_position = std::max(d.end_position, dp);
        if (!on_impact) d.end_velocity = std::max(d.end_velocity, dv);
      }
    }
  }
  // The k-th impact of a pair in one run is the k-th impact of that pair in the other.
  std::map<std::pair<BodyId, BodyId>, std::vector<double>> times_of, reference_times_of;
  const auto key = [](const Impact& i) { return std::minmax(i.body_a, i.body_b); };
  for (const Impact& i : run.impacts) times_of[key(i)].push_back(i.time);
  for (const Impact& i : reference.impacts) reference_times_of[key(i)].push_back(i.time);
  for (const auto& [pair, times] : times_of) {
    const auto& other = reference_times_of[pair];
    const std::size_t common = std::min(times.size(), other.size());
    for (std::size_t k = 0; k < common; ++k) {
      d.collision_time = std::max(d.collision_time, std::abs(times[k] - other[k]));
    }
    d.unmatched_impacts += times.size() - common;
  }
  for (const auto& [pair, other] : reference_times_of) {
    const auto found = times_of.find(pair);
    d.unmatched_impacts +=
        other.size() -
        std::min(other.size(), found == times_of.end() ? std::size_t{0} : found->second.size());
  }
  return d;
}

}  // namespace gp::verification
