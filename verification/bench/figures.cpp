#include "verification/bench/figures.hpp"

#include <algorithm>
#include <cmath>
#include <string_view>

#include "verification/bench/bench_engine.hpp"

namespace gp::bench {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2.0;
}

namespace {

double sample_stddev(const std::vector<double>& v) {
  if (v.size() < 2) return 0.0;
  double mean = 0.0;
  for (double x : v) mean += x;
  mean /= static_cast<double>(v.size());
  double squares = 0.0;
  for (double x : v) squares += (x - mean) * (x - mean);
  return std::sqrt(squares / static_cast<double>(v.size() - 1));
}

// The figures of `workload` in `engine` among `all`, which holds at most one of each pair (as
// figures() makes them), or none.
const Figures* figures_for(const std::vector<Figures>& all, std::string_view workload,
                           std::string_view engine) {
  const auto found = std::find_if(all.begin(), all.end(), [&](const Figures& f) {
    return f.workload == workload && f.engine == engine;
  });
  return found == all.end() ? nullptr : &*found;
}

}  // namespace

Spread spread_of(const std::vector<double>& v) {
  const auto [min, max] = std::minmax_element(v.begin(), v.end());
  return {median(v), *min, *max, sample_stddev(v)};
}

Figures figures_of(const Workload& w, std::string engine, const std::vector<double>& ms,
                   double moved_m) {
  return figures_of(w, std::move(engine), ms.size(), spread_of(ms), moved_m);
}

Figures figures_of(const Workload& w, std::string engine, std::size_t repetitions, const Spread& ms,
                   double moved_m) {
  Figures f{w.name, std::move(engine), repetitions};
  f.median_ms = ms.median;
  f.min_ms = ms.min;
  f.max_ms = ms.max;
  f.stddev_ms = ms.stddev;
  f.body_steps_per_s = body_steps_per_s(w, f.median_ms);
  f.moved_m = moved_m;
  f.bodies = w.scene.bodies.size();
  f.steps = static_cast<std::size_t>(w.steps);
  return f;
}

std::optional<double> ours_over_engine(const std::vector<Figures>& all, const Figures& f) {
  const Figures* ours = figures_for(all, f.workload, engine_label(Engine::Ours));
  if (ours == nullptr) return std::nullopt;
  return ours->median_ms / f.median_ms;
}

std::vector<std::pair<std::string, double>> heap_per_added_body(const std::vector<Figures>& all) {
  const auto heap_of = [&all](const std::string& workload, const std::string& engine) {
    const Figures* f = figures_for(all, workload, engine);
    return f != nullptr && f->heap_bytes >= 0.0 ? f->heap_bytes : -1.0;
  };
  std::vector<std::pair<std::string, double>> per_body;
  for (const Figures& f : all) {
    if (f.workload != "rain1000") continue;
    const double small = heap_of("rain1000", f.engine);
    const double large = heap_of("rain4000", f.engine);
    if (small >= 0.0 && large >= 0.0) per_body.emplace_back(f.engine, (large - small) / 3000.0);
  }
  return per_body;
}

std::vector<TimeGrowth> time_growth_over_bodies(const std::vector<Figures>& all) {
  const auto per_step = [](double ms, const Figures& f) {
    return ms / static_cast<double>(f.steps);
  };
  const auto n_log_n = [](const Figures& f) {
    const auto n = static_cast<double>(f.bodies);
    return n * std::log(n);
  };
  std::vector<TimeGrowth> growth;
  for (const Figures& small : all) {
    if (small.workload != "rain1000" || small.steps == 0 || small.bodies < 2) continue;
    for (const char* workload : {"rain4000", "rain16000"}) {
      const Figures* large = figures_for(all, workload, small.engine);
      if (large == nullptr || large->steps == 0) continue;
      growth.push_back({small.engine, workload,
                        per_step(large->median_ms, *large) / per_step(small.median_ms, small),
                        per_step(large->min_ms, *large) / per_step(small.min_ms, small),
                        n_log_n(*large) / n_log_n(small)});
    }
  }
  return growth;
}

double body_steps_per_s(const Workload& w, double ms) {
  return static_cast<double>(w.scene.bodies.size()) * w.steps / (ms / 1e3);
}

}  // namespace gp::bench
