#include "slamtune/optim/evaluation/mpi_evaluation.h"

#include <fmt/format.h>

#include <chrono>
#include <cstdlib>
#include <thread>

#include "slamtune/common/error.h"
#include "slamtune/optim/search_space.h"

#ifdef SLAMTUNE_HAVE_MPI
#include <mpi.h>
#endif

namespace slamtune::optim {
namespace {

// The world size mpirun announces, 0 when there is none.
int AnnouncedWorldSize() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_SIZE", "PMI_SIZE"}) {
    if (const char* v = std::getenv(name)) return std::atoi(v);
  }
  return 0;
}

}  // namespace

bool MpiWorld::LaunchedByMpirun() { return AnnouncedWorldSize() > 0 || std::getenv("PMIX_RANK") != nullptr; }

#ifdef SLAMTUNE_HAVE_MPI

namespace {

// Message tags of the protocol between rank 0 and the workers.
enum Tag : int { kSetup = 1, kReady = 2, kTask = 3, kResult = 4, kStop = 5 };

void Check(int rc, const char* what) {
  if (rc != MPI_SUCCESS) throw std::runtime_error(fmt::format("MPI: {} failed (code {})", what, rc));
}

void SendJson(const nlohmann::json& j, int dest, int tag) {
  const std::string text = j.dump();
  Check(MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, dest, tag, MPI_COMM_WORLD), "MPI_Send");
}

// Waits (polling, so an idle rank does not spin a core) for a message from `source` (or any
// source) with `tag` (or any tag), receives it and returns its text; status says who and what.
std::string ReceiveText(int source, int tag, MPI_Status* status) {
  int flag = 0;
  for (;;) {
    Check(MPI_Iprobe(source, tag, MPI_COMM_WORLD, &flag, status), "MPI_Iprobe");
    if (flag) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  int count = 0;
  Check(MPI_Get_count(status, MPI_CHAR, &count), "MPI_Get_count");
  std::string text(static_cast<std::size_t>(count), '\0');
  Check(MPI_Recv(text.data(), count, MPI_CHAR, status->MPI_SOURCE, status->MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE),
        "MPI_Recv");
  return text;
}

}  // namespace

bool MpiWorld::Built() { return true; }

