#include "verification/ensemble/process_group.hpp"

#include <chrono>
#include <cstdlib>
#include <thread>

#ifdef GP_WITH_MPI
#include <mpi.h>
#endif

namespace gp::verification {

namespace {

#ifdef GP_WITH_MPI
constexpr int kChunkTag = 1;

// Open MPI busy-waits in blocking calls; a rank that waits (rank 0 for the others' chunks, the
// others at the end) would take a core from a rank that computes when the ranks outnumber the
// cores. Waiting is done by polling with a millisecond's sleep instead.
void nap() {
  std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

void wait_for(MPI_Request& request) {
  for (int done = 0;; nap()) {
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done) return;
  }
}

// Rank 0's receipt of one chunk from any rank, if one has arrived (or, with `wait`, once one
// has): its index in 8 bytes, then its text.
bool receive_chunk(const std::function<void(std::uint64_t, const std::string&)>& store, bool wait) {
  MPI_Status status;
  for (int arrived = 0; !arrived; nap()) {
    MPI_Iprobe(MPI_ANY_SOURCE, kChunkTag, MPI_COMM_WORLD, &arrived, &status);
    if (!arrived && !wait) return false;
  }
  int bytes = 0;
  MPI_Get_count(&status, MPI_CHAR, &bytes);
  std::string message(static_cast<std::size_t>(bytes), '\0');
  MPI_Recv(message.data(), bytes, MPI_CHAR, status.MPI_SOURCE, kChunkTag, MPI_COMM_WORLD,
           MPI_STATUS_IGNORE);
  std::uint64_t chunk = 0;
  for (int b = 0; b < 8; ++b) {
    chunk |= std::uint64_t(static_cast<unsigned char>(message[b])) << 8 * b;
  }
  store(chunk, message.substr(8));
  return true;
}

void send_chunk(std::uint64_t chunk, const std::string& text) {
  std::string message(8, '\0');
  for (int b = 0; b < 8; ++b) message[b] = static_cast<char>((chunk >> 8 * b) & 0xff);
  message += text;
  MPI_Request request;
  MPI_Isend(message.data(), static_cast<int>(message.size()), MPI_CHAR, 0, kChunkTag,
            MPI_COMM_WORLD, &request);
  wait_for(request);
}
#endif

}  // namespace

ProcessGroup::ProcessGroup() {
#ifdef GP_WITH_MPI
  if (!launched()) return;
  MPI_Init(nullptr, nullptr);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  mpi_ = true;
#endif
}

ProcessGroup::~ProcessGroup() {
#ifdef GP_WITH_MPI
  if (mpi_) MPI_Finalize();
#endif
}

bool ProcessGroup::launched() {
  // Open MPI's mpirun, PMIx launchers (srun --mpi=pmix) and PMI-1/2 launchers set one of these.
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"}) {
    if (std::getenv(name)) return true;
  }
  return false;
}

bool ProcessGroup::built_with_mpi() {
#ifdef GP_WITH_MPI
  return true;
#else
  return false;
#endif
}

std::optional<std::vector<std::uint64_t>> ProcessGroup::share(
    const std::vector<std::uint64_t>& chunks, bool abort) const {
  if (!mpi_) return abort ? std::nullopt : std::optional(chunks);
#ifdef GP_WITH_MPI
  // The count first (-1: rank 0 gave up), then the indices.
  long long count = abort ? -1 : static_cast<long long>(chunks.size());
  MPI_Bcast(&count, 1, MPI_LONG_LONG, 0, MPI_COMM_WORLD);
  if (count < 0) return std::nullopt;
  std::vector<std::uint64_t> shared =
      root() ? chunks : std::vector<std::uint64_t>(static_cast<std::size_t>(count));
  MPI_Bcast(shared.data(), static_cast<int>(count), MPI_UINT64_T, 0, MPI_COMM_WORLD);
  return shared;
#endif
  return std::nullopt;
}

void ProcessGroup::run_chunks(
    const std::vector<std::uint64_t>& chunks, const std::function<std::string(std::uint64_t)>& run,
    const std::function<void(std::uint64_t, const std::string&)>& store) const {
  if (!mpi_) {
    for (std::uint64_t chunk : chunks) store(chunk, run(chunk));
    return;
  }
#ifdef GP_WITH_MPI
  std::size_t received = 0;
  for (std::size_t k = static_cast<std::size_t>(rank_); k < chunks.size(); k += size_) {
    const std::string text = run(chunks[k]);
    if (!root()) {
      send_chunk(chunks[k], text);
      continue;
    }
    store(chunks[k], text);
    ++received;
    // Store what the other ranks sent meanwhile, so that a stop loses as little as possible.
    while (receive_chunk(store, false)) ++received;
  }
  if (root()) {
    for (; received < chunks.size(); ++received) receive_chunk(store, true);
  }
  MPI_Request done;
  MPI_Ibarrier(MPI_COMM_WORLD, &done);
  wait_for(done);
#endif
}

}  // namespace gp::verification
