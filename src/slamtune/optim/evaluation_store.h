// The run database of `slamtune optimize`: one SQLite file per run folder holding the run's
// settings, every finished evaluation (written and committed the moment it finishes, so an
// interruption loses nothing) and the population of every finished generation.
//
// Resuming replays the seeded search with every finished evaluation served from here; the
// stored generations let the replay check that it retraces the interrupted run exactly.
#pragma once

#include <cstdint>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "slamtune/optim/evaluation_record.h"

struct sqlite3;

namespace slamtune::optim {

// Reads every page of the existing database at `path` (PRAGMA quick_check) without changing
// it. Throws InputError "PATH: the run database is damaged (WHAT); ..." when a page is
// corrupt or the file is not a database, so that --resume refuses before any work.
void CheckRunDatabase(const std::string& path);

class EvaluationStore {
 public:
  // Opens (creating if needed) the database at `path`. Throws InputError when the file
  // cannot be opened or is not a slamtune run database.
  explicit EvaluationStore(const std::string& path);
  ~EvaluationStore();
  EvaluationStore(const EvaluationStore&) = delete;
  EvaluationStore& operator=(const EvaluationStore&) = delete;

  const std::string& path() const { return path_; }

  // The start of a run, in one transaction: its settings (compared on --resume) and its
  // command line (meta "invocation"). A kill leaves both or neither.
  void StartRun(const nlohmann::json& settings, const nlohmann::json& invocation);
  // Run settings (JSON), written once at the start of a run and compared on --resume.
  void SetSettings(const nlohmann::json& settings);
  std::optional<nlohmann::json> Settings() const;
  // Free-form run metadata by key (e.g. the command line that started the run).
  void SetMeta(const std::string& key, const nlohmann::json& value);
  std::optional<nlohmann::json> Meta(const std::string& key) const;

  // Finished evaluations, keyed by SearchSpace::Key. Put commits at once; thread-safe. All()
  // lists them by their place: Put(record) gives the next one; a batch run in parallel reserves
  // a place per run first (ReserveOrder returns the first of `count`) and puts each record at
  // its own, so the list keeps the batch's order whichever run finishes first.
  std::int64_t ReserveOrder(std::size_t count);
  void Put(const EvaluationRecord& record, std::int64_t place);
  void Put(const EvaluationRecord& record);
  std::optional<EvaluationRecord> Get(const std::string& key) const;
  std::vector<EvaluationRecord> All() const;
  std::size_t Count() const;

  // Population of a finished generation (JSON with decision and objective vectors).
  void PutGeneration(int generation, const nlohmann::json& population);
  std::optional<nlohmann::json> Generation(int generation) const;
  int LastGeneration() const;  // -1 when none

 private:
  void Exec(const std::string& sql) const;

  std::string path_;
  sqlite3* db_ = nullptr;
  struct Lock;
  std::unique_ptr<Lock> lock_;
};

}  // namespace slamtune::optim
