#!/usr/bin/env bash
# Damaged recordings on the command line: what each command does with data it cannot use, and
# that it always says so. The bags are written here by tests/ros1_bag.py (a drive through a
# room) with one fault each.
# Usage: damaged_recording_cli_test.sh SLAMTUNE_BINARY [DATASETS_DIR]. Exit 0 pass, 1 fail, 77 skip.
set -u
bin=${1:?usage: damaged_recording_cli_test.sh SLAMTUNE_BINARY}
[[ -x "$bin" ]] || { echo "SKIP: $bin is not an executable" >&2; exit 77; }
command -v python3 >/dev/null || { echo "SKIP: python3 is needed to write the bags" >&2; exit 77; }
tests="$(cd "$(dirname "$0")" && pwd)"
work=$(mktemp -d "${TMPDIR:-/tmp}/slamtune_damaged.XXXXXX")
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }

# bag NAME PYTHON: writes $work/NAME.bag from a Drive `b` changed by PYTHON.
bag() {
  PYTHONPATH="$tests" python3 - "$work/$1.bag" <<EOF || fail "could not write $1.bag"
import math, sys
import ros1_bag
b = ros1_bag.Drive()
b.static_tf("base_link", "laser", x=0.1)
$2
b.write(sys.argv[1])
EOF
}
# expect_line EXPECTED CMD...: exit 2 and exactly the one line EXPECTED on stderr.
expect_line() {
  local expected=$1; shift
  local err; err=$("$@" 2>&1 >/dev/null); local rc=$?
  [[ $rc -eq 2 ]] || fail "exit $rc (want 2): $*"
  [[ "$err" == "$expected" ]] || fail "$*
  got:  $err
  want: $expected"
}

bag good ''
"$bin" run "$work/good.bag" --out "$work/run_good" --quiet >/dev/null 2>"$work/good.err" ||
  fail "run on the good bag: $(cat "$work/good.err")"
[[ ! -s "$work/good.err" ]] || fail "run --quiet on a sound bag printed: $(cat "$work/good.err")"

# 1. A loop in the tf tree (laser -> odom closes odom -> base_link -> laser): refused naming it
# by every command that would compose a pose through it; check reports it as its problem.
bag loop 'b.static_tf("laser", "odom")'
loop="slamtune: error: $work/loop.bag: the tf tree has a loop, odom -> base_link -> laser -> odom: odom is its own ancestor (odom -> base_link (dynamic), base_link -> laser (static), laser -> odom (static)), so the odometry odom -> base_link cannot be found (tf2 refuses every lookup through a loop); one of these transforms was published the wrong way round"
expect_line "$loop" "$bin" info "$work/loop.bag"
expect_line "$loop" "$bin" run "$work/loop.bag" --out "$work/run_loop" --quiet
expect_line "$loop" "$bin" optimize "$work/loop.bag" --out "$work/opt_loop" --quiet
"$bin" check "$work/loop.bag" > "$work/check_loop.txt"; rc=$?
[[ $rc -eq 0 ]] || fail "check on a tf loop exited $rc"
grep -q "^problem tf_loop: the tf tree has a loop, odom -> base_link -> laser -> odom" "$work/check_loop.txt" ||
  fail "check does not name the loop: $(cat "$work/check_loop.txt")"
grep -q "^verdict: 1 problem: tf_loop" "$work/check_loop.txt" || fail "check verdict: $(tail -1 "$work/check_loop.txt")"

if (( failures > 0 )); then echo "$failures failure(s)" >&2; exit 1; fi
echo "damaged recordings: all checks passed"
