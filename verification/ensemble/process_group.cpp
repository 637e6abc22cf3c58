#include "verification/ensemble/process_group.hpp"

#include <chrono>
#include <cstdlib>
#include <list>
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

// A chunk in transit: its index in 8 bytes, then its text. Kept in a std::list so that the buffer
// stays put until its request completes.
struct Message {
  std::string bytes;
  MPI_Request request = MPI_REQUEST_NULL;
};

std::string encode(std::uint64_t chunk, const std::string& text) {
  std::string bytes(8, '\0');
  for (int b = 0; b < 8; ++b) bytes[b] = static_cast<char>((chunk >> 8 * b) & 0xff);
  return bytes + text;
}

std::uint64_t decoded_chunk(const std::string& bytes) {
  std::uint64_t chunk = 0;
  for (int b = 0; b < 8; ++b) {
    chunk |= std::uint64_t(static_cast<unsigned char>(bytes[b])) << 8 * b;
  }
  return chunk;
}

// Hands every completed message to `done` and drops it; also lets MPI progress the others.
template <typename Done>
void complete(std::list<Message>& messages, const Done& done) {
  for (auto it = messages.begin(); it != messages.end();) {
    int finished = 0;
    MPI_Test(&it->request, &finished, MPI_STATUS_IGNORE);
    if (!finished) {
      ++it;
      continue;
    }
    done(*it);
    it = messages.erase(it);
  }
}

// Rank 0 posts a receive for every chunk that has arrived (the matched probe takes each message
// once, however many a rank has sent) and stores those received, without blocking: chunks are
// above the eager limit, so a sender's chunk moves only once its receive is posted, and a blocking
// receive between rank 0's own chunks would leave the sender idle meanwhile.
void receive_chunks(std::list<Message>& incoming, std::size_t& received,
                    const std::function<void(std::uint64_t, const std::string&)>& store) {
  for (;;) {
    int arrived = 0;
    MPI_Message handle;
    MPI_Status status;
    MPI_Improbe(MPI_ANY_SOURCE, kChunkTag, MPI_COMM_WORLD, &arrived, &handle, &status);
    if (!arrived) break;
    int bytes = 0;
    MPI_Get_count(&status, MPI_CHAR, &bytes);
    Message& message = incoming.emplace_back();
    message.bytes.resize(static_cast<std::size_t>(bytes));
    MPI_Imrecv(message.bytes.data(), bytes, MPI_CHAR, &handle, &message.request);
  }
  complete(incoming, [&](const Message& message) {
    store(decoded_chunk(message.bytes), message.bytes.substr(8));
    ++received;
  });
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
  // Rank 0's receives, or this rank's sends, not yet completed.
  std::list<Message> pending;
  std::size_t received = 0;
  for (std::size_t k = static_cast<std::size_t>(rank_); k < chunks.size(); k += size_) {
    const std::string text = run(chunks[k]);
    if (root()) {
      store(chunks[k], text);
      ++received;
      // Store what the other ranks sent meanwhile, so that a stop loses as little as possible.
      receive_chunks(pending, received, store);
      continue;
    }
    // The send completes once rank 0 has posted its receive; this rank computes on meanwhile.
    Message& message = pending.emplace_back();
    message.bytes = encode(chunks[k], text);
    MPI_Isend(message.bytes.data(), static_cast<int>(message.bytes.size()), MPI_CHAR, 0, kChunkTag,
              MPI_COMM_WORLD, &message.request);
    complete(pending, [](const Message&) {});
  }
  for (;; nap()) {
    if (root()) {
      receive_chunks(pending, received, store);
      if (received == chunks.size()) break;
    } else {
      complete(pending, [](const Message&) {});
      if (pending.empty()) break;
    }
  }
  MPI_Request done;
  MPI_Ibarrier(MPI_COMM_WORLD, &done);
  wait_for(done);
#endif
}

}  // namespace gp::verification
