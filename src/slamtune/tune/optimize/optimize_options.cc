#include "slamtune/tune/optimize/optimize_options.h"

#include <fmt/format.h>

#include "slamtune/common/error.h"
#include "slamtune/io/content_hash.h"
#include "slamtune/optim/objective_set.h"
#include "slamtune/optim/optimizer.h"

namespace slamtune::tune {

namespace {

constexpr NamedSpace kNamedSpaces[] = {NamedSpace::kLoop, NamedSpace::kPaper, NamedSpace::kFrontEnd};

// Schema 1 -> 2: what folders written before the record had a number ran with.
void MigrateFromSchema1(nlohmann::json& j) {
  nlohmann::json& inputs = j.at("inputs");
  // --params was applied over --preset's values before the base rule existed.
  if (!inputs.contains("base_rule")) inputs["base_rule"] = "preset_then_file";
  if (!j.contains("vary")) j["vary"] = nlohmann::json::array();
  if (!j.contains("fix")) j["fix"] = nlohmann::json::array();
  // Before named spaces, no --space and no --vary meant r and g around the base without steps.
  j["around_base_without_steps"] = j.at("space").get<std::string>().empty() && j.at("vary").empty();
  if (!j.contains("space_probed")) j["space_probed"] = false;
  if (!j.contains("front_end_repair")) {
    j["front_end_repair"] = {{"lower_bounds", nlohmann::json::object()}, {"initial", nlohmann::json::array()}};
  }
  // Before objective sets, the paper's; before early stopping, the whole budget.
  if (!j.contains("objectives")) j["objectives"] = optim::ObjectiveSet::NameOf(optim::ObjectiveSetKind::kPaper);
  if (!j.contains("settling")) {
    optim::SettlingOptions whole_budget;
    whole_budget.enabled = false;
    j["settling"] = whole_budget.ToJson();
  }
}

}  // namespace

const char* NameOf(NamedSpace space) {
  switch (space) {
    case NamedSpace::kLoop: return "loop";
    case NamedSpace::kPaper: return "paper";
    case NamedSpace::kFrontEnd: return "front-end";
  }
  SLAMTUNE_CHECK(false);
  return "";
}

std::optional<NamedSpace> ParseNamedSpace(const std::string& text) {
  for (NamedSpace space : kNamedSpaces) {
    if (text == NameOf(space)) return space;
  }
  return std::nullopt;
}

nlohmann::json OptimizeOptions::ToJson() const {
  const optim::OptimizeSettings defaults;
  optim::SettlingOptions stop = settling;
  stop.sound_answer_window = budget.sound_answer_window.value_or(settling.sound_answer_window);
  return {{"schema", kInvocationSchema},
          {"inputs", inputs.ToJson()},
          {"space", space},
          {"vary", vary},
          {"fix", fix},
          {"around_base_without_steps", around_base_without_steps},
          {"population", budget.population.value_or(defaults.population)},
          {"generations", budget.generations.value_or(defaults.generations)},
          {"divisions", budget.divisions.value_or(defaults.divisions)},
          {"seed", seed},
          {"objectives", objectives},
          {"front_end_repair", {{"lower_bounds", space_lower}, {"initial", initial}}},
          {"space_probed", space_probed},
          {"settling", stop.ToJson()}};
}

OptimizeOptions OptimizeOptions::FromJson(const nlohmann::json& j) {
  OptimizeOptions o;
  o.inputs = TuningInputOptions::FromJson(j.at("inputs"));
  o.space = j.at("space");
  o.vary = j.at("vary").get<std::vector<std::string>>();
  o.fix = j.at("fix").get<std::vector<std::string>>();
  o.around_base_without_steps = j.at("around_base_without_steps");
  o.budget.population = j.at("population").get<std::size_t>();
  o.budget.generations = j.at("generations").get<unsigned>();
  o.budget.divisions = j.at("divisions").get<std::size_t>();
  o.seed = j.at("seed");
  o.objectives = j.at("objectives");
  o.space_lower = j.at("front_end_repair").at("lower_bounds").get<std::map<std::string, double>>();
  o.initial = j.at("front_end_repair").at("initial").get<std::vector<optim::Assignment>>();
  o.space_probed = j.at("space_probed");
  o.settling = optim::SettlingOptions::FromJson(j.at("settling"));
  o.budget.sound_answer_window = o.settling.sound_answer_window;
  return o;
}

nlohmann::json MigrateInvocation(nlohmann::json j, const std::string& source) {
  const int schema = j.value("schema", 1);
  if (schema > kInvocationSchema) {
    throw InputError(
        source, 0,
        fmt::format("the run folder was written by a newer slamtune (invocation schema {}; this one reads up to {})",
                    schema, kInvocationSchema));
  }
  if (schema < 2) MigrateFromSchema1(j);
  j["schema"] = kInvocationSchema;
  return j;
}

std::map<std::string, std::string> InputFiles(const TuningInputOptions& in) {
  return {{"log", in.log}, {"params", in.params_file}, {"relations", in.relations}};
}

nlohmann::json InvocationRecord(const OptimizeOptions& options) {
  nlohmann::json j = options.ToJson();
  j["input_hashes"] = io::ContentHashes(InputFiles(options.inputs));
  return j;
}

void RequireRecordedContent(const nlohmann::json& invocation, const TuningInputOptions& inputs) {
  if (!invocation.contains("input_hashes")) return;
  std::map<std::string, std::string> same_path;
  for (const auto& [key, path] : InputFiles(inputs)) {
    if (invocation.at("inputs").value(key, std::string()) == path) same_path[key] = path;
  }
  io::RequireSameContent(invocation.at("input_hashes").get<std::map<std::string, std::string>>(), same_path);
}

}  // namespace slamtune::tune
