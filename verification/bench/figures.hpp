#pragma once
// The figures of one workload in one engine from the wall times of its repetitions: what the
// summary of gamephysics_bench and the speed section of `gamephysics verify` both report.

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "verification/bench/workloads.hpp"

namespace gp::bench {

/// Median, min, max and sample standard deviation of the wall time [ms] of one workload in one
/// engine, the body-steps per second of the median run and the watched body's displacement [m].
struct Figures {
  std::string workload;
  std::string engine;
  std::size_t repetitions = 0;
  double median_ms = 0.0, min_ms = 0.0, max_ms = 0.0, stddev_ms = 0.0;
  double body_steps_per_s = 0.0;
  double moved_m = -1.0;     ///< negative when the workload watches no body
  double heap_bytes = -1.0;  ///< held at the end of a run; negative when not measured
  std::size_t bodies = 0;    ///< of the workload's scene
  std::size_t steps = 0;     ///< of one run
};

/// The median of `v` (not empty): the middle value, or the mean of the two middle ones.
double median(std::vector<double> v);

/// Median, min, max and sample standard deviation of a set of measurements (0 for one).
struct Spread {
  double median, min, max, stddev;
};
/// The spread of `v` (not empty).
Spread spread_of(const std::vector<double>& v);

/// The figures of `repetitions` runs of `w` in `engine` whose wall times spread as `ms`.
Figures figures_of(const Workload& w, std::string engine, std::size_t repetitions, const Spread& ms,
                   double moved_m);
/// The figures of the repetitions of `w` in `engine` that took `ms` (not empty) each.
Figures figures_of(const Workload& w, std::string engine, const std::vector<double>& ms,
                   double moved_m);

/// Our median of f's workload over f's median (above 1: ours is slower; 1 on our own row), absent
/// when `all` has no figures of ours for that workload.
std::optional<double> ours_over_engine(const std::vector<Figures>& all, const Figures& f);

/// The heap each engine holds per body added from rain1000 to rain4000 [bytes]: the difference of
/// their heaps over the 3000 discs between them, which cancels what does not grow with the
/// bodies. One entry per engine that has heap figures of both, in the order of `all`.
std::vector<std::pair<std::string, double>> heap_per_added_body(const std::vector<Figures>& all);

/// How one engine's time per step grows from rain1000 to a larger rain [×], by the medians and by
/// the fastest runs, beside N log N's growth over the two scenes' bodies: issue 17 asks the time
/// per step from 1000 to 16,000 discs to grow no faster than that.
struct TimeGrowth {
  std::string engine;
  std::string workload;  ///< the larger rain
  double by_medians = 0.0;
  double by_fastest = 0.0;
  double n_log_n = 0.0;
};
/// One entry per engine and larger rain (rain4000, rain16000) that `all` has figures of beside
/// the engine's rain1000, in the order of `all`.
std::vector<TimeGrowth> time_growth_over_bodies(const std::vector<Figures>& all);

/// Bodies (static ones included, as every engine steps them) times steps, per second of a run of
/// `w` that took `ms`.
double body_steps_per_s(const Workload& w, double ms);

}  // namespace gp::bench
