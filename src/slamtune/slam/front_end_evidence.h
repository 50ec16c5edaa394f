// Where does a map break before any loop closes? — read from the run itself, without ground
// truth. Karto's front end places each new node by one sequential match (docs/engine.md
// §3.2 steps 6-7): a search over a square window of side correlation_search_space_dimension
// around the odometry's guess and over +-coarse_search_angle_offset of heading. When the
// odometry is off by more than the window (a wheel slip, a bump, a spin), the true pose lies
// outside the search and the match snaps to the best wrong pose it can see — at the edge of the
// window; when the scan sees too little to match (a featureless corridor, glass), its response
// collapses. Either way the node is misplaced, and no loop closure puts it back.
//
// This is analysis of a finished or running run, kept apart from Karto's semantics: it reads the
// ProcessResult of each sequential match and changes nothing. A step is suspect when its match
// ended at the window's edge (translation or heading) or its response fell below a fraction of
// the run's median response; suspects close together form a stretch, reported with log scan
// indices and times so a user can find the spot in the recording. Working runs of real logs
// have a few such stretches too (a bump the matcher absorbed at the window's edge, one poor
// scan that the next match puts right). A break is one match that did all three: ran out of
// search room (edge), found a pose that fits very badly (response below a quarter of the
// run's median), and was not undone by the matches after it (their corrections do not take
// back at least half of its own: of the heading when it hit the heading range's edge — a
// heading error dominates, and the position corrections after it follow from it — else of the
// position) — the node stays where the failed search left it, and the map breaks there. A
// stretch holding a break is strong evidence.
//
// A front end can also fail without any such event: where the scans see structure in one
// direction only (a long corridor with bare walls), the match cannot tell motion along it: the
// poses along the corridor fit equally well, the distance penalty favours the search's centre
// (§4.5), so the node keeps the odometry's guess and the odometry's error along the corridor goes
// into the map unchecked. Karto's own covariance says so: its positional ellipse is long along
// the corridor and thin across (§4.6). A degenerate match is
// one whose principal standard deviations differ by a large factor; a long run of them — tens
// of metres of travel — is a degenerate stretch, the second kind of strong evidence. Short runs
// are common in working runs (a few metres of plain corridor between doors). Calibrated on the
// built-in worlds with planted failures and the four public logs (docs/metrics.md).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "slamtune/common/pose2.h"
#include "slamtune/slam/mapper.h"
#include "slamtune/slam/params/mapper_params.h"

namespace slamtune::slam {

// One sequential match as the front end made it.
struct SequentialMatchStep {
  int log_index = -1;            // scan index in the log
  double time = 0.0;             // s since the log's first scan
  double response = 0.0;         // in [0, 1]
  double dx = 0.0;               // m, match - guess, world frame (the search window's axes)
  double dy = 0.0;               // m
  double dtheta = 0.0;           // rad, normalised
  double sigma_xy = 0.0;         // m, larger principal standard deviation of the match's position
  double sigma_minor = 0.0;      // m, smaller one: sigma_xy / sigma_minor >> 1 where the scan saw one direction only
  double x = 0.0, y = 0.0;       // m, the matched position in the map's frame (where to mark the step on a map)
  bool at_window_edge = false;   // |dx| or |dy| reached the window's half side
  bool at_heading_edge = false;  // |dtheta| reached the coarse angular range
};

// The step of one ProcessResult with a sequential match (sequential_response >= 0), judged
// against the window and angular range of `params`.
SequentialMatchStep StepOf(const ProcessResult& result, int log_index, double time, const MapperParams& params);

struct FrontEndEvidenceOptions {
  // A step whose response is below this fraction of the run's median response is suspect;
  // in (0, 1).
  double low_response_fraction = 0.5;
  // Suspect steps at most this many steps apart belong to one stretch; >= 0.
  int max_gap = 3;
  // A stretch needs this many suspect steps to be reported; >= 1. Two: a single odd match is
  // common in a working run, two close together are not.
  int min_suspects = 2;
  // A break's response is below this fraction of the run's median; in (0, low_response_fraction].
  double break_response_fraction = 0.25;
  // The matches after an edge hit that may undo it; >= 1.
  int recovery_matches = 3;
  // They undo it when their summed correction leaves less than this fraction of its own; in (0, 1).
  double recovered_fraction = 0.5;
  // A match is degenerate when its larger principal standard deviation is at least this many
  // times its smaller one; > 1. Matches in rooms and junctions stay below 3; plain corridor, 5-8.
  double degenerate_anisotropy = 5.0;
  // Degenerate matches (gaps of at most max_gap other matches allowed) over at least this much
  // travel form a degenerate stretch; m, > 0. The public logs' longest runs at slam_karto's
  // defaults are 3-29 m, the corridor-long world's 44-47 m (docs/metrics.md).
  double min_degenerate_length_m = 35.0;

