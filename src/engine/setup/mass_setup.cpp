#include "engine/setup/mass_setup.hpp"

#include "engine/geometry/mass_properties.hpp"
#include "gamephysics/models/dd/center_of_mass.hpp"
#include "gamephysics/models/dd/moment_of_inertia.hpp"

namespace gp {

MassSetup mass_setup(const BodyDef& def) {
  // A body has few shapes; the vectors are filled once, when the body is created.
  std::vector<double> masses;
  std::vector<Vec2> centroids;
  double own_moments = 0.0, total = 0.0;
  for (const auto& s : def.shapes) {
    const MassProperties p = mass_properties(s.shape);
    if (p.area <= 0.0) continue;
    masses.push_back(s.density * p.area);
    centroids.push_back(p.centroid);
    own_moments += s.density * p.polar_moment;
    total += masses.back();
  }
  MassSetup setup{0.0, 0.0, Vec2::Zero()};
  if (total > 0.0) {
    setup.local_center = dd::center_of_mass(masses, centroids);
    setup.mass = total;
    setup.moment = own_moments + dd::moment_of_inertia(masses, centroids, setup.local_center);
  }
  if (def.mass) {
    // Scaling every density by the same factor keeps the centre and scales the moment alike.
    if (total > 0.0) setup.moment *= *def.mass / total;
    setup.mass = *def.mass;
  }
  if (def.moment) setup.moment = *def.moment;
  return setup;
}

}  // namespace gp
