// newtop sweep across the ranks of MPI: rank 0 hands out batches of point indices on request and
// writes; the others compute each batch as a thread of run_sweep does (sweep::evaluate_batch: the
// ensemble stepper for a trajectory sweep, point by point otherwise). A result travels as one line
// of the checkpoint's format (17 significant digits), so it arrives as the same bits; each point's
// result is its own run's whatever the batch, so the output does not depend on the number of ranks
// (docs/sweep.md).

#include "sweep_mpi.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "newtop/sweep/sweep_ensemble.hpp"

#ifdef NEWTOP_WITH_MPI
#include <mpi.h>
#endif

namespace newtop::app {

#ifdef NEWTOP_WITH_MPI
namespace {

constexpr int kRequest = 1;  // a worker asks for a batch (carrying the last batch's results)
constexpr int kPoints = 2;   // rank 0 sends a batch of point indices; an empty one: stop

bool launched_by_mpi() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMI_SIZE") || std::getenv("PMIX_RANK");
}

void worker(const sweep::SweepFile& s) {
  std::string message;  // empty: the first request
  for (;;) {
    MPI_Send(message.data(), static_cast<int>(message.size()), MPI_CHAR, 0, kRequest,
             MPI_COMM_WORLD);
    MPI_Status status;
    MPI_Probe(0, kPoints, MPI_COMM_WORLD, &status);
    int count = 0;
    MPI_Get_count(&status, MPI_UINT64_T, &count);
    std::vector<std::uint64_t> batch(static_cast<std::size_t>(count));
    MPI_Recv(batch.data(), count, MPI_UINT64_T, 0, kPoints, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (batch.empty()) return;
    const std::vector<std::size_t> indices(batch.begin(), batch.end());
    const std::vector<sweep::PointResult> r = sweep::evaluate_batch(s, indices);
    message.clear();
    for (std::size_t k = 0; k < indices.size(); ++k) {
      message += sweep::encode_result(indices[k], r[k]);
    }
  }
}

sweep::SweepRun coordinator(int size, const sweep::SweepFile& s, sweep::SweepLedger& ledger,
                            const sweep::RunOptions& o) {
  const std::size_t width = sweep::quantity_columns(s).size();
  const std::vector<std::size_t>& todo = ledger.todo();
  // Batches as the threads of run_sweep take them, for the worker ranks (dynamic balancing: a
  // batch goes to whichever rank asks next).
  const std::size_t batch = sweep::batch_size(s, todo.size(), size - 1);
  std::size_t next = 0;
  bool stopped = false;
  int active = size - 1;
  while (active > 0) {
    MPI_Status status;
    MPI_Probe(MPI_ANY_SOURCE, kRequest, MPI_COMM_WORLD, &status);
    int length = 0;
    MPI_Get_count(&status, MPI_CHAR, &length);
    std::string message(static_cast<std::size_t>(length), '\0');
    MPI_Recv(message.data(), length, MPI_CHAR, status.MPI_SOURCE, kRequest, MPI_COMM_WORLD,
             MPI_STATUS_IGNORE);
    std::istringstream lines(message);
    std::string line;
    while (std::getline(lines, line)) {
      auto r = sweep::decode_result(line + '\n', width);
      if (!r) throw std::runtime_error("sweep: a rank sent a result that does not read back");
      ledger.record(r->first, std::move(r->second));
    }
    if (!stopped && o.stop && o.stop()) stopped = true;
    std::vector<std::uint64_t> indices;
    if (!stopped) {
      const std::size_t end = std::min(todo.size(), next + batch);
      indices.assign(todo.begin() + static_cast<std::ptrdiff_t>(next),
                     todo.begin() + static_cast<std::ptrdiff_t>(end));
      next = end;
    }
    if (indices.empty()) --active;
    MPI_Send(indices.data(), static_cast<int>(indices.size()), MPI_UINT64_T, status.MPI_SOURCE,
             kPoints, MPI_COMM_WORLD);
  }
  return ledger.finish(!stopped && next == todo.size(), size - 1);
}

}  // namespace

MpiSession::MpiSession() {
  if (!launched_by_mpi()) return;
  MPI_Init(nullptr, nullptr);
  initialised_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiSession::~MpiSession() {
  if (initialised_) MPI_Finalize();
}

bool MpiSession::confirm(bool ok) const {
  if (!initialised_) return ok;
  int flag = ok ? 1 : 0;
  MPI_Bcast(&flag, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return flag != 0;
}

std::optional<sweep::SweepRun> run_sweep_ranks(const MpiSession& mpi, const sweep::SweepFile& s,
                                               const sweep::RunOptions& o) {
  std::unique_ptr<sweep::SweepLedger> ledger;
  std::string error;
  if (mpi.rank() == 0) {
    try {
      ledger = std::make_unique<sweep::SweepLedger>(s, o);
    } catch (const InputError& e) {
      error = e.what();
    }
  }
  if (!mpi.confirm(error.empty())) throw InputError(mpi.rank() == 0 ? error : "");
  if (mpi.rank() != 0) {
    worker(s);
    return std::nullopt;
  }
  return coordinator(mpi.size(), s, *ledger, o);
}

#else

MpiSession::MpiSession() {
  // Started by mpirun without MPI in the build, every rank would run the whole sweep and write the
  // same files.
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) {
    const char* v = std::getenv(name);
    if (v && std::atoi(v) > 1) {
      throw InputError("mpirun: this build has no MPI (install libopenmpi-dev and rebuild)");
    }
  }
}
MpiSession::~MpiSession() = default;
bool MpiSession::confirm(bool ok) const { return ok; }

std::optional<sweep::SweepRun> run_sweep_ranks(const MpiSession&, const sweep::SweepFile&,
                                               const sweep::RunOptions&) {
  throw InputError("mpirun: this build has no MPI (install libopenmpi-dev and rebuild)");
}

#endif

}  // namespace newtop::app
