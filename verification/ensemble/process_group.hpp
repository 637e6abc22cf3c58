#pragma once
// The processes an ensemble runs on: the MPI ranks when the program was started by an MPI
// launcher (mpirun, srun) and built with MPI, else this process alone. Rank 0 decides what is left
// to run, every rank runs its share of the chunks, and rank 0 receives and stores them all.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace gp::verification {

class ProcessGroup {
 public:
  /// Initialises MPI when built with it and started by a launcher (its environment says so).
  ProcessGroup();
  ~ProcessGroup();
  ProcessGroup(const ProcessGroup&) = delete;
  ProcessGroup& operator=(const ProcessGroup&) = delete;

  /// Whether this build can run across processes (GP_WITH_MPI).
  static bool built_with_mpi();
  /// Whether an MPI launcher started this process (its environment says so).
  static bool launched();

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool root() const { return rank_ == 0; }

  /// Rank 0's `chunks`, on every rank; nothing when rank 0 gave up (it passes `abort`).
  std::optional<std::vector<std::uint64_t>> share(const std::vector<std::uint64_t>& chunks,
                                                  bool abort) const;

  /// Runs `run(chunk)` for this rank's share of `chunks` (every size()-th, from rank()) and calls
  /// `store(chunk, text)` on rank 0 for every chunk, as they arrive.
  void run_chunks(const std::vector<std::uint64_t>& chunks,
                  const std::function<std::string(std::uint64_t)>& run,
                  const std::function<void(std::uint64_t, const std::string&)>& store) const;

 private:
  int rank_ = 0;
  int size_ = 1;
  bool mpi_ = false;
};

}  // namespace gp::verification
