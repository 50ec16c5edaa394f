#!/usr/bin/env bash
# The stopping rule end to end (docs/usage.md, "optimize"): on the built-in office world, whose
# answer settles within a few generations, `optimize` stops before its cap of 30 generations
# and says so; a run interrupted by SIGINT before that point and resumed stops at the same
# generation with the same parameter files and tables. (That the rule does not stop while the
# front still moves is tested on a synthetic problem in optim/settling_test.cc.)
# Usage: early_stop_cli_test.sh SLAMTUNE_BINARY [DATASETS_DIR]. Exit 0 pass, 1 fail.
set -u
source "$(dirname "$0")/lib.sh"
cli_test_begin early_stop_cli_test "$@" -- sqlite3

# Seed 4 settles after 8 generations (seed 1 after 23): long enough to interrupt before the stop,
# short enough to run twice (whole, then cut and resumed) in a test.
args=(--world office --population 8 --generations 30 --seed 4 --jobs 2)

# stopped_at FILE: N of the line "NSGA-III stopped after generation N of 30: ...", or nothing.
stopped_at() { sed -n 's/^NSGA-III stopped after generation \([0-9]*\) of 30: .*/\1/p' "$1"; }

"$bin" optimize --out "$work/whole" "${args[@]}" > "$work/whole.out" 2> "$work/whole.err" ||
  { echo "FAIL: optimize failed: $(tail -3 "$work/whole.err")" >&2; exit 1; }
settled=$(stopped_at "$work/whole.out")
if [[ -z "$settled" ]]; then
  fail "no 'stopped after generation N of 30' line: $(grep '^NSGA-III' "$work/whole.out")"
  exit 1
fi
(( settled < 30 )) || fail "stopped at the cap ($settled), not before"
(( settled >= 4 )) || { fail "settled at generation $settled: too early to interrupt before it"; exit 1; }
grep -q "\"generations_run\": *$settled\b" "$work/whole/results.json" ||
  fail "results.json does not say generations_run $settled"
grep -q "stopped after generation $settled of 30" "$work/whole/report.html" ||
  fail "report.html does not say it stopped after generation $settled"

# generation DIR: the last generation stored in DIR's run database (-1 before the first).
generation() {
  [[ -s "$1/run.sqlite" ]] || { echo -1; return; }
  sqlite3 -cmd '.timeout 2000' "$1/run.sqlite" 'SELECT COALESCE(MAX(gen), -1) FROM generations' 2>/dev/null || echo -1
}

set -m  # a background job gets SIGINT only with job control on
"$bin" optimize --out "$work/cut" "${args[@]}" > "$work/cut.out" 2> "$work/cut.err" &
pid=$!
background+=("$pid")
stored=-1
for _ in $(seq 1 1200); do
  stored=$(generation "$work/cut")
  (( stored >= 2 )) && break
  kill -0 "$pid" 2>/dev/null || break
  sleep 0.1
done
(( stored >= 2 )) || fail "generation 2 was never stored: $(tail -3 "$work/cut.err")"
kill -INT "$pid"
wait "$pid"
rc=$?
[[ $rc -eq 130 ]] || fail "SIGINT: exit $rc, want 130"
interrupted=$(generation "$work/cut")
(( interrupted < settled )) || fail "interrupted at generation $interrupted, not before $settled"

"$bin" optimize --resume "$work/cut" --jobs 2 > "$work/resume.out" 2> "$work/resume.err" ||
  fail "--resume failed: $(tail -3 "$work/resume.err")"
resumed=$(stopped_at "$work/resume.out")
[[ "$resumed" == "$settled" ]] || fail "resumed run stopped after generation '$resumed', uninterrupted after $settled"
for f in best.yaml best_change.yaml best_slam_karto.yaml table3_best_worst_params.csv table4_6_objectives.csv \
         table7_loop_closures.csv; do
  cmp -s "$work/whole/$f" "$work/cut/$f" || fail "$f differs between the uninterrupted and the resumed run"
done

cli_test_end "settled after generation $settled of 30; interrupted after $interrupted, resumed to the same stop"
