#pragma once
// The instants at which a run reports its state.

#include <cstddef>

namespace gp {

/// t_k = k·output_dt (k = 0, 1, …) while before the end, then the end itself: every output
/// instant is exact, and the end is always one. An instant within 1e-9·output_dt of the end is
/// taken as the end, so that 10 intervals of 0.1 s end at 1 s once, not at 0.9999999999999999 s
/// and again at 1 s.
class OutputTimes {
 public:
  /// duration [s] finite and ≥ 0, output_dt [s] finite and > 0, duration / output_dt ≤ about 1e15
  /// (load_scene allows far less).
  OutputTimes(double duration, double output_dt);

  /// How many instants: at least 1 (t = 0, which is the end when duration = 0).
  std::size_t size() const { return before_end_ + 1; }
  /// Instant k [s], k < size().
  double operator[](std::size_t k) const {
    return k < before_end_ ? static_cast<double>(k) * output_dt_ : duration_;
  }

 private:
  double duration_;
  double output_dt_;
  std::size_t before_end_;  // the instants k·output_dt before the end
};

}  // namespace gp
