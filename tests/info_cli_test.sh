#!/usr/bin/env bash
# End-to-end test of `slamtune info` (and `slamtune gt-error`): args are the slamtune binary
# and the shared datasets folder. Malformed inputs are always checked; the dataset checks run
# when the folder holds intel.clf.gz, otherwise the script exits 77 (skip) after the rest passed.
set -u
SLAMTUNE=${1:?usage: info_cli_test.sh SLAMTUNE_BINARY DATASETS_DIR}
DATASETS=${2:?usage: info_cli_test.sh SLAMTUNE_BINARY DATASETS_DIR}
if [ ! -x "$SLAMTUNE" ]; then
  echo "FAIL: slamtune binary not found or not executable: $SLAMTUNE"
  exit 1
fi
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
failures=0

fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# run EXPECTED_RC ARGS...: runs slamtune, keeps stdout/stderr in $TMP/out, $TMP/err.
run() {
  local expected=$1; shift
  "$SLAMTUNE" "$@" >"$TMP/out" 2>"$TMP/err"
  local rc=$?
  if [ "$rc" -ne "$expected" ]; then
    fail "slamtune $* exited $rc, expected $expected; stderr: $(head -c 400 "$TMP/err")"
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
{ echo "# test log"; flaser 180 2.5 1.0; flaser 179 2.5 1.2; flaser 180 40 1.4; } >"$TMP/bad.clf"

run 2 info "$TMP/bad.clf"
expect_in "$TMP/err" "$TMP/bad.clf:3: FLASER declares 180 readings but has 179 numbers before the pose"

run 0 info --lenient "$TMP/bad.clf"
expect_in "$TMP/out" "laser scans              2"
expect_in "$TMP/out" "skipped (malformed)      1"

run 0 info --lenient --json "$TMP/bad.clf"
expect_in "$TMP/out" '"scans": 2'
expect_in "$TMP/out" '"skipped_records": 1'

# Truncated last line, truncated gzip, empty file, missing file, bad option value.
head -c 500 "$TMP/bad.clf" >"$TMP/cut.clf"
run 2 info "$TMP/cut.clf"
expect_in "$TMP/err" "cut.clf:2: truncated last line"
{ for t in 1 2 3 4 5 6 7 8 9; do flaser 180 1.$t $t; done; } | gzip -c >"$TMP/full.clf.gz"
head -c $(( $(wc -c <"$TMP/full.clf.gz") / 2 )) "$TMP/full.clf.gz" >"$TMP/trunc.clf.gz"
run 2 info "$TMP/trunc.clf.gz"
expect_in "$TMP/err" "truncated gzip stream"
run 0 info "$TMP/full.clf.gz"
expect_in "$TMP/out" "(gzip)"
expect_in "$TMP/out" "laser scans              9"
: >"$TMP/empty.clf"
run 2 info "$TMP/empty.clf"
expect_in "$TMP/err" "empty.clf: empty file"
run 2 info "$TMP/does-not-exist.clf"
expect_in "$TMP/err" "does-not-exist.clf: cannot open"
run 2 info --no-return -3 "$TMP/full.clf.gz"
expect_in "$TMP/err" "no_return_value = -3"

# gt-error on a hand-made trajectory and relations: one relation exact, one 0.5 m off.
printf '# t x y theta\n1 0 0 0\n2 1 0 0\n3 2 0.5 0\n' >"$TMP/traj.txt"
printf '1 2 1 0 0 0 0 0\n2 3 1 0 0 0 0 0\n1 9 1 0 0 0 0 0\n' >"$TMP/rel.txt"
run 0 gt-error --json "$TMP/traj.txt" "$TMP/rel.txt"
expect_in "$TMP/out" '"trans_mean_m": 0.25'
expect_in "$TMP/out" '"relations_used": 2'
expect_in "$TMP/out" '"relations_missing": 1'
run 2 gt-error "$TMP/rel.txt" "$TMP/traj.txt"
expect_in "$TMP/err" "rel.txt:1: expected 4 columns (timestamp x y theta), found 8"

if [ ! -f "$DATASETS/intel.clf.gz" ]; then
  [ "$failures" -eq 0 ] || exit 1
  echo "SKIP: $DATASETS/intel.clf.gz not found (malformed-input checks passed)"
  exit 77
fi

run 0 info "$DATASETS/intel.clf.gz"
expect_in "$TMP/out" "laser scans              13631"
expect_in "$TMP/out" "time backward steps      631"
run 0 info --json "$DATASETS/intel.clf.gz"
expect_in "$TMP/out" '"scans": 13631'
expect_in "$TMP/out" '"readings_per_scan": 180'
expect_in "$TMP/out" '"no_return_value": 81.83'
expect_in "$TMP/out" '"duration_s":'
expect_in "$TMP/out" '"record_counts":'
if [ -f "$DATASETS/mit-csail.clf.gz" ]; then
  run 0 info --json --max-scans 10 "$DATASETS/mit-csail.clf.gz"
  expect_in "$TMP/out" '"scans": 10'
  expect_in "$TMP/out" '"readings_per_scan": 361'
fi

[ "$failures" -eq 0 ] || exit 1
echo "PASS"
