#!/usr/bin/env bash
# End-to-end test of the parameter files `slamtune optimize` writes, starting from a user's own
# slam_toolbox and slam_karto configuration (tests/fixtures/params): the baseline is that
# configuration, each written file loads in its node (`slamtune params` exits 1 otherwise),
# the full file means the base with the tuned values, base + change = full, and `--params
# best.yaml` starts the next run from exactly the recommendation.
# Usage: params_files_cli_test.sh SLAMTUNE_BINARY [DATASETS_DIR]. Exit 0 pass, 1 fail, 77 skip.
set -u
source "$(dirname "$0")/lib.sh"
cli_test_begin params_files_cli_test "$@"
fixtures="$tests_dir/fixtures/params"
office_slice
common=("${slice[@]}" --population 8 --divisions 3 --seed 3 --jobs 2)
small=("${common[@]}" --generations 2)
short=("${common[@]}" --generations 1 --quiet)

# The engine's values of a stack of parameter files (sorted lines "name value").
meaning() { "$bin" params "$@" --all | awk '/^engine parameters over/{p = 1; next} p && /^  /{print $1, $2}' | sort; }

for case in toolbox:slam_toolbox_online_async.yaml:best.yaml:best_change.yaml \
            karto:slam_karto_mapper_params.yaml:best_slam_karto.yaml:best_slam_karto_change.yaml; do
  IFS=: read -r name base full change <<<"$case"
  out="$work/$name"
  "$bin" optimize --params "$fixtures/$base" --out "$out" "${small[@]}" >"$out.txt" 2>&1 ||
    { fail "$name: optimize failed: $(tail -3 "$out.txt")"; continue; }
  for f in best.yaml best_change.yaml best_slam_karto.yaml best_slam_karto_change.yaml; do
    "$bin" params "$out/$f" >"$out.$f.check" 2>&1 || fail "$name: $f does not load: $(cat "$out.$f.check")"
  done
  grep -q "\"base\": \"your configuration ($base)\"" "$out/results.json" ||
    fail "$name: results.json's base is not the user's file"
  grep -q "your configuration ($base)" "$out/report.html" || fail "$name: the report does not name the baseline"
  grep -q "ros2 launch slam_toolbox online_async_launch.py slam_params_file:=" "$out/report.html" ||
    fail "$name: the report does not say how to load the files"
  head -1 "$out/$full" | grep -qE '^# slamtune optimize, tuned for [a-z_]+ \(.*\): (the recommendation|NOT better)' ||
    fail "$name: $full does not open with the verdict"
  # The user's own lines are kept in the full file written for their node.
  if [[ $name == toolbox ]]; then
    grep -q "    mode: mapping #localization" "$out/$full" || fail "$name: the user's lines are not kept"
  else
    grep -q "^minimum_time_interval: 3600" "$out/$full" || fail "$name: the user's lines are not kept"
  fi
  # base + change = full
  [[ "$(meaning "$fixtures/$base" "$out/$change")" == "$(meaning "$out/$full")" ]] ||
    fail "$name: base + $change differs from $full"
  # The full file is the base with the recommended values (or the base unchanged).
  if grep -q '"verdict_kind": "better"' "$out/results.json"; then
    sets=()
    while IFS= read -r line; do
      [[ $line =~ ^\ \ ([a-z_]+):\ .*\ -\>\ (.*)$ ]] && sets+=(--set "${BASH_REMATCH[1]}=${BASH_REMATCH[2]}")
    done < <(sed -n '/^changes from /,/^$/p' "$out.txt")
    (( ${#sets[@]} > 0 )) || fail "$name: better, but no changes printed"
  else
    sets=()
    [[ -z "$(grep -v '^#' "$out/$change")" ]] || fail "$name: not better, but $change sets parameters"
  fi
  [[ "$(meaning "$fixtures/$base" "${sets[@]}")" == "$(meaning "$out/$full")" ]] ||
    fail "$name: $full is not the base with the printed changes"
  # Round trip: the next run's baseline is the recommendation.
  "$bin" optimize --params "$out/$full" --out "$out-again" "${short[@]}" >"$out-again.txt" 2>&1 ||
    fail "$name: optimize --params $full failed: $(tail -3 "$out-again.txt")"
  grep -A400 '"default"' "$out-again/results.json" | sed -n '/"params"/,/}/{p;/}/q}' >"$out.again.params"
  if grep -q '"verdict_kind": "better"' "$out/results.json"; then
    grep -A400 '"recommended": {' "$out/results.json" | sed -n '/"params"/,/}/{p;/}/q}' >"$out.first.params"
    diff -q "$out.first.params" "$out.again.params" >/dev/null ||
      fail "$name: --params $full does not start from the recommendation: $(diff "$out.first.params" "$out.again.params")"
  fi
done

# The check can fail: a wrong type, an unknown name, an unregistered solver.
printf 'slam_toolbox:\n  ros__parameters:\n    scan_buffer_size: 10.0\n    solver_plugin: solver_plugins::SpaSolver\n' \
  >"$work/bad.yaml"
"$bin" params "$work/bad.yaml" >"$work/bad.txt" 2>&1 && fail "params accepted a file slam_toolbox would refuse"
grep -q "scan_buffer_size: '10.0' reads as double, the node declares int" "$work/bad.txt" || fail "no type problem: $(cat "$work/bad.txt")"
grep -q "is not registered by slam_toolbox" "$work/bad.txt" || fail "no plugin problem: $(cat "$work/bad.txt")"

# Without --params the baseline is the preset's own defaults, named.
"$bin" optimize --preset slam_toolbox --out "$work/preset" "${short[@]}" >/dev/null 2>&1 ||
  fail "optimize --preset slam_toolbox failed"
grep -q '"base": "slam_toolbox'"'"'s defaults"' "$work/preset/results.json" || fail "preset baseline not named"
grep -q '"loop_search_maximum_distance": 3.0' "$work/preset/results.json" || fail "slam_toolbox's r = 3.0 not the baseline"

cli_test_end
