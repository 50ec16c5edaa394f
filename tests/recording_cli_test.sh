#!/usr/bin/env bash
# End-to-end test of ROS recordings on the command line, with the committed fixture bags
# (tests/fixtures/recordings, written by independent libraries from a simulated office drive
# with the laser mounted off the base): info, run (same run as on the world's CARMEN log),
# convert, check (clean and planted faults), and malformed recordings.
# Usage: recording_cli_test.sh SLAMTUNE_BINARY DATASETS_DIR. Exit 0 pass, 1 fail, 77 skip.
set -u
source "$(dirname "$0")/lib.sh"
cli_test_begin recording_cli_test "$@"
fixtures="$tests_dir/fixtures/recordings"
# The world the fixtures were made from (their README).
simulate_world "$work/sim" office --seed 1 --speed 1.0 --scan-rate 3 --laser-offset 0.12,-0.04,0.05 --float32-scans \
  --range-resolution 0.001953125
carmen="$work/sim/office.clf"
bags=(office_zstd.mcap office_db3 office_lz4.bag office_bz2.bag)

# 1. info reads every bag and says what it chose.
for b in "${bags[@]}"; do
  "$bin" info "$fixtures/$b" > "$work/info.txt" 2>&1 || fail "info $b: $(tail -1 "$work/info.txt")"
  grep -q "^scans  *  */scan (the only LaserScan topic), 655 messages, 655 used" "$work/info.txt" || fail "info $b: scan choice"
  grep -q "^laser offset  *x 0.1200 m, y -0.0400 m, yaw 2.865 deg" "$work/info.txt" || fail "info $b: laser offset"
done
"$bin" info "$fixtures/office_zstd.mcap" --json | grep -q '"input": \[' || fail "info --json lacks input"

# 2. run: the same loop closures and nodes as on the CARMEN log; trajectories agree to 1e-6 m.
"$bin" run "$carmen" --out "$work/run_carmen" --quiet > "$work/run_carmen.txt" || fail "run on the CARMEN log"
for b in "${bags[@]}"; do
  "$bin" run "$fixtures/$b" --out "$work/run_$b" > "$work/run_$b.txt" 2> "$work/run_$b.err" || fail "run $b: $(tail -1 "$work/run_$b.err")"
  grep -q "^odometry: tf odom -> base_footprint" "$work/run_$b.err" || fail "run $b does not print its odometry choice"
  cmp -s "$work/run_carmen/loop_closures.csv" "$work/run_$b/loop_closures.csv" || fail "run $b: loop closures differ"
  [[ "$(head -1 "$work/run_carmen.txt" | cut -d';' -f1 | sed 's/, [0-9.]* s wall.*//')" == \
     "$(head -1 "$work/run_$b.txt" | sed 's/, [0-9.]* s wall.*//')" ]] || fail "run $b: summary differs: $(cat "$work/run_$b.txt")"
  paste "$work/run_carmen/trajectory.txt" "$work/run_$b/trajectory.txt" | awk '
    !/^#/ { for (i = 1; i <= 4; ++i) { d = $i - $(i + 4); if (d < 0) d = -d; if (d > 1e-6) bad++ } }
    END { exit bad > 0 }' || fail "run $b: trajectory differs from the CARMEN run by more than 1e-6"
done

# 3. convert: the CARMEN log slamtune writes from a bag runs to the same loop closures.
"$bin" convert "$fixtures/office_zstd.mcap" --out "$work/converted.clf" --quiet > "$work/convert.txt" ||
  fail "convert: $(cat "$work/convert.txt")"
grep -q "^convert: 655 scans, 328 ODOM records; wrote" "$work/convert.txt" || fail "convert summary: $(cat "$work/convert.txt")"
grep -c '^ROBOTLASER1 ' "$work/converted.clf" | grep -qx 655 || fail "converted log lacks 655 ROBOTLASER1 lines"
"$bin" run "$work/converted.clf" --out "$work/run_converted" --quiet > /dev/null || fail "run on the converted log"
cmp -s "$work/run_carmen/loop_closures.csv" "$work/run_converted/loop_closures.csv" || fail "converted log: loop closures differ"

