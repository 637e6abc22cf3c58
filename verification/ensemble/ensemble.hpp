#pragma once
// An ensemble: a scene run many times with its inputs drawn within their uncertainties. Samples
// are grouped in chunks of kChunkSamples, the unit of work that is run in parallel, sent between
// processes, written to disk and skipped on resume. A chunk's text depends only on the setup and
// its index: not on the threads, the processes or what ran before.

#include <cstdint>
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "verification/ensemble/perturbation.hpp"
#include "verification/ensemble/sample_table.hpp"
#include "verification/ensemble/sampler.hpp"
#include "verification/ensemble/uncertainty.hpp"

namespace gp::verification {

inline constexpr std::uint64_t kChunkSamples = 32;

struct EnsembleSetup {
  Scene nominal;
  Spreads spreads;
  Sampler sampler = Sampler::Sobol;
  std::uint64_t seed = 0;
  std::uint64_t samples = 0;
  bool with_oracle = false;  ///< compare each sample with the oracle (scenes in its domain)
};

class Ensemble {
 public:
  /// Throws std::invalid_argument when the sampler cannot draw the scene's inputs (Sobol beyond
  /// its dimensions).
  explicit Ensemble(EnsembleSetup setup);

  const EnsembleSetup& setup() const { return setup_; }
  const std::vector<PerturbedInput>& inputs() const { return inputs_; }
  const SampleTable& table() const { return table_; }
  std::uint64_t chunk_count() const;

  /// The values of sample `index`'s perturbed inputs (in the order of inputs()).
  std::vector<double> sample_inputs(std::uint64_t index) const;

  /// Runs the samples of `chunk`, in parallel on the threads oneTBB allows, and returns its text:
  /// a line "S,<samples.csv row>" per sample, then a line "E,<energy.csv row>" per sample, in
  /// sample order.
  std::string run_chunk(std::uint64_t chunk) const;

 private:
  EnsembleSetup setup_;
  std::vector<PerturbedInput> inputs_;
  SampleTable table_;
};

}  // namespace gp::verification
