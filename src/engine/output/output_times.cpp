#include "engine/output/output_times.hpp"

#include <cmath>

namespace gp {

namespace {
constexpr double kEndTolerance = 1e-9;  // of output_dt
}  // namespace

OutputTimes::OutputTimes(double duration, double output_dt)
    : duration_(duration), output_dt_(output_dt), before_end_(0) {
  if (duration <= 0.0) return;  // t = 0 is the end
  const double end = duration - kEndTolerance * output_dt;
  // t = 0 is reported even when the end is closer to it than the tolerance.
  if (end <= 0.0) {
    before_end_ = 1;
    return;
  }
  // The count of k with k·output_dt < end: the quotient, corrected for its rounding.
  auto count = static_cast<std::size_t>(std::ceil(end / output_dt));
  while (count > 1 && static_cast<double>(count - 1) * output_dt >= end) --count;
  while (static_cast<double>(count) * output_dt < end) ++count;
  before_end_ = count;
}

}  // namespace gp
