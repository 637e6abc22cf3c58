#include "verification/ensemble/perturbation.hpp"

#include <algorithm>
#include <functional>

namespace gp::verification {

namespace {

// Visits every perturbed number of `scene` in the order of perturbed_inputs, with its name, its
// spread and a reference to it (a density factor is visited through a local it then applies).
void visit_inputs(Scene& scene, const Spreads& spreads,
                  const std::function<void(const std::string&, double&, double)>& visit) {
  auto maybe = [&](const std::string& name, double& value, std::string_view field) {
    const double u = spreads.of(field);
    if (value != 0.0 && u > 0.0) visit(name, value, u);
  };
  maybe("dt", scene.dt, "dt");
  for (BodyDef& body : scene.bodies) {
    if (body.type != BodyType::Static) {
      if (body.mass) {
        maybe(body.name + ".mass", *body.mass, "mass");
      } else {
        double factor = 1.0;
        maybe(body.name + ".density_factor", factor, "mass");
        for (ShapeDef& shape : body.shapes) shape.density *= factor;
      }
      if (body.moment) maybe(body.name + ".moment", *body.moment, "moment");
      maybe(body.name + ".x", body.position.x(), "position");
      maybe(body.name + ".y", body.position.y(), "position");
      maybe(body.name + ".angle", body.angle, "angle");
      maybe(body.name + ".vx", body.velocity.x(), "velocity");
      maybe(body.name + ".vy", body.velocity.y(), "velocity");
      maybe(body.name + ".omega", body.angular_velocity, "angular_velocity");
    }
    for (std::size_t s = 0; s < body.shapes.size(); ++s) {
      const std::string shape = body.name + ".shape" + std::to_string(s);
      maybe(shape + ".restitution", body.shapes[s].restitution, "restitution");
      maybe(shape + ".friction", body.shapes[s].friction, "friction");
    }
  }
}

}  // namespace

std::vector<PerturbedInput> perturbed_inputs(const Scene& scene, const Spreads& spreads) {
  Scene copy = scene;
  std::vector<PerturbedInput> inputs;
  visit_inputs(copy, spreads, [&](const std::string& name, double& value, double u) {
    inputs.push_back({name, value, u});
  });
  return inputs;
}

std::vector<double> input_values(std::span<const PerturbedInput> inputs,
                                 std::span<const double> u) {
  std::vector<double> values(inputs.size());
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    values[k] = inputs[k].nominal * (1.0 + inputs[k].relative * (2.0 * u[k] - 1.0));
    if (inputs[k].name.ends_with(".restitution")) values[k] = std::clamp(values[k], 0.0, 1.0);
  }
  return values;
}

Scene perturbed_scene(const Scene& scene, const Spreads& spreads, std::span<const double> values) {
  Scene perturbed = scene;
  std::size_t k = 0;
  visit_inputs(perturbed, spreads,
               [&](const std::string&, double& value, double) { value = values[k++]; });
  return perturbed;
}

}  // namespace gp::verification
