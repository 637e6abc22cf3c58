#include "verification/ensemble/error_against_spread.hpp"

#include <tbb/parallel_for.h>

#include <cmath>
#include <stdexcept>

#include "verification/ensemble/perturbation.hpp"
#include "verification/ensemble/sample_run.hpp"
#include "verification/oracle/oracle.hpp"
#include "verification/suite/oracle_domain.hpp"

namespace gp::verification {

namespace {

// A finer step for the reference of scenes outside the oracle's domain: RK4 at dt / 16 has an
// error 16^4 ≈ 6.6e4 times smaller than RK4 at dt on smooth motion.
constexpr double kFinerStep = 16.0;

std::vector<BodyState> final_states(const Scene& scene) {
  SampleOutputs run = run_sample(scene, false);
  if (!run.error.empty()) throw std::runtime_error(run.error);
  return run.final_states;
}

std::vector<std::size_t> moving_bodies(const Scene& scene) {
  std::vector<std::size_t> moving;
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    if (scene.bodies[b].type != BodyType::Static) moving.push_back(b);
  }
  return moving;
}

}  // namespace

std::vector<ErrorAgainstSpread> error_against_spread(const Scene& scene, const Spreads& spreads,
                                                     std::uint64_t samples, std::uint64_t seed,
                                                     bool oracle_reference) {
  const std::vector<std::size_t> moving = moving_bodies(scene);
  std::vector<BodyState> reference;
  std::string reference_name;
  if (oracle_reference) {
    try {
      const std::vector<double> end{scene.duration};
      reference = run_oracle(scene, end, reference_options(scene)).states.back();
      reference_name = "oracle (cvode-adams, rtol 1e-12)";
    } catch (const OracleDomainError& e) {
      reference_name = std::string("rk4 at dt/16 (the oracle stopped ") + e.what() + ")";
    }
  }
  if (reference.empty()) {
    Scene finer = scene;
    finer.settings.integrator = IntegratorKind::RK4;
    finer.dt = scene.dt / kFinerStep;
    reference = final_states(finer);
    if (reference_name.empty()) reference_name = "rk4 at dt/16 (outside the oracle's domain)";
  }
  const std::vector<PerturbedInput> inputs = perturbed_inputs(scene, spreads);
  std::vector<ErrorAgainstSpread> rows;
  for (IntegratorKind kind :
       {IntegratorKind::SymplecticEuler, IntegratorKind::VelocityVerlet, IntegratorKind::RK4}) {
    Scene nominal = scene;
    nominal.settings.integrator = kind;
    const std::vector<BodyState> ours = final_states(nominal);
    double squares = 0.0;
    for (std::size_t b : moving)
      squares += (ours[b].position - reference[b].position).squaredNorm();
    ErrorAgainstSpread row{std::string(integrator_name(kind)),
                           scene.dt,
                           std::sqrt(squares / static_cast<double>(moving.size())),
                           reference_name,
                           0.0,
                           0,
                           0};
    std::vector<SampleOutputs> runs(samples);
    tbb::parallel_for(std::uint64_t{0}, samples, [&](std::uint64_t i) {
      const auto values = input_values(inputs, unit_point(Sampler::Sobol, seed, inputs.size(), i));
      runs[i] = run_sample(perturbed_scene(nominal, spreads, values), false);
      runs[i].energy.clear();  // only the final states are needed: keep the memory small
    });
    for (const SampleOutputs& r : runs) row.samples += r.error.empty() ? 1 : 0;
    row.failed = samples - row.samples;
    if (row.samples < 2) throw std::runtime_error("fewer than 2 samples ran");
    // Per body, the variance of x plus that of y; then the RMS over bodies of its root.
    double variance_sum = 0.0;
    for (std::size_t b : moving) {
      Vec2 mean = Vec2::Zero();
      for (const SampleOutputs& r : runs) {
        if (r.error.empty()) mean += r.final_states[b].position;
      }
      mean /= static_cast<double>(row.samples);
      double squares_b = 0.0;
      for (const SampleOutputs& r : runs) {
        if (r.error.empty()) squares_b += (r.final_states[b].position - mean).squaredNorm();
      }
      variance_sum += squares_b / static_cast<double>(row.samples - 1);
    }
    row.input_spread = std::sqrt(variance_sum / static_cast<double>(moving.size()));
    rows.push_back(row);
  }
  return rows;
}

}  // namespace gp::verification
