#pragma once
// newtop sweep across the ranks of MPI (sweep_mpi.cpp; Open MPI when the build found it).

#include <optional>

#include "newtop/sweep/sweep.hpp"

namespace newtop::app {

/// MPI for the life of a sweep: initialised only when the process was started by mpirun, mpiexec
/// or srun (their environment says so), finalised on the way out.
class MpiSession {
 public:
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  int rank() const { return rank_; }
  /// Rank 0's `ok`, known to every rank (a collective call: every rank must make it).
  bool confirm(bool ok) const;
  int size() const { return size_; }

 private:
  bool initialised_ = false;
  int rank_ = 0, size_ = 1;
};

/// With more than one rank: rank 0 reads the checkpoint, hands out batches of points
/// (sweep::batch_size: one point, or a batch for the ensemble stepper) to the ranks that ask
/// (dynamic balancing), records their results (checkpoint, progress) and returns
/// the run; the other ranks compute and return nullopt. Bad input on rank 0 (a checkpoint without
/// --resume) ends every rank: rank 0 throws it, the others throw a silent InputError.
std::optional<sweep::SweepRun> run_sweep_ranks(const MpiSession& mpi, const sweep::SweepFile& s,
                                               const sweep::RunOptions& o);

}  // namespace newtop::app
