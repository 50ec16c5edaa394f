// The options of a command that do not change what it computes: how many runs at once,
// progress output, the output folder itself. `optimize --resume DIR` on its own takes every
// setting that changes results from the run database, so these are the only options that may
// accompany it. An option is marked where it is registered; one never marked counts as
// changing results, so a new option cannot slip past --resume unnoticed.
#pragma once

#include <CLI/CLI.hpp>
#include <vector>

namespace slamtune::cli {

class ResultNeutralOptions {
 public:
  // Marks `option` (or each of `options`) and returns it, for chaining with CLI11's setters.
  CLI::Option* Add(CLI::Option* option);
  void Add(const std::vector<CLI::Option*>& options);

  // Whether every option given on `app`'s command line is marked.
  bool OnlyTheseGiven(const CLI::App& app) const;

 private:
  std::vector<const CLI::Option*> options_;
};

}  // namespace slamtune::cli
