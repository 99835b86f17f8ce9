#pragma once

#include <string>
// A run under mpirun (issue 18). Launched by mpirun with more than one process, and built
// with MPI, tioa-check joins the other ranks and the checks that run distributed
// (checker/distributed_explorer.hpp) share the states among them; no option is needed.
// Rank 0 writes the reports; the other ranks write nothing on standard output and no
// file. Without MPI in the build, a launch with several processes is refused (each
// would check the whole model alone and print it).
//
// Ending: every rank makes the same collective calls, so a verdict ends them together, and
// an error in what every rank reads (a bad option, a check that does not run distributed)
// too: rank 0 prints its line, the others hold theirs. An error of one rank alone (its
// memory, say) leaves the others waiting in an exchange: after 5 s that rank prints its
// line with its rank and aborts the run (MPI_Abort) rather than let it hang.

namespace cli {

class MpiRun {
public:
  MpiRun(int& argc, char**& argv);
  ~MpiRun();
  MpiRun(const MpiRun&) = delete;
  MpiRun& operator=(const MpiRun&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  // The exit code of this rank; an error aborts every rank (see above).
  int finish(int code);

private:
  int rank_ = 0, size_ = 1;
  bool initialised_ = false;
};

// Whether this process is a rank of a distributed run other than the first (it prints no
// error line: rank 0 prints the same one).
bool secondary_rank();

// On a secondary rank, the error line it would print (finish() prints it if the error is
// its own).
void hold_error(const std::string& line);

// The ranks of this run on this machine (1 when not distributed): they share its cores, so
// each rank's default number of threads is its share.
int ranks_on_this_host();

// The number of processes mpirun launched, from its environment (1 when not under mpirun).
int launched_ranks();

} // namespace cli
