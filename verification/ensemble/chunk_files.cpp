#include "verification/ensemble/chunk_files.hpp"

#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace gp::verification {

std::filesystem::path chunk_path(const std::filesystem::path& dir, std::uint64_t chunk) {
  char name[40];
  std::snprintf(name, sizeof name, "chunk_%06llu.csv", static_cast<unsigned long long>(chunk));
  return dir / "chunks" / name;
}

std::vector<std::uint64_t> missing_chunks(const std::filesystem::path& dir, std::uint64_t count) {
  std::vector<std::uint64_t> missing;
  for (std::uint64_t c = 0; c < count; ++c) {
    if (!std::filesystem::exists(chunk_path(dir, c))) missing.push_back(c);
  }
  return missing;
}

void assemble_chunks(const std::filesystem::path& dir, std::uint64_t count,
                     const std::string& samples_header, const std::string& energy_header,
                     std::ostream& samples, std::ostream& energy) {
  samples << samples_header << '\n';
  energy << energy_header << '\n';
  for (std::uint64_t c = 0; c < count; ++c) {
    std::ifstream in(chunk_path(dir, c), std::ios::binary);
    if (!in) throw std::runtime_error("cannot read " + chunk_path(dir, c).string());
    for (std::string line; std::getline(in, line);) {
      std::ostream& out = line.starts_with("S,") ? samples : energy;
      out.write(line.data() + 2, static_cast<std::streamsize>(line.size() - 2)) << '\n';
    }
  }
}

}  // namespace gp::verification
