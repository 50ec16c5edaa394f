#!/usr/bin/env bash
# End-to-end test of `slamtune fault`: odometry faults planted into a CARMEN log (a simulated
# office drive) and a ROS bag; readings and timestamps kept, poses changed only from the stretch
# on, a planted jump breaks the map the way the office-jump world does, and bad input is one
# line and exit 2 with nothing written.
# Usage: fault_cli_test.sh SLAMTUNE_BINARY DATASETS_DIR (datasets are not needed). Exit 0 pass, 1 fail, 77 skip.
set -u
source "$(dirname "$0")/lib.sh"
cli_test_begin fault_cli_test "$@"
fixtures="$tests_dir/fixtures/recordings"

simulate_world "$work/sim" office
log="$work/sim/office.clf"
relations="$work/sim/office.relations"

# FLASER fields of a log, one line per scan: readings and timestamps (kept), poses (changed).
readings() { awk '$1 == "FLASER" { n = $2; s = n; for (i = 3; i <= n + 2; ++i) s = s sprintf(" %.6f", $i); print s }' "$1"; }
stamps() { awk '$1 == "FLASER" { n = $2; printf "%.6f %.6f\n", $(n + 9), $(n + 11) }' "$1"; }
poses() { awk '$1 == "FLASER" { n = $2; printf "%.6f %.6f %.6f %.6f %.6f %.6f\n", $(n+3), $(n+4), $(n+5), $(n+6), $(n+7), $(n+8) }' "$1"; }
odom() { awk '$1 == "ODOM" { printf "%.6f %.6f %.6f %.6f\n", $2, $3, $4, $8 }' "$1"; }

# 1. A jump of 1.5 m at 20 m: the scans are the same, the poses up to the stretch too, and after
#    it the odometry is 1.5 m further on.
"$bin" fault "$log" --fault jump,20,0.1,1.5 --out "$work/jump.clf" > "$work/jump.txt" 2> "$work/jump.err" ||
  fail "fault: $(cat "$work/jump.err")"
grep -q "^fault: odometric travel [0-9.]* m ([0-9]* robot poses, file order)" "$work/jump.txt" || fail "no travel line: $(cat "$work/jump.txt")"
grep -q "^planted jump at 20 m over 0.1 m: 1.5 m reported, not travelled: from scan [0-9]* ([0-9.]* s into the log), [01] scans within; odometry after it 1.[45][0-9]* m and 0.0 deg off" \
  "$work/jump.txt" || fail "planted line: $(cat "$work/jump.txt")"
grep -q "^fault: 2[0-9]* scans, [0-9]* ODOM records; wrote $work/jump.clf" "$work/jump.txt" || fail "summary: $(cat "$work/jump.txt")"
grep -q "^# planted: jump at 20 m" "$work/jump.clf" || fail "the log's header does not name the fault"
[[ ! -e "$work/jump.clf.partial" ]] || fail "a partial file is left"
cmp -s <(readings "$log") <(readings "$work/jump.clf") || fail "readings changed"
cmp -s <(stamps "$log") <(stamps "$work/jump.clf") || fail "timestamps changed"
[[ $(grep -c '^FLASER ' "$log") == $(grep -c '^FLASER ' "$work/jump.clf") ]] || fail "scan count changed"
[[ $(grep -c '^ODOM ' "$log") == $(grep -c '^ODOM ' "$work/jump.clf") ]] || fail "ODOM count changed"
first=$(sed -n 's/.*from scan \([0-9]*\) .*/\1/p' "$work/jump.txt")
cmp -s <(poses "$log" | head -n "$first") <(poses "$work/jump.clf" | head -n "$first") || fail "poses before the stretch changed"
paste -d' ' <(poses "$log") <(poses "$work/jump.clf") | awk -v first="$first" '
  NR > first + 5 { d = sqrt(($7 - $1)^2 + ($8 - $2)^2); if (d < 1.45 || d > 1.55) bad++ }
  END { exit bad > 0 }' || fail "poses after the stretch are not 1.5 m off"
# A jump undone by the opposite jump gives the log's poses back (to the 9 decimals written).
"$bin" fault "$log" --fault jump,20,0.1,1 --fault jump,20,0.1,-1 --out "$work/undone.clf" --quiet > /dev/null ||
  fail "two --fault"
cmp -s <(poses "$log") <(poses "$work/undone.clf") || fail "a jump and its opposite changed the poses"
cmp -s <(odom "$log") <(odom "$work/undone.clf") || fail "a jump and its opposite changed the ODOM records"

