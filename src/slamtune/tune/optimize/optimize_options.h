// What `slamtune optimize` is asked to do: the options that change its results, with their
// defaults written once, and their record in the run folder (the "invocation" of the run
// database, optim/evaluation_store.h), from which `optimize --resume DIR` alone takes them.
//
// The record carries a schema number. MigrateInvocation is the one place that reads a record of
// an earlier schema: it fills in what such folders ran with (the paper's objectives, no early
// stop, r and g around the base without steps, ...), so FromJson reads only the current schema.
#pragma once

#include <cstddef>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "slamtune/optim/search_space.h"
#include "slamtune/optim/settling.h"
#include "slamtune/tune/tuning_inputs.h"

namespace slamtune::tune {

// The search spaces `--space` knows by name (optim/search_space.h): r and g around the base
// configuration; the seed paper's; the front end (sequential matching and node spacing plus r, g,
// p, q). Any other --space value is a YAML file.
enum class NamedSpace { kLoop, kPaper, kFrontEnd };
// "loop", "paper", "front-end".
const char* NameOf(NamedSpace space);
// The named space `text` names, or nullopt (a file).
std::optional<NamedSpace> ParseNamedSpace(const std::string& text);

// --objectives auto: the set is chosen from the search space (optim::DefaultObjectiveSetKind).
inline constexpr const char* kAutomaticObjectives = "auto";

// The schema of the invocation record this version writes. 1: folders written before the record
// had a number (read through MigrateInvocation); 2: the current one.
inline constexpr int kInvocationSchema = 2;

// The budget the user gave; nullopt leaves the value to the tuner: the built-in world's, a broken
// map's (optim::BrokenMapBudget) or optim::OptimizeSettings' defaults. A planned optimisation
// has every value set (PlanOptimization), and so has a resumed one.
struct OptimizeBudget {
  std::optional<std::size_t> population;   // individuals per generation, >= 4
  std::optional<unsigned> generations;     // the most generations run, >= 1
  std::optional<std::size_t> divisions;    // Das-Dennis divisions of the reference points, >= 1
  std::optional<int> sound_answer_window;  // optim::SettlingOptions::sound_answer_window, >= 0
};

struct OptimizeOptions {
  TuningInputOptions inputs;
  // --space: a NamedSpace's name or a search-space YAML file; "" = chosen by one run of the base
  // configuration (the loop space, or the front end when that run's front end breaks).
  std::string space;
  std::vector<std::string> vary;                  // --vary NAME=MIN:MAX[:STEP]: the space from the command line
  std::vector<std::string> fix;                   // --fix NAME=VALUE, with --vary
  std::string objectives = kAutomaticObjectives;  // an optim::ObjectiveSet name, or kAutomaticObjectives
  optim::SettlingOptions settling;                // early stop (its sound_answer_window: budget.sound_answer_window)
  OptimizeBudget budget;
  unsigned seed = 1;  // the same seed gives the same result

  // Decided by the tuner and recorded, so that a resumed run does what the uninterrupted one did.
  bool space_probed = false;  // the space was chosen by a run of the base configuration
  // A folder written before named spaces (no space, no --vary): r and g around the base
  // configuration without steps (SearchSpace::AroundBase).
  bool around_base_without_steps = false;
  // The front end's informed start (optim/front_end_repair.h): the space's raised lower bounds
  // and the repaired configuration as the first individual.
  std::map<std::string, double> space_lower;
  std::vector<optim::Assignment> initial;

  // The invocation record (schema kInvocationSchema), without the inputs' content hashes
  // (InputContentHashes). Budget values left to the tuner are written as OptimizeSettings'
  // defaults; a planned optimisation has none left.
  nlohmann::json ToJson() const;
  // Reads a record of the current schema (MigrateInvocation first for a stored one).
  static OptimizeOptions FromJson(const nlohmann::json& invocation);
};

// A stored invocation record of any schema up to kInvocationSchema, as the current schema.
// InputError naming `source` (the run database) for a record of a newer schema (a newer slamtune
// wrote the folder).
nlohmann::json MigrateInvocation(nlohmann::json invocation, const std::string& source);

// The files whose content the run depends on, by their key in TuningInputOptions::ToJson:
// "log", "params" and "relations" (empty paths included; io::ContentHashes skips them).
std::map<std::string, std::string> InputFiles(const TuningInputOptions& inputs);

// The invocation as the run folder keeps it: ToJson and the content hashes of the input files,
// so that a resumed run notices a file changed under the same name (RequireRecordedContent).
nlohmann::json InvocationRecord(const OptimizeOptions& options);

// The inputs named now that are the recorded files must still have their recorded content;
// InputError naming the file otherwise. Records written before content hashes were kept are not
// checked.
void RequireRecordedContent(const nlohmann::json& invocation, const TuningInputOptions& inputs);

}  // namespace slamtune::tune
