// `gamephysics ensemble`: a scene run many times with its inputs drawn within their uncertainties
// (verification/ensemble, docs/ensembles.md), on every core and every MPI rank.
#include <tbb/global_control.h>

#include <chrono>
#include <exception>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>

#include "cli/commands.hpp"
#include "cli/interrupt_cleanup.hpp"
#include "cli/partial_file.hpp"
#include "cli/thread_limit.hpp"
#include "scene/input_error.hpp"
#include "scene/json_fields.hpp"
#include "verification/ensemble/chunk_files.hpp"
#include "verification/ensemble/ensemble.hpp"
#include "verification/ensemble/ensemble_report.hpp"
#include "verification/ensemble/error_against_spread.hpp"
#include "verification/ensemble/process_group.hpp"
#include "verification/ensemble/summary.hpp"
#include "verification/long_run/long_run.hpp"
#include "verification/suite/oracle_domain.hpp"
#include "verification/suite/report.hpp"

namespace gp::cli {

namespace {

using verification::Ensemble;
using verification::EnsembleSetup;

// The setup of the command line; throws InputError naming the option or the file's field, with
// `blamed` the file it is in (the scene, or the uncertainty file).
EnsembleSetup setup_of(const EnsembleOptions& o, std::string& blamed) {
  EnsembleSetup s;
  s.nominal = load_scene(o.scene, o.overrides);
  if (o.samples == 0) throw InputError("--samples", "must be > 0", "0");
  s.samples = o.samples;
  const auto sampler = verification::sampler_from_name(o.sampler);
  if (!sampler) throw InputError("--sampler", "must be sobol or random", o.sampler);
  s.sampler = *sampler;
  s.seed = o.seed;
  blamed = o.uncertainty;
  s.spreads = o.uncertainty == "srs" ? verification::srs_spreads()
                                     : verification::read_spreads(o.uncertainty);
  blamed = o.scene.string();
  // A scene declared outside the oracle's domain would only record the declaration per sample, and
  // a chaotic pile's samples have no trajectory to compare.
  if (const auto reason = verification::no_oracle_trajectory(o.scene.stem().string());
      o.oracle && reason) {
    throw InputError("--oracle", "needs a scene in the oracle's domain", std::string(*reason));
  }
  s.with_oracle = o.oracle;
  return s;
}

// ensemble.json: everything that decides the samples' rows, so that --resume can refuse a
// folder made with other settings.
nlohmann::ordered_json manifest_of(const Ensemble& e, const std::filesystem::path& scene) {
  const EnsembleSetup& s = e.setup();
  nlohmann::ordered_json m;
  m["scene"] = scene.filename().string();
  m["integrator"] = integrator_name(s.nominal.settings.integrator);
  m["dt"] = s.nominal.dt;
  m["duration"] = s.nominal.duration;
  m["output_dt"] = s.nominal.output_dt;
  m["samples"] = s.samples;
  m["sampler"] = verification::sampler_name(s.sampler);
  m["seed"] = s.seed;
  m["chunk_samples"] = verification::kChunkSamples;
  m["oracle"] = s.with_oracle;
  for (const verification::Spread& spread : s.spreads.fields) {
    m["spreads"][std::string(spread.field)] = {{"relative", spread.relative},
                                               {"source", spread.source}};
  }
  m["inputs"] = nlohmann::ordered_json::array();
  for (const verification::PerturbedInput& input : e.inputs()) {
    m["inputs"].push_back(
        {{"name", input.name}, {"nominal", input.nominal}, {"relative", input.relative}});
  }
  return m;
}

void write_file(const std::filesystem::path& target, const std::string& text) {
  PartialFile file(target);
  file.stream() << text;
  file.commit();
}

// Makes `out` ready: a new ensemble, or (with --resume) the same one. Throws InputError.
void prepare_folder(const std::filesystem::path& out, const nlohmann::ordered_json& manifest,
                    bool resume) {
  const std::filesystem::path file = out / "ensemble.json";
  const std::string text = manifest.dump(2) + "\n";
  if (std::filesystem::exists(file)) {
    if (!resume) {
      throw InputError("--out", "holds an ensemble already (give --resume, or another folder)",
                       out.string());
    }
    std::ifstream in(file, std::ios::binary);
    const std::string old((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (old != text) {
      throw InputError(
          "--resume",
          "needs the settings the ensemble in --out was started with (" + file.string() + ")",
          out.string());
    }
    return;
  }
  std::error_code error;
  std::filesystem::create_directories(out / "chunks", error);
  if (error) throw InputError("--out", "must be a folder that can be created", out.string());
  write_file(file, text);
}

// samples.csv, energy.csv, summary.json, the plots and report.md, from the chunk files.
void write_results(const Ensemble& e, const std::filesystem::path& out,
                   const nlohmann::ordered_json& manifest, bool plots) {
  {
    PartialFile samples(out / "samples.csv"), energy(out / "energy.csv");
    verification::assemble_chunks(out, e.chunk_count(), e.table().samples_header(),
                                  e.table().energy_header(), samples.stream(), energy.stream());
    samples.commit();
    energy.commit();
  }
  std::ifstream samples(out / "samples.csv", std::ios::binary);
  const nlohmann::ordered_json summary = verification::summarize_samples(samples);
  write_file(out / "summary.json", summary.dump(2) + "\n");
  const std::vector<std::string> pictures =
      plots ? verification::make_plots(
                  std::filesystem::path(GP_SOURCE_DIR) / "verification" / "ensemble" / "plots.py",
                  out)
            : std::vector<std::string>{};
  PartialFile report(out / "report.md");
  verification::write_ensemble_report(report.stream(), manifest, summary, pictures);
  report.commit();
}

// --compare-numerical-error: the table of error_against_spread, printed and written into `out`.
int compare(const EnsembleSetup& setup, const EnsembleOptions& options) {
  const std::string name = options.scene.stem().string();
  const auto rows =
      verification::error_against_spread(setup.nominal, setup.spreads, setup.samples, setup.seed,
                                         !verification::no_oracle_trajectory(name).has_value());
  std::filesystem::create_directories(options.out);
  PartialFile csv(options.out / "numerical_error_vs_spread.csv");
  PartialFile md(options.out / "numerical_error_vs_spread.md");
  csv.stream() << "scene,integrator,dt,numerical_error,reference,input_spread,samples,failed,"
                  "error_below_spread\n";
  md.stream() << "| scene | integrator | dt [s] | numerical error [m] | input spread [m] | "
                 "error below spread? | reference |\n|---|---|---:|---:|---:|---|---|\n";
  for (const auto& r : rows) {
    csv.stream() << name << "," << r.integrator << "," << verification::number_text(r.dt) << ","
                 << verification::number_text(r.numerical_error) << ",\"" << r.reference << "\","
                 << verification::number_text(r.input_spread) << "," << r.samples << "," << r.failed
                 << "," << (r.below() ? "yes" : "no") << "\n";
    md.stream() << "| " << name << " | " << r.integrator << " | " << verification::figure(r.dt)
                << " | " << verification::figure(r.numerical_error) << " | "
                << verification::figure(r.input_spread) << " | " << (r.below() ? "yes" : "**no**")
                << " | " << r.reference << " |\n";
  }
  csv.commit();
  md.commit();
  std::ifstream table(options.out / "numerical_error_vs_spread.md");
  std::cout << table.rdbuf();
  return 0;
}

}  // namespace

int ensemble(const EnsembleOptions& options) {
  install_interrupt_cleanup();
  const verification::ProcessGroup group;
  const std::string file = options.scene.string();
  std::string blamed = file;
  std::optional<Ensemble> e;
  std::optional<tbb::global_control> threads;
  try {
    limit_threads(threads, options.threads);
    if (verification::ProcessGroup::launched() && !verification::ProcessGroup::built_with_mpi()) {
      throw InputError("(build)", "was built without MPI: run it without mpirun",
                       "GP_WITH_MPI=OFF");
    }
    e.emplace(setup_of(options, blamed));
  } catch (const std::exception& error) {  // InputError, or a sampler that cannot draw the inputs
    if (group.root()) std::cerr << "error: " << blamed << ": " << error.what() << "\n";
    return kBadInput;
  }
  if (options.compare_numerical_error) {
    if (!group.root()) return 0;  // one process: the comparison uses the threads
    try {
      return compare(e->setup(), options);
    } catch (const std::exception& error) {
      std::cerr << "error: " << file << ": " << error.what() << "\n";
      return kRunFailed;
    }
  }
  const nlohmann::ordered_json manifest = manifest_of(*e, options.scene);
  std::vector<std::uint64_t> missing;
  bool abort = false;
  if (group.root()) {
    try {
      prepare_folder(options.out, manifest, options.resume);
      missing = verification::missing_chunks(options.out, e->chunk_count());
    } catch (const std::exception& error) {
      std::cerr << "error: " << file << ": " << error.what() << "\n";
      abort = true;
    }
  }
  const auto shared = group.share(missing, abort);
  if (!shared) return kBadInput;
  const std::vector<std::uint64_t>& todo = *shared;
  if (group.root()) {
    std::cout << "ensemble of " << file << ": " << e->setup().samples << " samples, "
              << e->inputs().size() << " perturbed inputs, "
              << (e->setup().with_oracle ? "compared with the oracle" : "without the oracle")
              << "; " << todo.size() << " of " << e->chunk_count() << " chunks to run on "
              << group.size() << (group.size() == 1 ? " process" : " processes")
              << (verification::ProcessGroup::built_with_mpi()
                      ? ""
                      : " (built without MPI: one machine)")
              << "\n";
  }
  const auto start = std::chrono::steady_clock::now();
  std::size_t stored = 0;
  try {
    group.run_chunks(
        todo, [&](std::uint64_t chunk) { return e->run_chunk(chunk); },
        [&](std::uint64_t chunk, const std::string& text) {
          write_file(verification::chunk_path(options.out, chunk), text);
          ++stored;
          if (stored * 10 / todo.size() != (stored - 1) * 10 / todo.size()) {
            std::cout << "  " << stored << "/" << todo.size() << " chunks, resident memory "
                      << verification::figure(verification::resident_mib()) << " MiB\n"
                      << std::flush;
          }
        });
    if (!group.root()) return 0;
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    write_results(*e, options.out, manifest, !options.no_plots);
    std::uint64_t ran = 0;
    for (std::uint64_t chunk : todo) {
      ran += std::min(verification::kChunkSamples,
                      e->setup().samples - chunk * verification::kChunkSamples);
    }
    std::cout << "wrote " << options.out.string() << ": ran " << ran << " samples in "
              << verification::figure(seconds) << " s ("
              << verification::figure(static_cast<double>(ran) / seconds) << " samples/s on "
              << group.size() << " x "
              << tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism)
              << " threads)\n";
  } catch (const std::exception& error) {  // a file could not be written
    std::cerr << "error: " << file << ": " << error.what() << "\n";
    return kRunFailed;
  }
  return 0;
}

}  // namespace gp::cli