# 2. The faulted log breaks slam_karto's front end where the jump is, as the office-jump world
#    does, and the log's relations still measure the error: above the untouched log's.
"$bin" run "$work/jump.clf" --relations "$relations" --out "$work/run_jump" --quiet > "$work/run_jump.txt" ||
  fail "run on the faulted log"
grep -q "^front end: 1 stretch where sequential matching lost its place (scans $first-" "$work/run_jump.txt" ||
  fail "no break found at scan $first: $(cat "$work/run_jump.txt")"
"$bin" run "$log" --relations "$relations" --out "$work/run_plain" --quiet > "$work/run_plain.txt" || fail "run on the log"
error() { sed -n 's/.*, error \([0-9.]*\) +- .*/\1/p' "$1"; }
awk -v broken="$(error "$work/run_jump.txt")" -v plain="$(error "$work/run_plain.txt")" \
  'BEGIN { exit !(broken > 2 * plain) }' || fail "errors: faulted $(error "$work/run_jump.txt"), untouched $(error "$work/run_plain.txt")"

# 3. A ROS bag: scans become ROBOTLASER1 with the bag's stamps, poses follow in time order.
"$bin" fault "$fixtures/office_zstd.mcap" --fault reverse,30,2 --out "$work/bag.clf" --quiet > "$work/bag.txt" ||
  fail "fault on a bag: $(cat "$work/bag.txt")"
grep -q "robot poses, time order)" "$work/bag.txt" || fail "bag: not in time order: $(cat "$work/bag.txt")"
grep -q "^fault: 655 scans, 328 ODOM records; wrote" "$work/bag.txt" || fail "bag summary: $(cat "$work/bag.txt")"
grep -q "^planted reverse at 30 m over 2 m: travel reported backwards: .* odometry after it 4.0[0-9]* m" "$work/bag.txt" ||
  fail "bag: a 2 m reverse does not move the odometry 4 m: $(cat "$work/bag.txt")"
"$bin" convert "$fixtures/office_zstd.mcap" --out "$work/converted.clf" --quiet > /dev/null || fail "convert"
rl_stamps() { awk '$1 == "ROBOTLASER1" { n = $9; printf "%.6f\n", $(n + 22) }' "$1"; }
cmp -s <(rl_stamps "$work/converted.clf") <(rl_stamps "$work/bag.clf") || fail "bag: stamps differ from convert's"
"$bin" run "$work/bag.clf" --out "$work/run_bag" --quiet > /dev/null || fail "run on the faulted bag's log"

# 4. Bad input: one line on stderr, exit 2, nothing written.
expect_error() {  # PATTERN ARGS...
  local pattern=$1; shift
  "$bin" fault "$@" > "$work/out.txt" 2> "$work/err.txt"; local rc=$?
  [[ $rc -eq 2 ]] || fail "fault $*: exit $rc, expected 2"
  [[ $(wc -l < "$work/err.txt") -eq 1 ]] || fail "fault $*: not one line: $(cat "$work/err.txt")"
  grep -q -- "^slamtune: error: .*$pattern" "$work/err.txt" || fail "fault $*: '$(cat "$work/err.txt")' lacks '$pattern'"
}
expect_error "--fault: required" "$log" --out "$work/x.clf"
expect_error "unknown kind 'slip'" "$log" --fault slip,1,1,1 --out "$work/x.clf"
expect_error "reverse takes 3 fields, got 4" "$log" --fault reverse,1,1,1 --out "$work/x.clf"
expect_error "'abc' is not a number" "$log" --fault jump,abc,1,1 --out "$work/x.clf"
expect_error "length_m = 0: must be finite and > 0" "$log" --fault spin,10,0,30 --out "$work/x.clf"
expect_error "office.clf: fault 2 (reverse at 5000 m over 3 m: travel reported backwards): its stretch ends at 5003 m, beyond the log's odometric travel of [0-9.]* m" \
  "$log" --fault jump,20,0.1,1 --fault reverse,5000,3 --out "$work/x.clf"
expect_error "the folder $work/missing does not exist" "$log" --fault jump,20,0.1,1 --out "$work/missing/x.clf"
expect_error "--out is a folder" "$log" --fault jump,20,0.1,1 --out "$work"
expect_error "no-such.clf" "$work/no-such.clf" --fault jump,20,0.1,1 --out "$work/x.clf"
[[ ! -e "$work/x.clf" && ! -e "$work/x.clf.partial" ]] || fail "a refused command wrote its output"

cli_test_end
