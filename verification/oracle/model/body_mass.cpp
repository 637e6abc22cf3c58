#include "verification/oracle/model/body_mass.hpp"

#include <variant>
#include <vector>

#include "gamephysics/models/dd/center_of_mass.hpp"
#include "gamephysics/models/dd/moment_of_inertia.hpp"
#include "verification/oracle/model/shape_integrals.hpp"

namespace gp::oracle {

namespace {

ShapeIntegrals integrals_of(const Circle& disc) {
  return disc_integrals(disc.center, disc.radius);
}

ShapeIntegrals integrals_of(const ConvexPolygon& polygon) {
  return polygon_integrals(std::span<const Vec2>(polygon.vertices.data(), polygon.count));
}

ShapeIntegrals integrals_of(const Segment& segment) {
  return capsule_integrals(segment.a, segment.b, segment.radius);
}

}  // namespace

BodyMass body_mass(const BodyDef& body) {
  std::vector<double> masses;
  std::vector<Vec2> centroids;
  double own_moments = 0.0;  // kg·m²: each shape's moment about its own centroid
  for (const ShapeDef& shape : body.shapes) {
    const ShapeIntegrals s = std::visit([](const auto& geometry) { return integrals_of(geometry); },
                                        shape.shape.geometry());
    if (s.area == 0.0) continue;  // a bare segment
    masses.push_back(shape.density * s.area);
    centroids.push_back(s.centroid);
    own_moments += shape.density * s.polar_moment;
  }
  BodyMass result{0.0, 0.0, Vec2::Zero()};
  if (!masses.empty()) {
    result.center = dd::center_of_mass(masses, centroids);
    for (const double m : masses) result.mass += m;
    result.moment = own_moments + dd::moment_of_inertia(masses, centroids, result.center);
  }
  if (body.mass) {
    if (result.mass > 0.0) result.moment *= *body.mass / result.mass;
    result.mass = *body.mass;
  }
  if (body.moment) result.moment = *body.moment;
  return result;
}

}  // namespace gp::oracle
