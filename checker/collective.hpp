#pragma once
// Exploration over several processes (issue 18): what the ranks of a distributed run
// exchange, as an interface the checker calls. The MPI implementation is in
// cli/mpi_collective.*, so the checker itself does not depend on MPI; a plain build has no
// implementation and never runs distributed.
//
// Every call is collective: every rank makes the same calls in the same order.

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace checker {

class Collective {
public:
  virtual ~Collective() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  // Sends bytes [offsets[r], offsets[r + 1]) of `data` to rank r (offsets has size() + 1
  // entries); returns what every rank sent this one, in rank order, one after the other.
  virtual std::vector<std::uint8_t> all_to_all(const std::vector<std::uint8_t>& data,
                                               const std::vector<std::uint64_t>& offsets) = 0;
  // Every rank's bytes, in rank order, on every rank (`sizes`: how many came from each).
  virtual std::vector<std::uint8_t> all_gather(const std::vector<std::uint8_t>& mine,
                                               std::vector<std::uint64_t>& sizes) = 0;
  virtual std::uint64_t sum(std::uint64_t value) = 0;
  virtual std::uint64_t min(std::uint64_t value) = 0;
  virtual std::uint64_t max(std::uint64_t value) = 0;
};

// Appends `bytes` bytes from `data` to `out` (a message being built).
inline void append_bytes(std::vector<std::uint8_t>& out, const void* data, std::size_t bytes) {
  const auto* p = static_cast<const std::uint8_t*>(data);
  out.insert(out.end(), p, p + bytes);
}

// The ranks of this run when it runs distributed (more than one process), else null.
Collective* distributed();
// Set once by the program that runs under mpirun (null: one process), for the thread that
// runs the checks.
void set_distributed(Collective* ranks);

// A check asked for in a distributed run that runs on one process only: one clear line,
// never a run that would answer for part of the states.
struct NotDistributed : std::runtime_error {
  using std::runtime_error::runtime_error;
};

} // namespace checker
