#include "slamtune/optim/evaluation_store.h"

#include <fmt/format.h>
#include <sqlite3.h>

#include <algorithm>
#include <cstdint>
#include <mutex>

#include "slamtune/common/error.h"

namespace slamtune::optim {

struct EvaluationStore::Lock {
  mutable std::mutex mutex;
  std::int64_t reserved_end = 0;  // one past the last place ReserveOrder gave out
};

namespace {

constexpr const char* kFormat = "slamtune-optimize-1";

// A prepared statement that finalises itself.
class Statement {
 public:
  Statement(sqlite3* db, const char* sql) : db_(db) {
    if (sqlite3_prepare_v2(db, sql, -1, &stmt_, nullptr) != SQLITE_OK) {
      SLAMTUNE_CHECK_MSG(false, sqlite3_errmsg(db));
    }
  }
  ~Statement() { sqlite3_finalize(stmt_); }
  void Bind(int i, const std::string& text) { sqlite3_bind_text(stmt_, i, text.c_str(), -1, SQLITE_TRANSIENT); }
  void Bind(int i, int value) { sqlite3_bind_int(stmt_, i, value); }
  void Bind(int i, std::int64_t value) { sqlite3_bind_int64(stmt_, i, value); }
  bool Step() {
    const int rc = sqlite3_step(stmt_);
    if (rc == SQLITE_ROW) return true;
    if (rc != SQLITE_DONE) throw InputError(fmt::format("database error: {}", sqlite3_errmsg(db_)));
    return false;
  }
  std::string Text(int col) const {
    const unsigned char* t = sqlite3_column_text(stmt_, col);
    return t ? reinterpret_cast<const char*>(t) : "";
  }
  int Int(int col) const { return sqlite3_column_int(stmt_, col); }
  std::int64_t Int64(int col) const { return sqlite3_column_int64(stmt_, col); }

 private:
  sqlite3* db_;
  sqlite3_stmt* stmt_ = nullptr;
};

// The first problem PRAGMA quick_check reports, or "" when the database is intact.
std::string QuickCheck(sqlite3* db) {
  sqlite3_stmt* stmt = nullptr;
  if (sqlite3_prepare_v2(db, "PRAGMA quick_check(1)", -1, &stmt, nullptr) != SQLITE_OK) {
    sqlite3_finalize(stmt);
    return sqlite3_errmsg(db);
  }
  std::string problem;
  const int rc = sqlite3_step(stmt);
  if (rc == SQLITE_ROW) {
    const unsigned char* text = sqlite3_column_text(stmt, 0);
    problem = text ? reinterpret_cast<const char*>(text) : "";
    if (problem == "ok") problem.clear();
  } else if (rc != SQLITE_DONE) {
    problem = sqlite3_errmsg(db);
  }
  sqlite3_finalize(stmt);
  return problem;
}

}  // namespace

void CheckRunDatabase(const std::string& path) {
  sqlite3* db = nullptr;
  std::string problem;
  if (sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READWRITE, nullptr) != SQLITE_OK) {
    problem = db ? sqlite3_errmsg(db) : "out of memory";
  } else {
    sqlite3_busy_timeout(db, 10000);
    problem = QuickCheck(db);
  }
  sqlite3_close(db);
  if (problem.empty()) return;
  for (char& c : problem) {
    if (c == '\n') c = ' ';
  }
  throw InputError(path, 0,
                   "the run database is damaged (" + problem +
                       "); it cannot be resumed: start again with a new --out (the report files beside it stay "
                       "readable)");
}

EvaluationStore::EvaluationStore(const std::string& path) : path_(path), lock_(std::make_unique<Lock>()) {
  if (sqlite3_open_v2(path.c_str(), &db_, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_FULLMUTEX,
                      nullptr) != SQLITE_OK) {
    const std::string why = db_ ? sqlite3_errmsg(db_) : "out of memory";
    sqlite3_close(db_);
    db_ = nullptr;
    throw InputError(path, 0, "cannot open run database: " + why);
  }
  sqlite3_busy_timeout(db_, 10000);
  try {
    // WAL keeps every committed evaluation safe across a kill while staying fast.
    Exec("PRAGMA journal_mode=WAL; PRAGMA synchronous=NORMAL;");
    // The tables and the format mark in one transaction: a new database is whole or empty.
    Exec(
        fmt::format("BEGIN IMMEDIATE;"
                    "CREATE TABLE IF NOT EXISTS meta (key TEXT PRIMARY KEY, value TEXT NOT NULL);"
                    "CREATE TABLE IF NOT EXISTS evaluations (key TEXT PRIMARY KEY, status TEXT NOT NULL,"
                    " record TEXT NOT NULL, seq INTEGER NOT NULL);"
                    "CREATE TABLE IF NOT EXISTS generations (gen INTEGER PRIMARY KEY, population TEXT NOT NULL);"
                    "INSERT OR IGNORE INTO meta(key, value) VALUES('format', '{}');"
                    "COMMIT;",
                    kFormat));
  } catch (const InputError&) {
    sqlite3_close(db_);
    db_ = nullptr;
    throw InputError(path, 0, "not a slamtune run database (or corrupt)");
  }
  std::string format;
  {
    Statement get(db_, "SELECT value FROM meta WHERE key = 'format'");
    if (get.Step()) format = get.Text(0);
  }
  if (format != kFormat) {
    sqlite3_close(db_);
    db_ = nullptr;
    throw InputError(path, 0, fmt::format("database format '{}' is not '{}'", format, kFormat));
  }
}

