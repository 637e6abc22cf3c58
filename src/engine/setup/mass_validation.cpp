#include "engine/setup/mass_validation.hpp"

#include <cmath>
#include <stdexcept>

#include "engine/setup/mass_setup.hpp"
#include "engine/setup/shape_offset.hpp"
#include "scene/input_error.hpp"
#include "scene/validation.hpp"

namespace gp {

void validate_derived_mass(const BodyDef& def, const std::string& prefix) {
  const MassSetup setup = mass_setup(def);
  const bool dynamic = def.type == BodyType::Dynamic;
  if (!std::isfinite(setup.mass) || !std::isfinite(setup.moment) ||
      !setup.local_center.allFinite() || (dynamic && !(setup.mass > 0.0))) {
    throw InputError(prefix + ".shapes",
                     "must give the body a finite mass (> 0 if dynamic), centre of mass and "
                     "moment of inertia",
                     "mass " + number_text(setup.mass) + ", moment " + number_text(setup.moment) +
                         ", centre " + number_text(setup.local_center));
  }
  for (std::size_t k = 0; k < def.shapes.size(); ++k) {
    try {
      translated(def.shapes[k].shape, -setup.local_center);
    } catch (const std::invalid_argument& e) {
      throw InputError(prefix + ".shapes[" + std::to_string(k) + "]",
                       "must stay finite about the body's centre of mass", e.what());
    }
  }
}

}  // namespace gp
