#pragma once
// The inputs of a scene an ensemble perturbs, and a scene with them perturbed by a point of the
// unit hypercube. Inputs that are zero in the scene, or whose spread is zero, are left alone: a
// relative uncertainty of zero is zero.

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "verification/ensemble/uncertainty.hpp"

namespace gp::verification {

/// One perturbed input: a named number of the scene with its relative half-width.
struct PerturbedInput {
  std::string name;  ///< "dt", "ball.mass", "ball.density_factor", "ground.shape0.restitution"...
  double nominal;    ///< the scene's value (1 for a density factor)
  double relative;   ///< u [1]: drawn from [nominal (1 − u), nominal (1 + u)]
};

/// The inputs of `scene` to perturb, in a fixed order: the step; then per body, in file order,
/// for moving (dynamic and kinematic) bodies the mass (or, without one, a factor on the shapes'
/// densities), the moment when given, x, y, ϕ, v_x, v_y, ω; and for every body its shapes' C_R
/// and μ. Static bodies keep their place: the frame of reference is not uncertain.
std::vector<PerturbedInput> perturbed_inputs(const Scene& scene, const Spreads& spreads);

/// The values of `inputs` at the point `u` of [0, 1)^n (n = inputs.size()): nominal (1 + u_r (2 u
/// − 1)), C_R clamped to its SRS range [0, 1].
std::vector<double> input_values(std::span<const PerturbedInput> inputs, std::span<const double> u);

/// `scene` with `values` (from input_values, in the order of perturbed_inputs(scene, spreads)).
Scene perturbed_scene(const Scene& scene, const Spreads& spreads, std::span<const double> values);

}  // namespace gp::verification
