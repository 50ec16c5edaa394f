#!/usr/bin/env bash
# End-to-end test of `slamtune run` on a simulated corridor log (and a short slice of aces when
# the datasets are present): output files, run.json keys, determinism, parameter handling and
# input errors.
# Usage: run_cli_test.sh SLAMTUNE_BINARY DATASETS_DIR
# Exit 0 = pass, 1 = fail, 77 = skip (binary missing).
set -u
source "$(dirname "$0")/lib.sh"
cli_test_begin run_cli_test "$@"
json_has() {  # FILE KEY: a top-level key "KEY": in the pretty-printed JSON
  grep -q "^  \"$2\":" "$1" || fail "$1 has no top-level key $2"
}
json_int() {  # FILE KEY -> integer value of a top-level key
  sed -n "s/^  \"$2\": \([0-9]*\),\{0,1\}$/\1/p" "$1"
}

simulate_world "$work/sim" corridor --speed 1.0 --seed 3
log="$work/sim/corridor.clf"
rel="$work/sim/corridor.relations"
fast=(--set minimum_travel_distance=0.4 --set scan_buffer_size=20 --set loop_match_minimum_chain_size=5)

# 1. A run writes every output.
if ! "$bin" run "$log" --out "$work/a" --relations "$rel" "${fast[@]}" --quiet >"$work/a.out" 2>"$work/a.err"; then
  fail "run exited non-zero: $(cat "$work/a.err")"
fi
for f in map.pgm map.yaml map.png trajectory.txt loop_closures.csv front_end.csv front_end_map.png run.json; do
  [[ -s "$work/a/$f" ]] || fail "missing or empty output $f"
done
for key in scans nodes loop_closures wall_s params edges solver_runs peak_memory_mb gt_error map; do
  json_has "$work/a/run.json" "$key"
done
grep -q '"loop_match_minimum_chain_size": 5' "$work/a/run.json" || fail "run.json params do not show the --set value"
grep -q '"trans_mean_m":' "$work/a/run.json" || fail "run.json gt_error has no trans_mean_m"
grep -q "^run: .* nodes, .* loop closures" "$work/a.out" || fail "no summary line on stdout: $(cat "$work/a.out")"
scans=$(json_int "$work/a/run.json" scans)
lines=$(grep -vc '^#' "$work/a/trajectory.txt")
[[ "$scans" == "$lines" ]] || fail "trajectory has $lines poses for $scans scans"
loops=$(json_int "$work/a/run.json" loop_closures)
csv_rows=$(($(wc -l <"$work/a/loop_closures.csv") - 1))
[[ "$loops" == "$csv_rows" ]] || fail "loop_closures.csv has $csv_rows rows, run.json says $loops"
[[ "$loops" -ge 1 ]] || fail "the corridor run closed no loop"
grep -q '^image: map.pgm' "$work/a/map.yaml" || fail "map.yaml does not name map.pgm"
[[ "$(head -c 2 "$work/a/map.pgm")" == "P5" ]] || fail "map.pgm is not a binary PGM"

# 2. Determinism: the same command gives the same trajectory and map.
"$bin" run "$log" --out "$work/b" --relations "$rel" "${fast[@]}" --quiet >/dev/null 2>&1 || fail "second run failed"
cmp -s "$work/a/trajectory.txt" "$work/b/trajectory.txt" || fail "trajectories of two identical runs differ"
cmp -s "$work/a/map.pgm" "$work/b/map.pgm" || fail "maps of two identical runs differ"

# 2b. --trace: the same run (same trajectory), one line per match and solve (docs/trace.md).
"$bin" run "$log" --out "$work/t" --relations "$rel" "${fast[@]}" --trace "$work/trace.txt" --quiet >/dev/null 2>&1 ||
  fail "run with --trace failed"
cmp -s "$work/a/trajectory.txt" "$work/t/trajectory.txt" || fail "--trace changed the trajectory"
nodes=$(json_int "$work/a/run.json" nodes)
seq_lines=$(grep -c '^match sequential ' "$work/trace.txt")
[[ "$seq_lines" == "$((nodes - 1))" ]] || fail "trace has $seq_lines sequential matches for $nodes nodes"
accepted=$(grep -c '^match loop_fine .* accepted$' "$work/trace.txt")
[[ "$accepted" == "$loops" ]] || fail "trace has $accepted accepted loop matches, run.json $loops loops"
solves=$(grep -c '^solve ' "$work/trace.txt")
[[ "$solves" == "$loops" ]] || fail "trace has $solves solves for $loops loops"
awk '$1 == "match" && NF != 21 { bad = 1 } $1 == "solve" && NF != 11 { bad = 1 } $1 == "step" && NF != 5 { bad = 1 }
     END { exit bad }' "$work/trace.txt" || fail "trace lines with the wrong number of fields"
"$bin" run "$log" --out "$work/t2" "${fast[@]}" --trace "$work/no_such_dir/trace.txt" --quiet >/dev/null 2>&1 &&
  fail "an unwritable --trace path was accepted"

# 3. --no-loop-closure and a ROS 2 parameter file.
cat >"$work/params.yaml" <<'EOF'
slam_toolbox:
  ros__parameters:
    odom_frame: odom
    minimum_travel_distance: 0.4
    scan_buffer_size: 20
    loop_match_minimum_chain_size: 5
