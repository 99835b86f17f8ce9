#include "cli/mpi_run.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "checker/collective.hpp"

#ifdef TIOA_WITH_MPI
#include <mpi.h>
#endif

namespace cli {

namespace {

bool secondary = false;
int host_ranks = 1;     // the ranks on this machine
std::string held_error; // a secondary rank's error line, printed only if it is its own

#ifdef TIOA_WITH_MPI
// A round of an exchange cut into rounds (MPI's counts and displacements are ints): for
// each rank's `sizes` bytes, the count of the next `piece` bytes from `done` on, and its
// displacement. Returns the round's total.
std::size_t round_counts(const std::vector<std::uint64_t>& sizes, std::uint64_t done,
                         std::uint64_t piece, std::vector<int>& counts,
                         std::vector<int>& displacements) {
  int at = 0;
  for (std::size_t r = 0; r < sizes.size(); ++r) {
    const std::uint64_t left = sizes[r] > done ? sizes[r] - done : 0;
    counts[r] = static_cast<int>(std::min(left, piece));
    displacements[r] = at;
    at += counts[r];
  }
  return static_cast<std::size_t>(at);
}

// The checker's collective calls over MPI_COMM_WORLD. Messages are cut into rounds that
// MPI's int counts can say.
class MpiCollective final : public checker::Collective {
public:
  MpiCollective(int rank, int size) : rank_(rank), size_(size) {}
  int rank() const override { return rank_; }
  int size() const override { return size_; }

  std::vector<std::uint8_t> all_to_all(const std::vector<std::uint8_t>& data,
                                       const std::vector<std::uint64_t>& offsets) override {
    const auto n = static_cast<std::size_t>(size_);
    std::vector<std::uint64_t> send_sizes(n), receive_sizes(n);
    for (std::size_t r = 0; r < n; ++r)
      send_sizes[r] = offsets[r + 1] - offsets[r];
    MPI_Alltoall(send_sizes.data(), 1, MPI_UINT64_T, receive_sizes.data(), 1, MPI_UINT64_T,
                 MPI_COMM_WORLD);
    std::vector<std::uint64_t> receive_at(n + 1, 0);
    for (std::size_t r = 0; r < n; ++r)
      receive_at[r + 1] = receive_at[r] + receive_sizes[r];
    std::vector<std::uint8_t> out(receive_at[n]);
    // Rounds of at most `piece` bytes per pair until every pair is done; a round's counts
    // and displacements are ints, so the n pairs of a round stay under 2^31 bytes.
    const std::uint64_t piece = std::uint64_t{std::numeric_limits<int>::max()} / n;
    std::uint64_t longest = 0;
    for (std::size_t r = 0; r < n; ++r)
      longest = std::max({longest, send_sizes[r], receive_sizes[r]});
    longest = max(longest);
    std::vector<int> sc(n), sd(n), rc(n), rd(n);
    std::vector<std::uint8_t> send_round, receive_round;
    std::uint64_t done = 0;
    do {
      send_round.resize(round_counts(send_sizes, done, piece, sc, sd));
      for (std::size_t r = 0; r < n; ++r)
        if (sc[r] > 0)
          std::memcpy(send_round.data() + sd[r], data.data() + offsets[r] + done,
                      static_cast<std::size_t>(sc[r]));
      receive_round.resize(round_counts(receive_sizes, done, piece, rc, rd));
      MPI_Alltoallv(send_round.data(), sc.data(), sd.data(), MPI_BYTE, receive_round.data(),
                    rc.data(), rd.data(), MPI_BYTE, MPI_COMM_WORLD);
      for (std::size_t r = 0; r < n; ++r)
        if (rc[r] > 0)
          std::memcpy(out.data() + receive_at[r] + done, receive_round.data() + rd[r],
                      static_cast<std::size_t>(rc[r]));
      done += piece;
    } while (done < longest);
    return out;
  }

