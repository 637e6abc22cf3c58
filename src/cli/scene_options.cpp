#include "cli/scene_options.hpp"

namespace gp::cli {

void add_scene_options(CLI::App& command, std::filesystem::path& scene, SceneOverrides& overrides,
                       unsigned which) {
  command.add_option("scene", scene, "Scene file (JSON)")->required();
  if (which & kIntegrator) {
    command.add_option("--integrator", overrides.integrator,
                       "symplectic_euler, velocity_verlet or rk4 (overrides the file)");
  }
  if (which & kStep) {
    command.add_option("--dt", overrides.dt, "Time step [s] (overrides the file)");
  }
  if (which & kDuration) {
    command.add_option("--duration", overrides.duration, "Simulated time [s] (overrides the file)");
  }
  if (which & kOutputInterval) {
    command.add_option("--output-dt", overrides.output_dt,
                       "Interval between output rows [s] (overrides the file)");
  }
}

}  // namespace gp::cli
