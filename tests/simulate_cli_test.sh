#!/usr/bin/env bash
# End-to-end test of `slamtune simulate`: --list, a simulated run, determinism, bad input.
# Usage: simulate_cli_test.sh SLAMTUNE_BINARY [DATASETS_DIR]   (datasets are not needed)
set -u
source "$(dirname "$0")/lib.sh"
cli_test_begin simulate_cli_test "$@"

# --list names the worlds, default first, and needs no --out.
"$bin" simulate --list > "$work/list.txt" || fail "--list exited non-zero"
head -n 1 "$work/list.txt" | grep -q '^office ' || fail "--list does not start with office"
for world in office hall corridor office-slip office-jump corridor-long building building-broken; do
  grep -q "^$world " "$work/list.txt" || fail "--list lacks $world"
done

# A default run writes the three files.
"$bin" simulate --seed 3 --out "$work/a" > "$work/a.txt" || fail "simulate exited non-zero"
for file in office.clf office.relations office.truth.txt; do
  [[ -s "$work/a/$file" ]] || fail "missing or empty $file"
done
scans=$(grep -c '^FLASER ' "$work/a/office.clf")
(( scans >= 1000 && scans <= 3000 )) || fail "office has $scans scans, expected 1000..3000"
bad_counts=$(awk '$1 == "FLASER" && $2 != 181' "$work/a/office.clf" | wc -l)
(( bad_counts == 0 )) || fail "$bad_counts FLASER lines without 181 readings"
grep -q '^PARAM laser_front_laser_max_range 30 ' "$work/a/office.clf" || fail "no max-range PARAM"
truth_lines=$(grep -vc '^#' "$work/a/office.truth.txt")
(( truth_lines == scans )) || fail "truth has $truth_lines poses for $scans scans"
grep -q 'scans' "$work/a.txt" || fail "no summary printed"

# Same seed: byte-identical files; another seed: a different log.
"$bin" simulate --world office --seed 3 --out "$work/b" > /dev/null
for file in office.clf office.relations office.truth.txt; do
  cmp -s "$work/a/$file" "$work/b/$file" || fail "same seed gave a different $file"
done
"$bin" simulate --seed 4 --out "$work/c" > /dev/null
if cmp -s "$work/a/office.clf" "$work/c/office.clf"; then fail "seeds 3 and 4 gave the same log"; fi

# Other worlds and laser options.
"$bin" simulate --world hall --beams 361 --max-range 25 --out "$work/h" > /dev/null || fail "hall with 361 beams"
awk '$1 == "FLASER" && $2 != 361 {exit 1}' "$work/h/hall.clf" || fail "hall lines without 361 readings"

# Planted faults: a fault world names its fault in the log header and summary; --fault adds
# one; a jump and its opposite give back the plain world's log byte for byte.
"$bin" simulate --world office-jump --seed 3 --out "$work/j" > "$work/j.txt" || fail "office-jump"
grep -q '^# planted odometry fault (true distance travelled): jump at 20 m over 0.1 m' "$work/j/office-jump.clf" ||
  fail "office-jump log does not name its fault"
grep -q 'planted odometry fault: jump' "$work/j.txt" || fail "office-jump summary does not name its fault"
if grep -q 'planted' "$work/a/office.clf"; then fail "the plain office log names a fault"; fi
"$bin" simulate --world office-jump --seed 3 --fault jump,20,0.1,-1 --out "$work/u" > /dev/null || fail "--fault"
cmp -s <(grep -v '^#' "$work/u/office-jump.clf") <(grep -v '^#' "$work/a/office.clf") ||
  fail "a jump and its opposite did not give the plain office log"
"$bin" simulate --seed 3 --fault spin,45,0.1,60 --fault reverse,100,1 --out "$work/s" > "$work/s.txt" || fail "two --fault"
[[ $(grep -c '^# planted odometry fault' "$work/s/office.clf") == 2 ]] || fail "two faults not both in the header"
# --without-world-faults: the fault world's healthy twin is the plain world's log.
"$bin" simulate --world office-jump --seed 3 --without-world-faults --out "$work/t" > "$work/t.txt" ||
  fail "--without-world-faults"
cmp -s <(grep -v '^#' "$work/t/office-jump.clf") <(grep -v '^#' "$work/a/office.clf") ||
  fail "office-jump without its fault is not the plain office log"
if grep -q 'planted' "$work/t.txt"; then fail "--without-world-faults still names a fault"; fi
# The large building: at least 15 minutes (4000 scans at 5 Hz); its broken variant names its two
# faults and, without them, is the building's log.
"$bin" simulate --world building --out "$work/b" > "$work/b.txt" || fail "building"
building_scans=$(grep -c '^FLASER ' "$work/b/building.clf")
(( building_scans >= 4000 && building_scans <= 4800 )) || fail "building has $building_scans scans, expected 4000..4800"
"$bin" simulate --world building-broken --out "$work/bb" > /dev/null || fail "building-broken"
[[ $(grep -c '^# planted odometry fault' "$work/bb/building-broken.clf") == 2 ]] || fail "building-broken: not two faults"
"$bin" simulate --world building-broken --without-world-faults --out "$work/bt" > /dev/null ||
  fail "building-broken --without-world-faults"
cmp -s <(grep -v '^#' "$work/bt/building-broken.clf") <(grep -v '^#' "$work/b/building.clf") ||
  fail "building-broken without its faults is not the building's log"
cmp -s "$work/bt/building-broken.relations" "$work/b/building.relations" || fail "building-broken: other relations"

# Bad input: non-zero exit, nothing claimed.
expect_failure() {
  if "$bin" simulate "$@" > "$work/out.txt" 2> "$work/err.txt"; then fail "accepted: simulate $*"; fi
}
expect_failure --bogus-option --out "$work/x"
expect_failure --world moon --out "$work/x"
grep -q "moon" "$work/err.txt" || fail "unknown world not named in the error"
expect_failure --beams 1 --out "$work/x"
grep -q "beams" "$work/err.txt" || fail "bad beam count not named in the error"
expect_failure --speed -1 --out "$work/x"
expect_failure --seed -1 --out "$work/x"
expect_failure --fault slip,1,1,1 --out "$work/x"
grep -q "unknown kind 'slip'" "$work/err.txt" || fail "unknown fault kind not named in the error"
expect_failure --fault jump,1,0,1 --out "$work/x"
grep -q "length_m = 0" "$work/err.txt" || fail "bad fault length not named in the error"
expect_failure --seed 1
grep -q -- "--out" "$work/err.txt" || fail "missing --out not explained"
[[ ! -e "$work/x" ]] || fail "a failed run created its output folder"

cli_test_end "office: $scans scans"
