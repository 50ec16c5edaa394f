#!/usr/bin/env bash
# End-to-end test of `slamtune optimize` and `slamtune sweep` on a slice of the simulated office
# world (the built-in world itself for its default budget): outputs, an exact resume after `kill -9`
# in the middle of a generation, and input errors.
# Usage: optimize_cli_test.sh SLAMTUNE_BINARY DATASETS_DIR. Exit 0 pass, 1 fail, 77 skip.
set -u
source "$(dirname "$0")/lib.sh"
cli_test_begin optimize_cli_test "$@"
# The plumbing runs on a slice of the office world's log; what is particular to the built-in world
# (its default budget) on the world itself.
office_slice
small=("${slice[@]}" --population 8 --generations 3 --divisions 3 --seed 5 --jobs 2 --quiet)

# 1. An uninterrupted run writes every output.
"$bin" optimize --out "$work/whole" "${small[@]}" > "$work/whole.txt" 2>&1 || fail "optimize failed: $(tail -3 "$work/whole.txt")"
for f in best.yaml best_slam_karto.yaml results.json report.html evaluations.csv table3_best_worst_params.csv table4_6_objectives.csv \
         table7_loop_closures.csv table8_loop_scans.csv table9_10_errors.csv maps_side_by_side.png \
         population_gen1.png population_gen3.png map_recommended.pgm map_recommended.yaml run.sqlite; do
  [[ -s "$work/whole/$f" ]] || fail "missing output $f"
done
for key in recommended knee worst default evaluations cache_hits wall_s; do
  grep -q "\"$key\"" "$work/whole/results.json" || fail "results.json lacks $key"
done
grep -q "loop_search_maximum_distance:" "$work/whole/best.yaml" || fail "best.yaml lacks r"
grep -q "ros__parameters:" "$work/whole/best.yaml" || fail "best.yaml is not a ROS 2 parameter file"
# The slam_karto file is flat (ROS 1) and holds the same values.
r2=$(grep -E '^ +loop_search_maximum_distance:' "$work/whole/best.yaml" | awk '{print $2}')
r1=$(grep -E '^loop_search_maximum_distance:' "$work/whole/best_slam_karto.yaml" | awk '{print $2}')
[[ -n "$r1" && "$r1" == "$r2" ]] || fail "best_slam_karto.yaml r '$r1' is not best.yaml's '$r2'"
if grep -q "ros__parameters" "$work/whole/best_slam_karto.yaml"; then fail "best_slam_karto.yaml is nested"; fi
# No --objectives and a loop-closure search (the node spacing is fixed): maps are judged by
# u_h, n_c and the count of occupied cells; --objectives names another set.
grep -Eq '"set": *"occupied"' "$work/whole/results.json" || fail "results.json: the automatic set is not 'occupied'"
# The report counts the recommendation's share against the population that was run.
grep -Eq '<th>recommended share</th><td>[0-9]+ of 8 individuals of the final population</td>' "$work/whole/report.html" ||
  fail "report.html does not give the recommended share of the population of 8"

# With --verbose, progress lines (plain, not a terminal) say how much scan matching the runs
# shared and the end lists the caches; without it, or with --no-share, nothing of it.
tiny=("${slice[@]}" --population 4 --generations 1 --divisions 3 --seed 5 --jobs 2)
"$bin" optimize --out "$work/tiny" "${tiny[@]}" --verbose > "$work/tiny.txt" 2>&1 || fail "optimize (tiny) failed: $(tail -3 "$work/tiny.txt")"
grep -Eq '^gen 1/1 .*\| matches: [0-9.]+% of [0-9.]+( [kM])? shared, [0-9.]+( [kM])? computed$' "$work/tiny.txt" ||
  fail "progress lacks the shared-match summary: $(grep '^gen' "$work/tiny.txt" | tail -1)"
grep -q '^match cache: ' "$work/tiny.txt" || fail "--verbose did not list the caches"
grep -q '^generation 0: [0-9]* SLAM runs in .* to come take up to' "$work/tiny.txt" || fail "no budget estimate after generation 0"
"$bin" optimize --out "$work/tiny_plain" "${tiny[@]}" > "$work/tiny_plain.txt" 2>&1 || fail "optimize (plain) failed"
if grep -Eq 'matches:|^match cache' "$work/tiny_plain.txt"; then fail "cache statistics without --verbose"; fi
grep -q 'maps judged by unbacked hits (u_h), corner pixels (n_c) and occupied cells (n_o);' "$work/tiny_plain.txt" ||
  fail "the first line does not say what maps are judged by: $(grep '^optimising' "$work/tiny_plain.txt")"
"$bin" optimize --out "$work/tiny_consistency" "${tiny[@]}" --objectives consistency --quiet > /dev/null 2>&1 ||
  fail "optimize --objectives consistency failed"
grep -Eq '"set": *"consistency"' "$work/tiny_consistency/results.json" || fail "--objectives consistency was not used"
"$bin" optimize --out "$work/tiny_noshare" "${tiny[@]}" --no-share --verbose > "$work/tiny_noshare.txt" 2>&1 ||
  fail "optimize --no-share failed: $(tail -3 "$work/tiny_noshare.txt")"
