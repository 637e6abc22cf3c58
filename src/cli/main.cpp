// build/bin/gamephysics: the command line of GamePhysics.
#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>

#include "cli/commands.hpp"
#include "cli/scene_options.hpp"
#include "verification/peers/peer_world.hpp"

int main(int argc, char** argv) {
  CLI::App app{"GamePhysics: a verification-driven 2D rigid-body physics library (SRS-traced)"};
  app.require_subcommand(1);
  // The repository whose srs/, tests/ and traceability/ the audit reads; the build's source tree
  // unless given.
  std::string root = GP_SOURCE_DIR;

  gp::cli::VerifyOptions verification;
  std::string report = "out/report";
  auto* verify = app.add_subcommand(
      "verify", "The main job: SRS audit, then every scene against the SUNDIALS oracle; report");
  verify->add_option("--root", root, "Repository root")->check(CLI::ExistingDirectory);
  verify->add_option("--out", report, "Report folder (default out/report)");
  verify->add_flag("--quick", verification.quick, "Short runs only (what ctest runs)");
  verify
      ->add_option("--test-results", verification.test_results,
                   "JUnit report of the Catch2 tests (gamephysics_tests -r junit)")
      ->check(CLI::ExistingFile);
  verify->add_flag("--long", verification.long_runs,
                   "Long runs of rain1000 and pyramid20 at 1e6 steps each (hours)");
  verify
      ->add_option("--speed-repetitions", verification.speed_repetitions,
                   "Runs of each workload in each engine, speed against the peers (default 3)")
      ->check(CLI::PositiveNumber);

  bool check_only = false;
  std::string out;
  auto* trace = app.add_subcommand("trace", "Write traceability/ from the catalogue and the code");
  trace->add_option("--root", root, "Repository root")->check(CLI::ExistingDirectory);
  trace->add_option("--out", out, "Where to write (default: ROOT/traceability)");
  trace->add_flag("--check", check_only, "Write nothing; fail if the files in --out are stale");

  gp::cli::SimulateOptions simulation;
  auto* simulate =
      app.add_subcommand("simulate", "Run a scene file (docs/scene-format.md), write CSV");
  gp::cli::add_scene_options(*simulate, simulation.scene, simulation.overrides,
                             gp::cli::kEveryOverride);
  simulate->add_option("--out", simulation.out, "Trajectory CSV to write");
  simulate->add_flag("--explain", simulation.explain,
                     "Print the pipeline of a step (runs nothing unless --out is given; with "
                     "--out, then the wall time of each stage)");
  simulate->add_option("--threads", simulation.threads,
                       "Threads of a step (default: 1; 0: every core); the output is the same");
  simulate->add_option("--lanes", simulation.lanes,
                       "Doubles the step's SIMD paths take at a time: 1, 2 (SSE2) or 4 (AVX2) "
                       "(default: the widest the CPU has); the output is the same");

  gp::cli::OracleCommandOptions oracle_run;
  auto* oracle = app.add_subcommand(
      "oracle", "Integrate a scene file with the SUNDIALS oracle, write CSV like simulate");
  gp::cli::add_scene_options(*oracle, oracle_run.scene, oracle_run.overrides,
                             gp::cli::kDuration | gp::cli::kOutputInterval);
  oracle->add_option("--out", oracle_run.out, "Trajectory CSV to write")->required();
  oracle->add_option("--events", oracle_run.events, "Impact log CSV to write");
  oracle->add_option("--method", oracle_run.method,
                     "cvode-adams (default), cvode-bdf, arkode-erk, or time-stepping (piles)");
  oracle->add_option("--rtol", oracle_run.rtol, "Relative tolerance, > 0 (default 1e-10)");
  oracle->add_option("--atol", oracle_run.atol, "Absolute tolerance, > 0 (default 1e-10)");
  oracle->add_option("--step", oracle_run.step,
                     "time-stepping's largest step [s], > 0 (default 1e-3; first order)");

  gp::cli::PeerOptions peer_run;
  auto* peer = app.add_subcommand("peer", "Run a scene file in Chipmunk2D or Box2D, write CSV");
  gp::cli::add_scene_options(*peer, peer_run.scene, peer_run.overrides,
                             gp::cli::kStep | gp::cli::kDuration | gp::cli::kOutputInterval);
  peer->add_option("--engine", peer_run.engine, gp::peers::engine_choices())->required();
  peer->add_option("--config", peer_run.config,
                   "matched (our physics, the default) or default (as the peer's users run it)");
  peer->add_option("--out", peer_run.out, "Trajectory CSV to write")->required();

  gp::cli::ViewOptions view_run;
  auto* view = app.add_subcommand(
      "view", "Run a scene file, write one self-contained HTML page that plays it back");
  gp::cli::add_scene_options(*view, view_run.scene, view_run.overrides, gp::cli::kEveryOverride);
  view->add_option("--out", view_run.out, "HTML page to write")->required();
  view->add_flag("--oracle", view_run.oracle, "Overlay the SUNDIALS oracle's solution");
  view->add_option("--audit", view_run.audit,
                   "The audit page as the page links to it (e.g. audit.html beside it): each SRS "
                   "id links to its entry there");

  std::string audit_out = "out/report";
  auto* audit = app.add_subcommand("audit", "The SRS audit alone, and its page OUT/audit.html");
  audit->add_option("--root", root, "Repository root")->check(CLI::ExistingDirectory);
  std::optional<std::filesystem::path> audit_results;
  audit->add_option("--out", audit_out, "Report folder (default out/report)");
  audit
      ->add_option("--test-results", audit_results,
                   "JUnit report of the Catch2 tests (gamephysics_tests -r junit)")
      ->check(CLI::ExistingFile);
  gp::cli::LongRunOptions long_run;
  auto* longrun = app.add_subcommand(
      "longrun", "Step a scene file N times: no NaN, no body leaving its box, no memory growth");
  longrun->add_option("scene", long_run.scene, "Scene file (JSON)")->required();
  longrun->add_option("--steps", long_run.steps, "Steps of the scene's dt (default 1e6)")
      ->check(CLI::PositiveNumber);
  longrun->add_option("--bodies", long_run.bodies, "Keep only the first N bodies of the file")
      ->check(CLI::PositiveNumber);

  gp::cli::EnsembleOptions ensemble_run;
  auto* ensemble = app.add_subcommand(
      "ensemble", "Run a scene many times with its inputs drawn within their uncertainties");
  gp::cli::add_scene_options(*ensemble, ensemble_run.scene, ensemble_run.overrides,
                             gp::cli::kEveryOverride);
  ensemble->add_option("--samples", ensemble_run.samples, "Number of samples")->required();
  ensemble->add_option("--uncertainty", ensemble_run.uncertainty,
                       "srs (the SRS's typical uncertainties, default) or a JSON file of spreads");
  ensemble->add_option("--sampler", ensemble_run.sampler, "sobol (default) or random");
  ensemble->add_option("--seed", ensemble_run.seed, "Seed of the sampler (default 0)");
  ensemble->add_option("--out", ensemble_run.out, "Folder to write")->required();
  ensemble->add_flag("--resume", ensemble_run.resume, "Continue the ensemble in --out");
  ensemble->add_option("--threads", ensemble_run.threads, "Threads per process (default: all)");
  ensemble->add_flag("--oracle", ensemble_run.oracle,
                     "Run each sample in the SUNDIALS oracle too and record the engine's error");
  ensemble->add_flag("--no-plots", ensemble_run.no_plots, "Do not make the plots");
  ensemble->add_flag("--compare-numerical-error", ensemble_run.compare_numerical_error,
                     "Per integrator: is its numerical error below the input spread?");

  bool quick_bench = false;
  auto* bench = app.add_subcommand("bench", "Benchmarks: ours, Chipmunk2D and Box2D, one run");
  bench->add_flag("--quick", quick_bench, "Fewer repetitions");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  try {
    if (*verify) {
      verification.root = root;
      verification.out = report;
      return gp::cli::verify(verification);
    }
    if (*peer) return gp::cli::peer(peer_run);
    if (*bench) return gp::cli::bench(quick_bench);
    if (*simulate) return gp::cli::simulate(simulation);
    if (*view) return gp::cli::view(view_run);
    if (*audit) return gp::cli::audit(root, audit_out, audit_results);
    if (*oracle) return gp::cli::oracle(oracle_run);
    if (*longrun) return gp::cli::longrun(long_run);
    if (*ensemble) return gp::cli::ensemble(ensemble_run);
    return gp::cli::trace(
        root,
        out.empty() ? std::filesystem::path(root) / "traceability" : std::filesystem::path(out),
        check_only);
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
}
