// NSGA-III as a pagmo user-defined algorithm.
//
// Deb, K. and Jain, H., "An Evolutionary Many-Objective Optimization Algorithm Using
// Reference-Point-Based Nondominated Sorting Approach, Part I: Solving Problems With Box
// Constraints", IEEE Trans. Evolutionary Computation 18(4):577-601, 2014.
//
// Each generation (Algorithm 1): N offspring from random mating, SBX and polynomial
// mutation (variation.h), evaluated without duplicate work (nsga3_evaluation.h); then
// survival of N out of the 2N by non-dominated sorting and reference-point niching on the
// adaptively normalised objectives (nsga3_survival.h). Against NSGA-II (pagmo::nsga2) the
// crowding distance is replaced by niching around well-spread reference directions, which
// keeps the spread on three or more objectives and makes the search invariant to the scale
// of each objective; the price is choosing the reference points (reference_points.h).
//
// Usage, composing with pagmo:
//   nsga3::Nsga3 nsga3(options, /*seed=*/42);
//   pagmo::population pop(problem, nsga3.RequiredPopulationSize(problem.get_nobj()), 7);
//   pop = nsga3.evolve(pop);            // or pagmo::algorithm(nsga3).evolve(pop)
//   nsga3.summary().BriefReport();      // via algorithm.extract<Nsga3>() when wrapped
//
// Supported problems: box-constrained (no equality/inequality constraints), deterministic,
// two or more objectives, finite bounds; pagmo's nix integer genes (the LAST nix genes) are
// kept integral. Randomness comes only from the seed, so a seed fixes the run; a batch
// fitness evaluator (set_bfe) changes how offspring are evaluated, never the result.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <pagmo/bfe.hpp>
#include <pagmo/population.hpp>
#include <pagmo/rng.hpp>
#include <random>
#include <string>
#include <vector>

#include "slamtune/nsga3/normalization.h"
#include "slamtune/nsga3/nsga3_options.h"

namespace slamtune::nsga3 {

// One generation of a run.
struct GenerationRecord {
  unsigned generation = 0;                // 1-based, counted within one evolve() call
  unsigned long long evaluations = 0;     // the problem's fitness evaluations so far (get_fevals)
  std::size_t new_evaluations = 0;        // genotypes evaluated in this generation
  std::size_t duplicates_skipped = 0;     // offspring whose fitness was copied, not evaluated
  std::size_t fronts_used = 0;            // fronts that entered S_t
  std::size_t niched = 0;                 // survivors chosen by niching from the last front
  std::vector<NadirSource> nadir_source;  // per objective; empty when S_t fit exactly
  std::vector<double> ideal;              // ideal point over all generations so far (§IV-C)
  // Population after survival. Always set in the record handed to the callback; kept in
  // history() only when Nsga3Options::record_history is true.
  std::vector<std::vector<double>> x;
  std::vector<std::vector<double>> f;
};

enum class CallbackAction { kContinue, kStop };

// Called after every generation with the record and the run's resumable state (RngState()
// text). Saving the population (record.x, record.f) and the state lets a later run resume
// bit for bit: build a population from them, RestoreRngState, evolve the remaining
// generations. Returning kStop ends evolve() after this generation.
using GenerationCallback = std::function<CallbackAction(const GenerationRecord& record, const std::string& state)>;

enum class StopReason { kNotRun, kGenerationLimit, kCallbackStop };

// What the last evolve() did.
struct Nsga3Summary {
  StopReason stop_reason = StopReason::kNotRun;
  unsigned generations_run = 0;
  unsigned long long evaluations = 0;         // fitness evaluations made by this evolve()
  unsigned long long duplicates_skipped = 0;  // offspring not evaluated because already known
  unsigned hyperplane_rejections = 0;         // normalisations that fell back (normalization.h)

  std::string BriefReport() const;
};

class Nsga3 {
 public:
  // Default options, seed from pagmo's global random device (pagmo requires a default ctor).
  Nsga3();
  // Throws InputError if `options` are invalid.
  explicit Nsga3(Nsga3Options options, unsigned seed = pagmo::random_device::next());

  // Runs options().generations generations on `pop`. Throws InputError before changing
  // anything when the problem is unsupported (see the file comment), the population size
  // is not RequiredPopulationSize(M), a member has non-finite objectives or a non-integral
  // integer gene, or the reference points do not fit M.
  pagmo::population evolve(pagmo::population pop) const;

  // pagmo UDA interface. set_seed starts a new run: it reseeds the generator and forgets the
  // ideal point carried from earlier evolve() calls.
  void set_seed(unsigned seed);
  unsigned get_seed() const { return seed_; }
  void set_bfe(const pagmo::bfe& bfe) { bfe_ = bfe; }
  void unset_bfe() { bfe_.reset(); }
  std::string get_name() const { return "NSGA-III: reference-point based non-dominated sorting (Deb & Jain 2014)"; }
  std::string get_extra_info() const;

  void set_generation_callback(GenerationCallback callback) { callback_ = std::move(callback); }
  const Nsga3Options& options() const { return options_; }
  std::size_t RequiredPopulationSize(std::size_t objectives) const {
    return options_.RequiredPopulationSize(objectives);
  }
  // Records of the last evolve(), one per generation.
  const std::vector<GenerationRecord>& history() const { return history_; }
  const Nsga3Summary& summary() const { return summary_; }

  // The run state that is not in the population, as text: the random generator and the
  // ideal point over all generations so far (which the paper's normalisation keeps, §IV-C,
  // and which a population cannot recover once its extreme members are gone). Restoring it
  // (InputError if malformed) and evolving a saved population continues a run exactly.
  std::string RngState() const;
  void RestoreRngState(const std::string& state);

 private:
  Nsga3Options options_;
  unsigned seed_;
  std::optional<pagmo::bfe> bfe_;
  GenerationCallback callback_;
  // evolve() is const for pagmo; the generator advances across calls as in pagmo's algorithms.
  mutable std::mt19937 rng_;
  // Ideal point over every population seen since the last set_seed (empty before the first
  // evolve); carried across evolve() calls like the generator, for pagmo islands.
  mutable std::vector<double> ideal_;
  mutable std::vector<GenerationRecord> history_;
  mutable Nsga3Summary summary_;
};

const char* ToString(StopReason reason);

}  // namespace slamtune::nsga3
