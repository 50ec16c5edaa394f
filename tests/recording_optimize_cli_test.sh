#!/usr/bin/env bash
# `slamtune optimize BAG` end to end on the committed fixture bags of a simulated office drive
# (ROS 2 MCAP zstd, rosbag2 SQLite3 folder, ROS 1 lz4 and bz2; laser mounted off the base):
# each gives the same recommendation, knee, worst and default — and the same objective and
# parameter tables — as the world's CARMEN log.
# Usage: recording_optimize_cli_test.sh SLAMTUNE_BINARY DATASETS_DIR. Exit 0 pass, 1 fail, 77 skip.
set -u
source "$(dirname "$0")/lib.sh"
cli_test_begin recording_optimize_cli_test "$@"
fixtures="$tests_dir/fixtures/recordings"
simulate_world "$work/sim" office --seed 1 --speed 1.0 --scan-rate 3 --laser-offset 0.12,-0.04,0.05 --float32-scans \
  --range-resolution 0.001953125
budget=(--population 8 --generations 2 --divisions 3 --seed 7 --jobs 2)
candidates() { grep -E '^(recommended|knee|worst|default) ' "$1"; }

"$bin" optimize "$work/sim/office.clf" --out "$work/carmen" "${budget[@]}" > "$work/carmen.txt" 2>&1 ||
  { echo "FAIL: optimize on the CARMEN log: $(tail -3 "$work/carmen.txt")" >&2; exit 1; }
candidates "$work/carmen.txt" > "$work/carmen.candidates"
[[ $(wc -l < "$work/carmen.candidates") -eq 4 ]] || fail "the CARMEN run printed no candidates"
for b in office_zstd.mcap office_db3 office_lz4.bag office_bz2.bag; do
  "$bin" optimize "$fixtures/$b" --out "$work/$b" "${budget[@]}" > "$work/$b.txt" 2>&1 ||
    { fail "optimize $b: $(tail -3 "$work/$b.txt")"; continue; }
  candidates "$work/$b.txt" | diff "$work/carmen.candidates" - > "$work/$b.diff" ||
    fail "optimize $b: candidates differ from the CARMEN log's: $(cat "$work/$b.diff")"
  for t in table3_best_worst_params.csv table4_6_objectives.csv table7_loop_closures.csv; do
    cmp -s "$work/carmen/$t" "$work/$b/$t" || fail "optimize $b: $t differs from the CARMEN log's"
  done
  grep -q "^laser offset: x 0.1200 m, y -0.0400 m" "$work/$b.txt" || fail "optimize $b does not print the laser offset"
done
echo "recommended on every recording: $(grep '^recommended' "$work/carmen.candidates")"
cli_test_end
