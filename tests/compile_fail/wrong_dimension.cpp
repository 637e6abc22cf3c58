// A model function with a dimensional slip, written as models/ writes them: DD:linVel's
// displacement over a step taken as v̄ / h instead of v̄ h. With double and Vec2 it compiles (and
// is wrong); instantiated with units, as verification/dimensions/code_audit.cpp does, it must not.
// ctest builds it twice: as it is (must fail, naming the unit-carrying vector), and with
// GP_WITHOUT_SLIP (must compile, so the failure comes from the dimension alone).
#include "gamephysics/models/types.hpp"
#include "verification/dimensions/si_quantities.hpp"
#include "verification/dimensions/unit_vector.hpp"

namespace {

template <class Displacement = gp::Vec2, class Velocity = gp::Vec2, class Time = double>
Displacement displacement_from_velocity(gp::models::In<Velocity> mean_velocity,
                                        gp::models::In<Time> step) {
#ifdef GP_WITHOUT_SLIP
  return mean_velocity * step;
#else
  return mean_velocity / step;
#endif
}

}  // namespace

int main() {
  using namespace gp::verification;
  using namespace gp::verification::si_quantities;
  const gp::Vec2 with_doubles = displacement_from_velocity(gp::Vec2{2.51, 0.0}, 0.5);
  const auto with_units = displacement_from_velocity<UnitVec2<Length>, UnitVec2<Velocity>, Time>(
      {Velocity::from_value(2.51), Velocity::from_value(0.0)}, Time::from_value(0.5));
  return with_doubles.x() == with_units.x.value() ? 0 : 1;
}
