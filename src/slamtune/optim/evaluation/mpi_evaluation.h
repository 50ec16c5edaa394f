// Distributed evaluation over Open MPI (`mpirun -np K slamtune optimize ...`).
//
// Rank 0 runs the optimiser and alone writes the run database and the report. Ranks 1..K-1
// only evaluate: rank 0 sends each of them the inputs once (Setup: the log path, relations,
// base parameters, as JSON; every host must read the same files at the same paths), then
// its BatchEvaluator hands each missing parameter set to a free worker rank (MpiDispatcher,
// a RemoteEvaluators) while its own --jobs threads take sets from the same queue. A worker
// evaluates one set at a time and sends the record back as JSON (doubles round-trip exactly).
// An evaluation is a deterministic function of its parameter set, so which rank ran it
// changes nothing: the result is the one a single process with the same seed gives.
//
// Waiting is by polling (MPI_Iprobe and a 1 ms sleep), not Open MPI's spinning blocking
// calls, so an idle rank leaves its core to the ranks that work.
//
// Without MPI in the build, or in a process not started by mpirun, MpiWorld is a world of one
// rank and nothing here calls MPI.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "slamtune/optim/evaluation/batch_evaluator.h"

namespace slamtune::optim {

class MpiWorld {
 public:
  // Joins the MPI job (MPI_Init_thread, funneled: only this thread calls MPI) when the process
  // was started by mpirun; otherwise a world of one rank.
  MpiWorld();
  ~MpiWorld();  // MPI_Finalize when joined
  MpiWorld(const MpiWorld&) = delete;
  MpiWorld& operator=(const MpiWorld&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool distributed() const { return size_ > 1; }
  // Whether this build has MPI support (CMake option SLAMTUNE_WITH_MPI and Open MPI found).
  static bool Built();
  // Whether the environment says this process was started by mpirun (Open MPI or PMIx).
  static bool LaunchedByMpirun();

 private:
  bool joined_ = false;
  int rank_ = 0;
  int size_ = 1;
};

// Rank 0's side: the worker ranks as remote evaluation slots, one set at a time each.
class MpiDispatcher final : public RemoteEvaluators {
 public:
  explicit MpiDispatcher(const MpiWorld& world);
  ~MpiDispatcher() override;  // stops the workers if Stop() was not called
  MpiDispatcher(const MpiDispatcher&) = delete;
  MpiDispatcher& operator=(const MpiDispatcher&) = delete;

  // Sends `setup` to every worker and waits until each has built its evaluator; throws
  // InputError naming the rank and its error when one could not (e.g. the log is missing on
  // its host). Call once, before the first Evaluate.
  void Setup(const nlohmann::json& setup);
  // Tells every worker to exit. Idempotent.
  void Stop();

  int slots() const override { return ready_ ? workers_ : 0; }
  void Drain(const std::function<std::optional<Task>()>& next,
             const std::function<void(std::size_t, EvaluationRecord)>& done) override;

 private:
  int workers_ = 0;
  bool ready_ = false;
  bool stopped_ = false;
};

// Builds a worker's evaluation function from rank 0's setup JSON; may throw InputError.
using MakeEvaluatorFn = std::function<EvaluateFn(const nlohmann::json& setup)>;

// A worker rank's whole life: waits for the setup (or a stop), builds its evaluator, then
// evaluates what rank 0 sends until rank 0 says stop. Returns the number of sets evaluated.
// A setup that fails is reported to rank 0, which stops the job with that message.
std::size_t ServeEvaluations(const MpiWorld& world, const MakeEvaluatorFn& make_evaluator);

}  // namespace slamtune::optim
