// build/bin/gamephysics: the command line of GamePhysics.
#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>

#include "cli/commands.hpp"

int main(int argc, char** argv) {
  CLI::App app{"GamePhysics: a verification-driven 2D rigid-body physics library (SRS-traced)"};
  app.require_subcommand(1);
  // The repository whose srs/, tests/ and traceability/ the audit reads; the build's source tree
  // unless given.
  std::string root = GP_SOURCE_DIR;

  auto* verify = app.add_subcommand("verify", "Run the verification suite (the SRS audit)");
  verify->add_option("--root", root, "Repository root")->check(CLI::ExistingDirectory);

  bool check_only = false;
  std::string out;
  auto* trace = app.add_subcommand("trace", "Write traceability/ from the catalogue and the code");
  trace->add_option("--root", root, "Repository root")->check(CLI::ExistingDirectory);
  trace->add_option("--out", out, "Where to write (default: ROOT/traceability)");
  trace->add_flag("--check", check_only, "Write nothing; fail if the files in --out are stale");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  try {
    if (*verify) return gp::cli::verify(root);
    return gp::cli::trace(
        root,
        out.empty() ? std::filesystem::path(root) / "traceability" : std::filesystem::path(out),
        check_only);
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
}
