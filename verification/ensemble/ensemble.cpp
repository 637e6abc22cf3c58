#include "verification/ensemble/ensemble.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>

#include "engine/output/output_times.hpp"

namespace gp::verification {

namespace {

std::vector<double> output_instants(const Scene& scene) {
  const OutputTimes instants(scene.duration, scene.output_dt);
  std::vector<double> times(instants.size());
  for (std::size_t k = 0; k < instants.size(); ++k) times[k] = instants[k];
  return times;
}

}  // namespace

Ensemble::Ensemble(EnsembleSetup setup)
    : setup_(std::move(setup)),
      inputs_(perturbed_inputs(setup_.nominal, setup_.spreads)),
      table_(setup_.nominal, inputs_, setup_.with_oracle, output_instants(setup_.nominal)) {
  sample_inputs(0);  // a sampler that cannot draw these inputs fails here, not in a worker
}

std::uint64_t Ensemble::chunk_count() const {
  return (setup_.samples + kChunkSamples - 1) / kChunkSamples;
}

std::vector<double> Ensemble::sample_inputs(std::uint64_t index) const {
  return input_values(inputs_, unit_point(setup_.sampler, setup_.seed, inputs_.size(), index));
}

std::string Ensemble::run_chunk(std::uint64_t chunk) const {
  const std::uint64_t first = chunk * kChunkSamples;
  const std::uint64_t count = std::min(kChunkSamples, setup_.samples - first);
  std::vector<std::string> rows(count), energies(count);
  tbb::parallel_for(std::uint64_t{0}, count, [&](std::uint64_t k) {
    const std::vector<double> values = sample_inputs(first + k);
    const Scene scene = perturbed_scene(setup_.nominal, setup_.spreads, values);
    const SampleOutputs outputs = run_sample(scene, setup_.with_oracle);
    rows[k] = table_.samples_row(first + k, values, outputs);
    energies[k] = table_.energy_row(first + k, outputs);
  });
  std::string text;
  for (const std::string& row : rows) text += "S," + row + "\n";
  for (const std::string& row : energies) text += "E," + row + "\n";
  return text;
}

}  // namespace gp::verification
