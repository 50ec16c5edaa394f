#!/usr/bin/env bash
# End-to-end test of `slamtune info` (and `slamtune gt-error`): args are the slamtune binary
# and the shared datasets folder. Malformed inputs are always checked; the dataset checks run
# when the folder holds intel.clf.gz, otherwise the script exits 77 (skip) after the rest passed.
set -u
source "$(dirname "$0")/lib.sh"
cli_test_begin info_cli_test "$@"

# run EXPECTED_RC ARGS...: runs slamtune, keeps stdout/stderr in $work/out, $work/err.
run() {
  local expected=$1; shift
  "$bin" "$@" >"$work/out" 2>"$work/err"
  local rc=$?
  if [ "$rc" -ne "$expected" ]; then
    fail "slamtune $* exited $rc, expected $expected; stderr: $(head -c 400 "$work/err")"
  fi
}
expect_in() {  # expect_in FILE TEXT
  grep -qF -- "$2" "$1" || fail "missing '$2' in $(basename "$1"): $(head -c 400 "$1")"
}

# A small FLASER log: 3 scans of 180 readings; the second declares 180 but has 179.
flaser() {  # flaser COUNT VALUE TIME
  local line="FLASER 180" i
  for ((i = 0; i < $1; i++)); do line+=" $2"; done
  echo "$line 0 0 0 0 0 0 $3 nohost $3"
}
{ echo "# test log"; flaser 180 2.5 1.0; flaser 179 2.5 1.2; flaser 180 40 1.4; } >"$work/bad.clf"

run 2 info "$work/bad.clf"
expect_in "$work/err" "$work/bad.clf:3: FLASER declares 180 readings but has 179 numbers before the pose"

run 0 info --lenient "$work/bad.clf"
expect_in "$work/out" "laser scans              2"
expect_in "$work/out" "skipped (malformed)      1"

run 0 info --lenient --json "$work/bad.clf"
expect_in "$work/out" '"scans": 2'
expect_in "$work/out" '"skipped_records": 1'

# Truncated last line, truncated gzip, empty file, missing file, bad option value.
head -c 500 "$work/bad.clf" >"$work/cut.clf"
run 2 info "$work/cut.clf"
expect_in "$work/err" "cut.clf:2: truncated last line"
{ for t in 1 2 3 4 5 6 7 8 9; do flaser 180 1.$t $t; done; } | gzip -c >"$work/full.clf.gz"
head -c $(( $(wc -c <"$work/full.clf.gz") / 2 )) "$work/full.clf.gz" >"$work/trunc.clf.gz"
run 2 info "$work/trunc.clf.gz"
expect_in "$work/err" "truncated gzip stream"
run 0 info "$work/full.clf.gz"
expect_in "$work/out" "(gzip)"
expect_in "$work/out" "laser scans              9"
: >"$work/empty.clf"
run 2 info "$work/empty.clf"
expect_in "$work/err" "empty.clf: empty file"
run 2 info "$work/does-not-exist.clf"
expect_in "$work/err" "does-not-exist.clf: cannot open"
run 2 info --no-return -3 "$work/full.clf.gz"
expect_in "$work/err" "no_return_value = -3"

# gt-error on a hand-made trajectory and relations: one relation exact, one 0.5 m off.
printf '# t x y theta\n1 0 0 0\n2 1 0 0\n3 2 0.5 0\n' >"$work/traj.txt"
printf '1 2 1 0 0 0 0 0\n2 3 1 0 0 0 0 0\n1 9 1 0 0 0 0 0\n' >"$work/rel.txt"
run 0 gt-error --json "$work/traj.txt" "$work/rel.txt"
expect_in "$work/out" '"trans_mean_m": 0.25'
expect_in "$work/out" '"relations_used": 2'
expect_in "$work/out" '"relations_missing": 1'
run 2 gt-error "$work/rel.txt" "$work/traj.txt"
expect_in "$work/err" "rel.txt:1: expected 4 columns (timestamp x y theta), found 8"

if [ ! -f "$datasets/intel.clf.gz" ]; then
  [ "$failures" -eq 0 ] || cli_test_end
  echo "SKIP: $datasets/intel.clf.gz not found (malformed-input checks passed)"
  exit 77
fi

run 0 info "$datasets/intel.clf.gz"
expect_in "$work/out" "laser scans              13631"
expect_in "$work/out" "time backward steps      631"
run 0 info --json "$datasets/intel.clf.gz"
expect_in "$work/out" '"scans": 13631'
expect_in "$work/out" '"readings_per_scan": 180'
expect_in "$work/out" '"no_return_value": 81.83'
expect_in "$work/out" '"duration_s":'
expect_in "$work/out" '"record_counts":'
if [ -f "$datasets/mit-csail.clf.gz" ]; then
  run 0 info --json --max-scans 10 "$datasets/mit-csail.clf.gz"
  expect_in "$work/out" '"scans": 10'
  expect_in "$work/out" '"readings_per_scan": 361'
fi

cli_test_end