MpiWorld::MpiWorld() {
  if (!LaunchedByMpirun()) return;
  int initialized = 0;
  MPI_Initialized(&initialized);
  SLAMTUNE_CHECK(!initialized);  // one MpiWorld per process
  int provided = 0;
  Check(MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
  joined_ = true;
  if (provided < MPI_THREAD_FUNNELED) {
    throw std::runtime_error("MPI: the library does not provide MPI_THREAD_FUNNELED");
  }
  Check(MPI_Comm_rank(MPI_COMM_WORLD, &rank_), "MPI_Comm_rank");
  Check(MPI_Comm_size(MPI_COMM_WORLD, &size_), "MPI_Comm_size");
}

MpiWorld::~MpiWorld() {
  if (joined_) MPI_Finalize();
}

MpiDispatcher::MpiDispatcher(const MpiWorld& world) : workers_(world.size() - 1) { SLAMTUNE_CHECK(world.rank() == 0); }

MpiDispatcher::~MpiDispatcher() {
  try {
    Stop();
  } catch (...) {
    // Nothing better to do while unwinding: mpirun ends the job when rank 0 exits.
  }
}

void MpiDispatcher::Setup(const nlohmann::json& setup) {
  SLAMTUNE_CHECK(!ready_ && !stopped_);
  for (int w = 1; w <= workers_; ++w) SendJson(setup, w, kSetup);
  std::string first_error;
  for (int k = 0; k < workers_; ++k) {
    MPI_Status status;
    const auto reply = nlohmann::json::parse(ReceiveText(MPI_ANY_SOURCE, kReady, &status));
    if (!reply.at("ok").get<bool>() && first_error.empty()) {
      first_error = fmt::format("MPI rank {}: {}", status.MPI_SOURCE, reply.at("error").get<std::string>());
    }
  }
  if (!first_error.empty()) throw InputError(first_error);
  ready_ = true;
}

void MpiDispatcher::Stop() {
  if (stopped_) return;
  stopped_ = true;
  ready_ = false;
  for (int w = 1; w <= workers_; ++w) {
    Check(MPI_Send(nullptr, 0, MPI_CHAR, w, kStop, MPI_COMM_WORLD), "MPI_Send");
  }
}

void MpiDispatcher::Drain(const std::function<std::optional<Task>()>& next,
                          const std::function<void(std::size_t, EvaluationRecord)>& done) {
  SLAMTUNE_CHECK(ready_);
  int busy = 0;
  bool exhausted = false;
  // Every worker gets a task, then each returned record frees its worker for the next one.
  for (int w = 1; w <= workers_ && !exhausted; ++w) {
    if (auto task = next()) {
      SendJson({{"id", task->first}, {"params", task->second}}, w, kTask);
      ++busy;
    } else {
      exhausted = true;
    }
  }
  while (busy > 0) {
    MPI_Status status;
    const auto reply = nlohmann::json::parse(ReceiveText(MPI_ANY_SOURCE, kResult, &status));
    --busy;
    done(reply.at("id").get<std::size_t>(), reply.at("record").get<EvaluationRecord>());
    if (exhausted) continue;
    if (auto task = next()) {
      SendJson({{"id", task->first}, {"params", task->second}}, status.MPI_SOURCE, kTask);
      ++busy;
    } else {
      exhausted = true;
    }
  }
}

std::size_t ServeEvaluations(const MpiWorld& world, const MakeEvaluatorFn& make_evaluator) {
  SLAMTUNE_CHECK(world.rank() > 0);
  MPI_Status status;
  std::string text = ReceiveText(0, MPI_ANY_TAG, &status);
  if (status.MPI_TAG == kStop) return 0;  // rank 0 failed before any work
  SLAMTUNE_CHECK(status.MPI_TAG == kSetup);
  EvaluateFn evaluate;
  try {
    evaluate = make_evaluator(nlohmann::json::parse(text));
    SendJson({{"ok", true}}, 0, kReady);
  } catch (const std::exception& e) {
    SendJson({{"ok", false}, {"error", e.what()}}, 0, kReady);
    while (status.MPI_TAG != kStop) ReceiveText(0, MPI_ANY_TAG, &status);
    return 0;
  }
  std::size_t served = 0;
  for (;;) {
    text = ReceiveText(0, MPI_ANY_TAG, &status);
    if (status.MPI_TAG == kStop) return served;
    SLAMTUNE_CHECK(status.MPI_TAG == kTask);
    const auto task = nlohmann::json::parse(text);
    const auto params = task.at("params").get<Assignment>();
    const EvaluationRecord record = RunGuarded(evaluate, params, SearchSpace::Key(params));
    SendJson({{"id", task.at("id")}, {"record", record}}, 0, kResult);
    ++served;
  }
}

#else  // no MPI in this build

bool MpiWorld::Built() { return false; }

MpiWorld::MpiWorld() {
  if (AnnouncedWorldSize() > 1) {
    throw InputError(
        "started by mpirun, but this slamtune was built without MPI (install libopenmpi-dev and rebuild "
        "with -DSLAMTUNE_WITH_MPI=ON)");
  }
}

MpiWorld::~MpiWorld() = default;

MpiDispatcher::MpiDispatcher(const MpiWorld&) { SLAMTUNE_CHECK(false); }
MpiDispatcher::~MpiDispatcher() = default;
void MpiDispatcher::Setup(const nlohmann::json&) { SLAMTUNE_CHECK(false); }
void MpiDispatcher::Stop() {}
void MpiDispatcher::Drain(const std::function<std::optional<Task>()>&,
                          const std::function<void(std::size_t, EvaluationRecord)>&) {
  SLAMTUNE_CHECK(false);
}

std::size_t ServeEvaluations(const MpiWorld&, const MakeEvaluatorFn&) {
  SLAMTUNE_CHECK(false);
  return 0;
}

#endif

}  // namespace slamtune::optim
