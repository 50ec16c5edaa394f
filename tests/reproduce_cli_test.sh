#!/usr/bin/env bash
# End-to-end test that a parameter file `slamtune optimize` writes runs, with `slamtune run
# --params FILE` (and no other option), exactly the candidate optimize recommended: the same nodes,
# loop closures and error against the truth as results.json records. For a slam_toolbox base in
# the synchronous node's mode (best.yaml, whose first comment names the mode) and for a
# slam_karto base (best_slam_karto.yaml).
# `slamtune render --params FILE` reads the file with the same loader.
# Usage: reproduce_cli_test.sh SLAMTUNE_BINARY. Exit 0 pass, 1 fail, 77 skip.
set -u
source "$(dirname "$0")/lib.sh"
cli_test_begin reproduce_cli_test "$@" -- python3

# On the hall world (drift doubles walls) both bases are improved with this small budget.
simulate_world "$work/sim" hall --seed 2
log="$work/sim/hall.clf"
rel="$work/sim/hall.relations"

# The candidate the parameter files hold (the recommendation when better, else the base
# configuration, "default") and run.json, as "nodes loops error" lines.
written() {
  python3 - "$1" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
c = r["recommended" if r["verdict_kind"] == "better" else "default"]
print(c["nodes"], c["loop_closures"], "%.9g" % c["gt_error"]["trans_mean_m"])
PY
}
ran() {
  python3 - "$1" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
print(r["nodes"], r["loop_closures"], "%.9g" % r["gt_error"]["trans_mean_m"])
PY
}

json_resolution() {
  python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["map"]["resolution"])' "$1"
}

for case in slam_toolbox_sync:best.yaml slam_karto:best_slam_karto.yaml; do
  IFS=: read -r preset file <<<"$case"
  out="$work/opt_$preset"
  "$bin" optimize "$log" --relations "$rel" --preset "$preset" --out "$out" --population 8 --divisions 3 \
    --generations 2 --seed 5 --jobs 2 --quiet >"$out.txt" 2>&1 || { fail "$preset: optimize failed: $(tail -3 "$out.txt")"; continue; }
  grep -q "\"node_mode\": \"$preset\"" "$out/results.json" ||
    fail "$preset: results.json does not name the node mode"
  grep -q '"verdict_kind": "better"' "$out/results.json" || fail "$preset: no better recommendation to reproduce"
  "$bin" run "$log" --relations "$rel" --params "$out/$file" --out "$work/run_$preset" --quiet >"$work/run_$preset.txt" 2>&1 ||
    { fail "$preset: run --params $file failed: $(cat "$work/run_$preset.txt")"; continue; }
  expected=$(written "$out/results.json")
  got=$(ran "$work/run_$preset/run.json")
  [[ "$got" == "$expected" ]] || fail "$preset: run --params $file gives '$got', optimize recorded '$expected'"
  # render reads the file with the same loader: from the candidate's trajectory it draws the same
  # map as with the mode named explicitly, at the candidate's resolution.
  for how in file explicit; do
    extra=()
    [[ $how == explicit ]] && extra=(--preset "$preset")
    "$bin" render "$log" --poses "$work/run_$preset/trajectory.txt" --params "$out/$file" "${extra[@]}" \
      --out "$work/render_${preset}_$how" >"$work/render_$preset.txt" 2>&1 ||
      fail "$preset: render --params $file failed: $(cat "$work/render_$preset.txt")"
  done
  cmp -s "$work/render_${preset}_file/map.pgm" "$work/render_${preset}_explicit/map.pgm" ||
    fail "$preset: render --params $file draws another map than with --preset $preset"
  grep -q "^resolution: $(json_resolution "$work/run_$preset/run.json")\$" "$work/render_${preset}_file/map.yaml" ||
    fail "$preset: render --params $file: resolution differs from the run's"
done
# The mode comes from best.yaml's first comment; --preset overrides it.
grep -q '"node_mode": "slam_toolbox_sync"' "$work/run_slam_toolbox_sync/run.json" ||
  fail "run --params best.yaml did not take the mode best.yaml was tuned for"

cli_test_end