  // Throws InputError naming the field, its value and the rule.
  void Validate() const;
};

struct SuspectStretch {
  int first_log_index = -1, last_log_index = -1;  // log scan indices of its first and last suspect step
  double first_time = 0.0, last_time = 0.0;       // s since the log's first scan
  int suspects = 0;                               // suspect steps in it
  int at_edge = 0;                                // of them, matches that ended at the window's or heading range's edge
  int low_response = 0;                           // of them, matches with a collapsed response
  double min_response = 1.0;
  int breaks = 0;  // of them, breaks (edge hit, collapsed response, not undone)
  bool strong() const { return breaks > 0; }
};

// Travel over which the scans constrained one direction only (see the file comment).
struct DegenerateStretch {
  int first_log_index = -1, last_log_index = -1;  // log scan indices of its first and last match
  double first_time = 0.0, last_time = 0.0;       // s since the log's first scan
  int matches = 0;                                // degenerate matches in it
  double length_m = 0.0;        // travel from its first to its last match, along the matched positions
  double max_anisotropy = 0.0;  // the largest sigma ratio in it
};

struct FrontEndEvidence {
  int matches = 0;  // sequential matches made
  double median_response = 0.0;
  int at_edge = 0;                                      // matches at the window's or heading range's edge
  int low_response = 0;                                 // matches below low_response_fraction x median
  int breaks = 0;                                       // matches that broke the map (see above)
  std::vector<SuspectStretch> stretches;                // in log order
  int degenerate = 0;                                   // degenerate matches (anisotropy at or above the option)
  std::vector<DegenerateStretch> degenerate_stretches;  // at least min_degenerate_length_m long, in log order

  // True when the run shows a break or a degenerate stretch: the front end lost its place there,
  // or never had one.
  bool points_at_front_end() const { return breaks > 0 || !degenerate_stretches.empty(); }
  // One line for the terminal, e.g. "front end: 2 suspect stretches (scans 812-840 at
  // 162.4-168.0 s: 5 matches at the search window's edge; ...)" or "front end: no sign of a
  // broken sequential match (1469 matches, median response 0.71)".
  std::string Summary() const;
};

FrontEndEvidence AssessFrontEnd(const std::vector<SequentialMatchStep>& steps,
                                const FrontEndEvidenceOptions& options = {});

// True when a step is suspect given the run's median response.
bool IsSuspect(const SequentialMatchStep& step, double median_response, const FrontEndEvidenceOptions& options);

// True when a step is degenerate: sigma_xy >= degenerate_anisotropy x sigma_minor (and not both 0).
bool IsDegenerate(const SequentialMatchStep& step, const FrontEndEvidenceOptions& options);

// The degenerate stretches of a run, in log order.
std::vector<DegenerateStretch> FindDegenerateStretches(const std::vector<SequentialMatchStep>& steps,
                                                       const FrontEndEvidenceOptions& options);

// True when steps[i] is a break: suspect by both edge and response, and not undone by the
// recovery_matches steps after it.
bool IsBreak(const std::vector<SequentialMatchStep>& steps, std::size_t i, double median_response,
             const FrontEndEvidenceOptions& options);

// Watches a run's sequential matches as they are made and says when its front end has broken,
// so that a run which can no longer give a sound map can be stopped there (the tuner's
// front-end search does so: a broken map is never the recommendation). A break is IsBreak's,
// judged against the median response of the matches made so far (the whole run's median is not
// known yet) once at least `min_matches` have been made and the recovery_matches after it are
// in, so it is confirmed recovery_matches matches late (the first min_matches steps are judged
// when the min_matches-th is made). Deterministic; a value (copy it with
// the runner).
class BreakWatch {
 public:
  explicit BreakWatch(const FrontEndEvidenceOptions& options = {}, int min_matches = 20);

  // Call after each new step is appended to `steps` (the run's matches so far, in order);
  // returns the index into `steps` of a break confirmed by it, if any.
  std::optional<std::size_t> Add(const std::vector<SequentialMatchStep>& steps);

 private:
  // The median response of the steps seen so far, kept in two heaps.
  void Insert(double response);
  double Median() const;

  FrontEndEvidenceOptions options_;
  int min_matches_;
  std::vector<double> low_;   // max-heap: the lower half
  std::vector<double> high_;  // min-heap: the upper half
  std::size_t seen_ = 0;
  std::size_t next_ = 0;  // the first step not judged yet
};

}  // namespace slamtune::slam
