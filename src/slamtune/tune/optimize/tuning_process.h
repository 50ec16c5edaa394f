// A tuning command's process and its part in an MPI job (optim/evaluation/mpi_evaluation.h): started by
// mpirun with several ranks, rank 0 drives the command and hands SLAM runs to the others (the
// workers), which wait for its WorkerSetup, build the same evaluation context and only evaluate;
// an error on rank 0 before StopWorkers stops them too. Alone, the process does everything and
// there are no workers.
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "slamtune/optim/evaluation/batch_evaluator.h"
#include "slamtune/optim/evaluation/mpi_evaluation.h"
#include "slamtune/optim/evaluation/slam_evaluation.h"
#include "slamtune/tune/tuning_inputs.h"

namespace slamtune::tune {

// What rank 0 sends the worker ranks (MpiDispatcher::Setup) so that they build the same context.
// `stop_broken_runs`: SlamEvaluationContext::stop_broken_runs.
nlohmann::json WorkerSetup(const TuningInputOptions& inputs, const std::map<std::string, double>& fixed,
                           const TuningRunOptions& run, optim::WallDrawing drawing, bool stop_broken_runs = false);

// The evaluation context a worker rank builds from rank 0's WorkerSetup (the inputs loaded
// without a word: rank 0 says what was read).
std::shared_ptr<optim::SlamEvaluationContext> WorkerContext(const nlohmann::json& setup);

// A worker rank under mpirun: builds its context (WorkerContext), evaluates what rank 0 sends
// until told to stop, and returns 0.
int ServeAsWorker(const optim::MpiWorld& world);

class TuningProcess {
 public:
  TuningProcess();
  TuningProcess(const TuningProcess&) = delete;
  TuningProcess& operator=(const TuningProcess&) = delete;

  // Whether this is a worker rank, which should only Serve.
  bool is_worker() const { return world_.rank() > 0; }
  // A worker rank's whole life (ServeAsWorker); returns its exit code.
  int Serve() const { return ServeAsWorker(world_); }
  bool has_workers() const { return workers_.has_value(); }
  int ranks() const { return world_.size(); }

  // One rank per core: with workers, rank 0 evaluates on one thread unless --jobs was given.
  void FitJobs(bool jobs_given, TuningRunOptions& run) const;
  // Sends the workers what they build their context from (WorkerSetup); nothing without workers.
  void SetupWorkers(const TuningInputOptions& inputs, const std::map<std::string, double>& fixed,
                    const TuningRunOptions& run, optim::WallDrawing drawing, bool stop_broken_runs = false);
  // Lets `evaluator` hand runs to the workers beside its own threads.
  void ShareWith(optim::BatchEvaluator& evaluator);
  // Tells the workers to exit; idempotent.
  void StopWorkers();

  // "K MPI ranks (J evaluating on rank 0)" with workers, else "J jobs".
  std::string Parallelism(int jobs) const;
  // "N of the SLAM runs ran on the K worker ranks", or "" without workers.
  std::string WorkersShare(const optim::BatchEvaluatorStats& evaluations) const;

 private:
  optim::MpiWorld world_;
  std::optional<optim::MpiDispatcher> workers_;
};

}  // namespace slamtune::tune