grep -q '^gen 1/1 ' "$work/tiny_noshare.txt" || fail "--no-share run printed no progress line"
if grep '^gen' "$work/tiny_noshare.txt" | grep -q 'matches:'; then fail "--no-share progress mentions shared matches"; fi

# The default budget: on a log, 36 individuals over the 36 reference points of 7 divisions; on
# the built-in world, 10 divisions unless --divisions is given.
setting() { python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["settings"][sys.argv[2]])' "$@"; }
"$bin" optimize --out "$work/world_budget" --population 4 --generations 1 --seed 5 --jobs 2 --quiet > /dev/null 2>&1 ||
  fail "optimize (world budget) failed"
[[ $(setting "$work/world_budget/results.json" divisions) == 10 ]] || fail "the built-in world's divisions are not 10"
"$bin" optimize "$work/office/office.clf" --max-scans 40 --generations 1 --seed 5 --jobs 2 --quiet \
  --out "$work/log_budget" > "$work/log_budget.txt" 2>&1 || fail "optimize (log budget) failed: $(tail -3 "$work/log_budget.txt")"
[[ $(setting "$work/log_budget/results.json" population) == 36 && $(setting "$work/log_budget/results.json" divisions) == 7 ]] ||
  fail "a log's default budget is not population 36 over 7 divisions"
"$bin" optimize --help | grep -q 'default 7: 36 points' || fail "optimize --help does not state the default divisions"

# 2. kill -9 in the middle of the run, then --resume: the same tables as the uninterrupted run.
"$bin" optimize --out "$work/cut" "${small[@]}" > "$work/cut.txt" 2>&1 &
pid=$!
for _ in $(seq 1 600); do  # wait until some evaluations are committed (the WAL grows with each)
  size=$(stat -c %s "$work/cut/run.sqlite-wal" 2>/dev/null || echo 0)
  [[ "$size" -gt 60000 ]] && break
  kill -0 "$pid" 2>/dev/null || break
  sleep 0.2
done
if kill -0 "$pid" 2>/dev/null; then
  kill -9 "$pid"; wait "$pid" 2>/dev/null
  echo "killed the run after its WAL reached $size bytes"
else
  fail "the run finished before it could be killed (test did not exercise resume)"
fi
"$bin" optimize --resume "$work/cut" --jobs 2 --quiet > "$work/resume.txt" 2>&1 || fail "resume failed: $(tail -3 "$work/resume.txt")"
for f in table3_best_worst_params.csv table4_6_objectives.csv table7_loop_closures.csv table8_loop_scans.csv \
         table9_10_errors.csv best.yaml best_slam_karto.yaml; do
  cmp -s "$work/whole/$f" "$work/cut/$f" || fail "$f differs between the uninterrupted and the resumed run"
done

# 3. Bad input: clear errors before any work.
expect_error() {  # PATTERN CMD...
  local pattern=$1; shift
  local out; out=$("$@" 2>&1); local rc=$?
  [[ $rc -ne 0 ]] || fail "expected failure: $*"
  grep -q -- "$pattern" <<<"$out" || fail "expected '$pattern' from: $* (got: $out)"
}
mkdir -p "$work/notarun"
expect_error "not a slamtune optimisation folder" "$bin" optimize --resume "$work/notarun"
expect_error "already holds an optimisation" "$bin" optimize --out "$work/whole" "${small[@]}"
expect_error "different settings" "$bin" optimize --resume "$work/whole" --seed 6 --population 8 --generations 3 --divisions 3
expect_error "cannot open" "$bin" optimize "$work/missing.clf" --out "$work/x1"
printf 'vary:\n  loop_search_maximum_distance: {min: 6, max: 2}\n' > "$work/reversed.yaml"
expect_error "bounds reversed" "$bin" optimize --space "$work/reversed.yaml" --out "$work/x2"
printf 'vary:\n  loop_search_maximum_distanse: {min: 2, max: 6}\n' > "$work/unknown.yaml"
expect_error "loop_search_maximum_distanse" "$bin" optimize --space "$work/unknown.yaml" --out "$work/x3"
printf 'vary: {}\n' > "$work/empty.yaml"
expect_error "search space is empty" "$bin" optimize --space "$work/empty.yaml" --out "$work/x4"
touch "$work/afile"
expect_error "cannot create output folder" "$bin" optimize --out "$work/afile/sub" "${small[@]}"

# 4. sweep along g at r = 2 (the paper's Figure 14), three values.
"$bin" sweep "${slice[@]}" --vary g=6:20:7 --fix r=2 --out "$work/sweep" --quiet > "$work/sweep.txt" 2>&1 || fail "sweep failed"
[[ -s "$work/sweep/sweep.csv" && -s "$work/sweep/sweep.png" ]] || fail "sweep outputs missing"
[[ $(grep -c "loop_match_minimum_chain_size" "$work/sweep/sweep.csv") -ge 1 ]] || fail "sweep.csv lacks the parameter"
expect_error "bounds reversed" "$bin" sweep --vary r=6:2 --out "$work/sweep2"

cli_test_end