# 4. check: a clean bag passes, each planted fault is found; --strict exits 1 on a problem.
"$bin" check "$fixtures/office_zstd.mcap" --strict > "$work/check.txt" || fail "check on the clean bag: $(tail -3 "$work/check.txt")"
grep -q "^verdict: no problem found" "$work/check.txt" || fail "clean bag verdict"
for pair in fault_no_tf_static:no_laser_offset fault_tf_gap:tf_missing fault_two_scan_topics:several_scan_topics \
            fault_inf_nan:range_max_too_low; do
  f=${pair%%:*} kind=${pair##*:}
  "$bin" check "$fixtures/$f.mcap" > "$work/$f.txt"; rc=$?
  [[ $rc -eq 0 ]] || fail "check $f exited $rc without --strict"
  grep -q "^problem $kind:" "$work/$f.txt" || fail "check $f does not find $kind: $(grep '^verdict' "$work/$f.txt")"
  "$bin" check "$fixtures/$f.mcap" --strict > /dev/null; rc=$?
  [[ $rc -eq 1 ]] || fail "check --strict $f exited $rc, not 1"
done
"$bin" check "$fixtures/fault_tf_gap.mcap" --json | grep -q '"kind": "tf_missing"' || fail "check --json lacks the problem kind"

# 5. Malformed recordings: one line "slamtune: error: FILE...: what", exit 2, never a crash.
expect_error() {  # NAME FILE PATTERN [args]
  local name=$1 file=$2 pattern=$3; shift 3
  "$bin" info "$file" "$@" > "$work/err.out" 2> "$work/err.txt"; local rc=$?
  [[ $rc -eq 2 ]] || fail "$name: exit $rc, not 2 ($(head -c 300 "$work/err.txt"))"
  [[ $(wc -l < "$work/err.txt") -eq 1 ]] || fail "$name: not one line: $(head -c 300 "$work/err.txt")"
  grep -q "^slamtune: error: .*$pattern" "$work/err.txt" || fail "$name: message '$(cat "$work/err.txt")' lacks '$pattern'"
}
# A recording cut off inside a record (a power loss while recording) reads up to its last whole
# record, and every command says how many bytes were not read (run with --quiet too).
for cut in "150000 office_zstd.mcap truncated.mcap" "100000 office_lz4.bag truncated.bag"; do
  read -r size src name <<<"$cut"
  head -c "$size" "$fixtures/$src" > "$work/$name"
  "$bin" info "$work/$name" > "$work/cut_info.txt" 2>&1 || fail "info on a cut-off $src: $(tail -1 "$work/cut_info.txt")"
  grep -q "cut off inside a record: read up to its last whole record, the last [0-9]* bytes (.* % of the file) not read ($work/$name: byte" \
    "$work/cut_info.txt" || fail "info does not say $name was cut off: $(grep recording "$work/cut_info.txt")"
  "$bin" run "$work/$name" --out "$work/run_$name" --quiet > /dev/null 2> "$work/cut_run.txt" ||
    fail "run on a cut-off $src: $(cat "$work/cut_run.txt")"
  grep -q "^not used: the scans in the last [0-9]* bytes of the recording (how many is not known): cut off inside" \
    "$work/cut_run.txt" || fail "run --quiet does not say what was lost of $name: '$(cat "$work/cut_run.txt")'"
done
cp "$fixtures/office_slice_none.mcap" "$work/flipped.mcap"
printf '\xff\xff\xff\xff' | dd of="$work/flipped.mcap" bs=1 seek=60000 conv=notrunc status=none
"$bin" info "$work/flipped.mcap" > /dev/null 2> "$work/err.txt"; rc=$?
[[ $rc -eq 0 || $rc -eq 2 ]] || fail "corrupted MCAP: exit $rc ($(cat "$work/err.txt"))"
: > "$work/empty.mcap"
expect_error "empty file" "$work/empty.mcap" "empty"
mkdir "$work/notabag"
expect_error "folder without metadata.yaml" "$work/notabag" "metadata.yaml"
expect_error "missing tf_static" "$fixtures/fault_no_tf_static.mcap" "--laser-offset"
expect_error "two scan topics" "$fixtures/fault_two_scan_topics.mcap" "--scan-topic"
expect_error "unknown scan topic" "$fixtures/office_zstd.mcap" "--scan-topic /nope" --scan-topic /nope
expect_error "bad --beams" "$fixtures/office_zstd.mcap" "--beams 'x'" --beams x

cli_test_end
