#pragma once
// The rows of an ensemble's two tables, as CSV text: samples.csv (a sample's inputs under their
// scene names, e.g. "ball.y"; its final state, "final.ball.y"; its impact times; its final energy;
// the oracle's comparison; its error) and energy.csv (a sample's total
// energy at every output instant). Numbers are written in their shortest round-trip form, so that
// a row depends on its sample alone and every run writes the same bytes.

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "verification/ensemble/perturbation.hpp"
#include "verification/ensemble/sample_run.hpp"

namespace gp::verification {

class SampleTable {
 public:
  /// The columns of `nominal`'s ensemble: its perturbed `inputs`, its moving bodies, the oracle's
  /// columns when `with_oracle`, and the energy at `times` [s].
  SampleTable(const Scene& nominal, std::vector<PerturbedInput> inputs, bool with_oracle,
              std::vector<double> times);

  std::string samples_header() const;
  std::string energy_header() const;
  /// samples.csv's row of sample `index`, with its input `values` (no newline).
  std::string samples_row(std::uint64_t index, std::span<const double> values,
                          const SampleOutputs& outputs) const;
  /// energy.csv's row of sample `index`; instants after a failure are empty (no newline).
  std::string energy_row(std::uint64_t index, const SampleOutputs& outputs) const;

 private:
  std::vector<PerturbedInput> inputs_;
  std::vector<std::size_t> moving_;  ///< indices of the dynamic and kinematic bodies
  std::vector<std::string> names_;   ///< of every body
  bool with_oracle_;
  std::vector<double> times_;
};

/// `value` in its shortest round-trip form ("0.1", "1e-12", "nan").
std::string number_text(double value);

}  // namespace gp::verification
