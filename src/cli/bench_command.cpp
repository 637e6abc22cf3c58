// `gamephysics bench`: runs build/bin/gamephysics_bench (verification/bench), which is built
// beside this program; it links Google Benchmark, which the command line need not.
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "cli/commands.hpp"

namespace gp::cli {

int bench(bool quick) {
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  const std::string program = (self.parent_path() / "gamephysics_bench").string();
  std::string quick_flag = "--quick";
  std::vector<char*> args{const_cast<char*>(program.c_str())};
  if (quick) args.push_back(quick_flag.data());
  args.push_back(nullptr);
  ::execv(program.c_str(), args.data());
  // execv returns only when it failed.
  std::cerr << "error: bench: cannot run " << program << ": " << std::strerror(errno) << "\n";
  return 2;
}

}  // namespace gp::cli