EOF
"$bin" run "$log" --out "$work/c" --params "$work/params.yaml" --no-loop-closure --quiet >/dev/null 2>&1 ||
  fail "run with --params and --no-loop-closure failed"
"$bin" run "$log" --out "$work/c2" --params "$work/params.yaml" --quiet >/dev/null 2>&1 || fail "run with --params failed"
[[ "$(json_int "$work/c/run.json" loop_closures)" == "0" ]] || fail "--no-loop-closure still closed loops"
[[ "$(json_int "$work/c/run.json" nodes)" == "$(json_int "$work/c2/run.json" nodes)" ]] ||
  fail "node count depends on loop closure (it must depend on odometry only)"
grep -q '"node_mode": "slam_toolbox_async"' "$work/c/run.json" || fail "a slam_toolbox file does not run its node"

# 3b. A laser whose beam count changes: every other scan as a ROBOTLASER1 line keeping beams 0, 2, ...,
# 180 at their own angles (91 beams, 2 degree steps). The node drops them (--beams node, the default);
# --beams per-geometry runs one Karto laser per geometry and drops none (docs/engine.md §3.5).
awk 'BEGIN { pi = atan2(0, -1) }
     /^FLASER / && ++k % 2 == 0 {
       n = $2; out = sprintf("ROBOTLASER1 0 %.17g %.17g %.17g 30 0 0 91", -pi / 2, pi, pi / 90)
       for (i = 0; i < n; i += 2) out = out " " $(3 + i)
       out = out " 0"
       for (j = 3 + n; j <= 8 + n; ++j) out = out " " $j
       out = out " 0 0 0 0 0"
       for (j = 9 + n; j <= 11 + n; ++j) out = out " " $j
       print out; next
     }
     { print }' "$log" >"$work/two_counts.clf"
"$bin" run "$work/two_counts.clf" --out "$work/n" "${fast[@]}" --quiet >/dev/null 2>&1 || fail "run on two counts failed"
"$bin" run "$work/two_counts.clf" --out "$work/g" --beams per-geometry "${fast[@]}" --quiet >"$work/g.out" 2>&1 ||
  fail "run --beams per-geometry failed: $(cat "$work/g.out")"
wrong_count() {  # RUN_JSON -> scans_not_used.wrong_reading_count.count
  python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["scans_not_used"]["wrong_reading_count"]["count"])' "$1"
}
[[ "$(wrong_count "$work/n/run.json")" -gt 100 ]] || fail "the node kept scans of another count"
[[ "$(wrong_count "$work/g/run.json")" == "0" ]] || fail "per-geometry dropped scans"
[[ "$(grep -c '"name": "laser_' "$work/g/run.json")" == "2" ]] || fail "per-geometry: run.json does not list two lasers"
grep -q '"laser_link": 1' "$work/g/run.json" || fail "per-geometry: the lasers' first scans are not linked"
grep -q '^lasers: laser_0 (181 readings) .*, laser_1 (91 readings)' "$work/g.out" || fail "no lasers line: $(cat "$work/g.out")"
"$bin" run "$work/two_counts.clf" --out "$work/g2" --beams per-geometry "${fast[@]}" --quiet >/dev/null 2>&1
cmp -s "$work/g/trajectory.txt" "$work/g2/trajectory.txt" || fail "two per-geometry runs differ"

# 4. Bad input: exit 2 with a message naming the problem.
expect_error() {  # PATTERN ARGS...
  local pattern=$1
  shift
  "$bin" run "$@" >"$work/err.out" 2>"$work/err.txt"
  local code=$?
  [[ $code -eq 2 ]] || fail "run $* exited $code, expected 2"
  grep -q -- "$pattern" "$work/err.txt" || fail "run $*: message lacks '$pattern': $(cat "$work/err.txt")"
}
expect_error "unknown mapper parameter 'loop_radius'" "$log" --out "$work/e1" --set loop_radius=3
expect_error "loop_match_minimum_chain_size = 0 is out of range" "$log" --out "$work/e2" \
  --set loop_match_minimum_chain_size=0
expect_error "unknown preset 'cartographer'" "$log" --out "$work/e3" --preset cartographer
expect_error "no_such.clf" "$work/no_such.clf" --out "$work/e4"
# Every reading a no-return (NaN, inf, negative, at the maximum): a clear error, not an empty map.
printf 'FLASER 2 1.0 nan 0 0 0 0 0 0 1.0 host 1.0\nFLASER 2 inf -1 0.1 0 0 0.1 0 0 1.2 host 1.2\n' > "$work/noreturns.clf"
expect_error "nothing to map" "$work/noreturns.clf" --out "$work/e5"

# 5. A short slice of a real dataset, with its relations, when available.
if [[ -n "$datasets" && -f "$datasets/aces.clf.gz" ]]; then
  if "$bin" run "$datasets/aces.clf.gz" --max-scans 400 --relations "$datasets/aces.relations" --out "$work/aces" \
    --quiet >/dev/null 2>"$work/aces.err"; then
    grep -q '"laser_max_range_m": 50.0' "$work/aces/run.json" || fail "aces: maxRange is not the 50 m no-return value"
    grep -q '"relations_used": [1-9]' "$work/aces/run.json" || fail "aces: no relation used"
  else
    fail "aces slice failed: $(cat "$work/aces.err")"
  fi
else
  echo "note: datasets not found, aces slice skipped" >&2
fi

cli_test_end
