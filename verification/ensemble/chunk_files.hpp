#pragma once
// An ensemble's folder on disk: chunks/chunk_NNNNNN.csv, one file per completed chunk (its text
// from Ensemble::run_chunk), from which samples.csv and energy.csv are assembled in sample order.

#include <cstdint>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace gp::verification {

/// DIR/chunks/chunk_NNNNNN.csv.
std::filesystem::path chunk_path(const std::filesystem::path& dir, std::uint64_t chunk);

/// The chunks below `count` with no file in `dir` yet, in order.
std::vector<std::uint64_t> missing_chunks(const std::filesystem::path& dir, std::uint64_t count);

/// Writes `samples_header` and every chunk's "S," lines to `samples`, and `energy_header` and its
/// "E," lines to `energy`, chunk after chunk. Throws std::runtime_error when a chunk file is
/// missing or unreadable.
void assemble_chunks(const std::filesystem::path& dir, std::uint64_t count,
                     const std::string& samples_header, const std::string& energy_header,
                     std::ostream& samples, std::ostream& energy);

}  // namespace gp::verification