  std::vector<std::uint8_t> all_gather(const std::vector<std::uint8_t>& mine,
                                       std::vector<std::uint64_t>& sizes) override {
    const auto n = static_cast<std::size_t>(size_);
    std::vector<std::uint64_t> offsets(n + 1, 0);
    sizes.assign(n, 0);
    const std::uint64_t my_size = mine.size();
    MPI_Allgather(&my_size, 1, MPI_UINT64_T, sizes.data(), 1, MPI_UINT64_T, MPI_COMM_WORLD);
    for (std::size_t r = 0; r < n; ++r)
      offsets[r + 1] = offsets[r] + sizes[r];
    std::vector<std::uint8_t> out(offsets[n]);
    // Rounds of at most `piece` bytes of each rank, as all_to_all.
    const std::uint64_t piece = std::uint64_t{std::numeric_limits<int>::max()} / n;
    const std::uint64_t longest = *std::max_element(sizes.begin(), sizes.end());
    std::vector<int> counts(n), displacements(n);
    std::vector<std::uint8_t> round;
    std::uint64_t done = 0;
    do {
      round.resize(round_counts(sizes, done, piece, counts, displacements));
      const int mine_now = counts[static_cast<std::size_t>(rank_)];
      MPI_Allgatherv(mine.data() + std::min<std::uint64_t>(done, mine.size()), mine_now, MPI_BYTE,
                     round.data(), counts.data(), displacements.data(), MPI_BYTE, MPI_COMM_WORLD);
      for (std::size_t r = 0; r < n; ++r)
        if (counts[r] > 0)
          std::memcpy(out.data() + offsets[r] + done, round.data() + displacements[r],
                      static_cast<std::size_t>(counts[r]));
      done += piece;
    } while (done < longest);
    return out;
  }

  std::uint64_t sum(std::uint64_t value) override { return reduce(value, MPI_SUM); }
  std::uint64_t min(std::uint64_t value) override { return reduce(value, MPI_MIN); }
  std::uint64_t max(std::uint64_t value) override { return reduce(value, MPI_MAX); }

private:
  std::uint64_t reduce(std::uint64_t value, MPI_Op op) {
    std::uint64_t out = 0;
    MPI_Allreduce(&value, &out, 1, MPI_UINT64_T, op, MPI_COMM_WORLD);
    return out;
  }
  int rank_, size_;
};

std::optional<MpiCollective> collective;
MPI_Comm finish_comm = MPI_COMM_NULL; // MpiRun::finish()'s barrier
#endif

int environment_int(const char* name) {
  const char* value = std::getenv(name);
  return value ? std::atoi(value) : 0;
}

} // namespace

int launched_ranks() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"})
    if (const int n = environment_int(name); n > 0)
      return n;
  return 1;
}

int ranks_on_this_host() {
  return host_ranks;
}

bool secondary_rank() {
  return secondary;
}

void hold_error(const std::string& line) {
  held_error = line;
}

MpiRun::MpiRun(int& argc, char**& argv) {
  if (launched_ranks() <= 1)
    return;
#ifdef TIOA_WITH_MPI
  // Threads of a rank explore; only the thread that called main calls MPI.
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  initialised_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  MPI_Comm_dup(MPI_COMM_WORLD, &finish_comm);
  MPI_Comm host;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &host);
  MPI_Comm_size(host, &host_ranks);
  MPI_Comm_free(&host);
  secondary = rank_ > 0;
  if (secondary) // rank 0 writes the reports
    if (!std::freopen("/dev/null", "w", stdout))
      std::cout.setstate(std::ios::badbit);
  collective.emplace(rank_, size_);
  checker::set_distributed(&*collective);
#else
  (void)argc;
  (void)argv;
  size_ = launched_ranks();
#endif
}

int MpiRun::finish(int code) {
#ifdef TIOA_WITH_MPI
  if (!initialised_)
    return code;
  std::cout.flush();
  // Every rank that ends comes here; on a communicator of its own, so that a rank still
  // inside an exchange of the checker's does not match it.
  MPI_Request request;
  MPI_Ibarrier(finish_comm, &request);
  const auto began = std::chrono::steady_clock::now();
  for (int done = 0;;) {
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done)
      return code;
    if (code == 2 && std::chrono::steady_clock::now() - began > std::chrono::seconds(5))
      break; // this rank's error is its own: the others wait for it in an exchange
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (!held_error.empty())
    std::cerr << held_error << " (rank " << rank_ << " of " << size_ << ")" << std::endl;
  std::cerr.flush();
  MPI_Abort(MPI_COMM_WORLD, code);
#endif
  return code;
}

MpiRun::~MpiRun() {
#ifdef TIOA_WITH_MPI
  if (initialised_) {
    checker::set_distributed(nullptr);
    MPI_Comm_free(&finish_comm);
    MPI_Finalize();
  }
#endif
}

} // namespace cli
