#pragma once
// Scale-out of the fitness evaluations over MPI ranks (Open MPI from Debian):
// `mpirun -np N facadeslam optimise ...` runs the same command on N ranks;
// rank 0 runs the genetic algorithm and hands out genomes one at a time to
// ranks 1..N-1 as they become free, which evaluate them (the same split,
// seed and evaluator as a threaded run, so the same results) and send the
// evaluation back. Only rank 0 reads or writes the run folder.
//
// Built only when CMake finds MPI (FACADESLAM_HAVE_MPI); without it
// `optimise` runs threaded only.
#include <functional>
#include <string>

#include "semantics/optimiser/fitness.hpp"
#include "semantics/optimiser/optimisation_run.hpp"

namespace facadeslam::semantics {

// True when this process was started by an MPI launcher (mpirun, srun):
// only then is MPI initialised, so a plain `facadeslam optimise` never
// touches the MPI runtime.
bool launched_by_mpi();

// MPI_Init ... MPI_Finalize for one command.
class MpiSession {
 public:
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }
  // Ends every rank at once with `code` (a rank failed: the others would
  // wait for it forever).
  [[noreturn]] static void abort(int code);

 private:
  int rank_ = 0, size_ = 1;
};

// Rank 0: evaluates a batch on ranks 1..size-1.
EvaluateBatch mpi_evaluate_batch(int size);
// Rank 0: tells every worker rank to stop serving.
void stop_mpi_workers(int size);
// Ranks > 0: evaluate what rank 0 sends until it says stop.
void serve_mpi_evaluations(const FitnessEvaluator& evaluator);

}  // namespace facadeslam::semantics