EvaluationStore::~EvaluationStore() {
  if (db_) sqlite3_close(db_);
}

void EvaluationStore::Exec(const std::string& sql) const {
  char* err = nullptr;
  if (sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, &err) != SQLITE_OK) {
    const std::string why = err ? err : "unknown";
    sqlite3_free(err);
    throw InputError(path_, 0, "database error: " + why);
  }
}

void EvaluationStore::StartRun(const nlohmann::json& settings, const nlohmann::json& invocation) {
  std::lock_guard guard(lock_->mutex);
  Exec("BEGIN IMMEDIATE");
  try {
    for (const auto& [key, value] : {std::pair{"settings", &settings}, std::pair{"invocation", &invocation}}) {
      Statement put(db_, "INSERT OR REPLACE INTO meta(key, value) VALUES(?, ?)");
      put.Bind(1, std::string(key));
      put.Bind(2, value->dump());
      put.Step();
    }
    Exec("COMMIT");
  } catch (...) {
    sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
    throw;
  }
}

void EvaluationStore::SetSettings(const nlohmann::json& settings) { SetMeta("settings", settings); }

std::optional<nlohmann::json> EvaluationStore::Settings() const { return Meta("settings"); }

void EvaluationStore::SetMeta(const std::string& key, const nlohmann::json& value) {
  SLAMTUNE_CHECK(key != "format");
  std::lock_guard guard(lock_->mutex);
  Statement put(db_, "INSERT OR REPLACE INTO meta(key, value) VALUES(?, ?)");
  put.Bind(1, key);
  put.Bind(2, value.dump());
  put.Step();
}

std::optional<nlohmann::json> EvaluationStore::Meta(const std::string& key) const {
  std::lock_guard guard(lock_->mutex);
  Statement get(db_, "SELECT value FROM meta WHERE key = ?");
  get.Bind(1, key);
  if (!get.Step()) return std::nullopt;
  return nlohmann::json::parse(get.Text(0));
}

std::int64_t EvaluationStore::ReserveOrder(std::size_t count) {
  std::lock_guard guard(lock_->mutex);
  Statement next(db_, "SELECT COALESCE(MAX(seq), 0) + 1 FROM evaluations");
  next.Step();
  const std::int64_t first = std::max(next.Int64(0), lock_->reserved_end);
  lock_->reserved_end = first + static_cast<std::int64_t>(count);
  return first;
}

void EvaluationStore::Put(const EvaluationRecord& record, std::int64_t place) {
  std::lock_guard guard(lock_->mutex);
  Statement put(db_, "INSERT OR REPLACE INTO evaluations(key, status, record, seq) VALUES(?, ?, ?, ?)");
  put.Bind(1, record.key);
  put.Bind(2, std::string(NameOf(record.status)));
  put.Bind(3, nlohmann::json(record).dump());
  put.Bind(4, place);
  put.Step();
}

void EvaluationStore::Put(const EvaluationRecord& record) { Put(record, ReserveOrder(1)); }

std::optional<EvaluationRecord> EvaluationStore::Get(const std::string& key) const {
  std::lock_guard guard(lock_->mutex);
  Statement get(db_, "SELECT record FROM evaluations WHERE key = ?");
  get.Bind(1, key);
  if (!get.Step()) return std::nullopt;
  return nlohmann::json::parse(get.Text(0)).get<EvaluationRecord>();
}

std::vector<EvaluationRecord> EvaluationStore::All() const {
  std::lock_guard guard(lock_->mutex);
  Statement all(db_, "SELECT record FROM evaluations ORDER BY seq");
  std::vector<EvaluationRecord> out;
  while (all.Step()) out.push_back(nlohmann::json::parse(all.Text(0)).get<EvaluationRecord>());
  return out;
}

std::size_t EvaluationStore::Count() const {
  std::lock_guard guard(lock_->mutex);
  Statement count(db_, "SELECT COUNT(*) FROM evaluations");
  count.Step();
  return static_cast<std::size_t>(count.Int(0));
}

void EvaluationStore::PutGeneration(int generation, const nlohmann::json& population) {
  std::lock_guard guard(lock_->mutex);
  Statement put(db_, "INSERT OR REPLACE INTO generations(gen, population) VALUES(?, ?)");
  put.Bind(1, generation);
  put.Bind(2, population.dump());
  put.Step();
}

std::optional<nlohmann::json> EvaluationStore::Generation(int generation) const {
  std::lock_guard guard(lock_->mutex);
  Statement get(db_, "SELECT population FROM generations WHERE gen = ?");
  get.Bind(1, generation);
  if (!get.Step()) return std::nullopt;
  return nlohmann::json::parse(get.Text(0));
}

int EvaluationStore::LastGeneration() const {
  std::lock_guard guard(lock_->mutex);
  Statement get(db_, "SELECT COALESCE(MAX(gen), -1) FROM generations");
  get.Step();
  return get.Int(0);
}

}  // namespace slamtune::optim
