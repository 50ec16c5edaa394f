#!/usr/bin/env bash
# Damaged recordings on the command line: what each command does with data it cannot use, and
# that it always says so. The bags are written here by tests/ros1_bag.py (a drive through a
# room) with one fault each.
# Usage: damaged_recording_cli_test.sh SLAMTUNE_BINARY [DATASETS_DIR]. Exit 0 pass, 1 fail, 77 skip.
set -u
source "$(dirname "$0")/lib.sh"
cli_test_begin damaged_recording_cli_test "$@" -- python3

# bag NAME PYTHON [DRIVE_ARGS]: writes $work/NAME.bag from a Drive(DRIVE_ARGS) `b` changed by PYTHON.
bag() {
  PYTHONPATH="$tests_dir" python3 - "$work/$1.bag" <<EOF || fail "could not write $1.bag"
import math, sys
import ros1_bag
b = ros1_bag.Drive(${3:-})
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

# 2. Scans not used are said on stderr with --quiet too, and counted by kind under
# `scans_not_used` in run.json, results.json and check --json, and in the report: here 11 scans
# whose tf (odom -> base_link) is NaN for a second.
bag tfnan '
for k, (conn, t, payload) in enumerate(b.messages):
    if b.connections[conn][0] == "/tf" and b.start_ns + 4e9 <= t <= b.start_ns + 5e9:
        b.messages[k] = (conn, t, ros1_bag.tf_message([("odom", "base_link", t, (float("nan"), 4.0, 0.0), (0, 0, 0, 1))]))'
notused="not used: 11 scans without odometry at their stamp (21 tf transforms refused: NaN, inf or a bad rotation, or a bad frame id) (first: scan 40 at 104.025000 s: odom -> base_link at 104.025000 s: no sample for 1.100 s around it (gap 103.950000 s .. 105.050000 s))"
count() {  # FILE.json PATH...: the value at that path
  python3 -c 'import json, sys
v = json.load(open(sys.argv[1]))
for k in sys.argv[2:]: v = v[k]
print(json.dumps(v))' "$@"
}
"$bin" run "$work/tfnan.bag" --out "$work/run_tfnan" --quiet >/dev/null 2>"$work/run_tfnan.err" || fail "run on tfnan.bag failed"
[[ "$(cat "$work/run_tfnan.err")" == "$notused" ]] || fail "run --quiet: stderr '$(cat "$work/run_tfnan.err")'"
[[ $(count "$work/run_tfnan/run.json" scans_not_used no_odometry count) == 11 ]] || fail "run.json: no_odometry count"
[[ $(count "$work/run_tfnan/run.json" scans_not_used not_moved data_loss) == false ]] || fail "run.json: not_moved"
for kind in no_odometry malformed cut_off wrong_reading_count filtered_by_node not_moved; do
  count "$work/run_tfnan/run.json" scans_not_used "$kind" count >/dev/null 2>&1 || fail "run.json lacks scans_not_used.$kind"
done
"$bin" optimize "$work/tfnan.bag" --out "$work/opt_tfnan" --quiet --population 4 --generations 1 --jobs 2 >/dev/null \
  2>"$work/opt_tfnan.err" || fail "optimize on tfnan.bag failed: $(cat "$work/opt_tfnan.err")"
grep -qxF "$notused" "$work/opt_tfnan.err" || fail "optimize --quiet: stderr '$(cat "$work/opt_tfnan.err")'"
[[ $(count "$work/opt_tfnan/results.json" scans_not_used no_odometry count) == 11 ]] || fail "results.json: count"
grep -q '<p class="warning">Not used: 11 scans without odometry' "$work/opt_tfnan/report.html" ||
  fail "the report does not warn of the scans not used"
"$bin" check "$work/tfnan.bag" --json > "$work/check_tfnan.json" || fail "check --json on tfnan.bag"
[[ $(count "$work/check_tfnan.json" scans_not_used no_odometry count) == 11 ]] || fail "check --json: count"
# A recording cut off after its first chunk (no end marker): read up to there, and said.
python3 - "$tests_dir/fixtures/recordings/office_zstd.mcap" "$work/first_chunk.mcap" <<'EOF2'
import struct, sys
data = open(sys.argv[1], "rb").read()
pos = 8
while True:
    opcode, length = data[pos], struct.unpack_from("<Q", data, pos + 1)[0]
    pos += 9 + length
    if opcode == 0x06:  # the first Chunk record
        break
open(sys.argv[2], "wb").write(data[:pos])
EOF2
"$bin" run "$work/first_chunk.mcap" --out "$work/run_first_chunk" --quiet >/dev/null 2>"$work/first_chunk.err" ||
  fail "run on a recording cut after its first chunk: $(cat "$work/first_chunk.err")"
grep -q "^not used: whatever was recorded after the file's end: it ends without its end marker" "$work/first_chunk.err" ||
  fail "run --quiet does not say the recording was cut off: '$(cat "$work/first_chunk.err")'"
[[ $(count "$work/run_first_chunk/run.json" scans_not_used cut_off count) == null ]] || fail "run.json: cut_off count"

# 3. Impossible LaserScan limits. range_max NaN (or 0): read with no upper limit, and said with
# the first scan, the count and the rule by info and check.
rule="read with no upper limit: inf and NaN readings are no-returns, every other reading above range_min is a range, and the range threshold is the node's own (--no-return M sets a limit)"
for v in 'float("nan")' 0.0; do
  bag badmax '' "range_max=$v"
  "$bin" info "$work/badmax.bag" > "$work/info_badmax.txt" 2>&1 || fail "info on range_max $v: $(cat "$work/info_badmax.txt")"
  grep -qF "LaserScan range_max is NaN, infinite, 0 or negative in 100 of 100 scans (first: scan 0 at 100.025000 s: range_max $([[ $v == 0.0 ]] && echo 0 || echo nan)): $rule" \
    "$work/info_badmax.txt" || fail "info does not say range_max $v is unusable: $(cat "$work/info_badmax.txt")"
  grep -q "^no-return value  *inf m (rule: none: LaserScan range_max is NaN, infinite, 0 or negative)" "$work/info_badmax.txt" ||
    fail "info's no-return rule for range_max $v: $(grep no-return "$work/info_badmax.txt")"
  "$bin" check "$work/badmax.bag" > "$work/check_badmax.txt" || fail "check on range_max $v exited $?"
  grep -qF "problem bad_range_max: LaserScan range_max is NaN, infinite, 0 or negative in 100 of 100 scans" \
    "$work/check_badmax.txt" || fail "check does not report range_max $v: $(grep -E '^(problem|verdict)' "$work/check_badmax.txt")"
done
# range_min above range_max: no reading can be a range; the scans are malformed (an error that
# names --lenient; with it, skipped and counted).
bag minmax '' 'range_min=40.0'
expect_line "slamtune: error: $work/minmax.bag: byte 4867: /scan: LaserScan range_min 40 m exceeds range_max 30 m: no reading can be a range (--lenient skips such scans and counts them)" \
  "$bin" info "$work/minmax.bag"

# 4. Not one reading a range (range_max 0.5 m in a room of 12 x 8 m: every reading a no-return):
# run and optimize refuse it in one line; check reports it.
bag noranges '' 'range_min=0.0, range_max=0.5'
noranges="slamtune: error: $work/noranges.bag: not one of the 18100 readings of the 100 scans is a range (each is inf, NaN, negative, at or above range_max 0.5 m or at or below range_min): nothing to map"
expect_line "$noranges" "$bin" run "$work/noranges.bag" --out "$work/run_noranges" --quiet
expect_line "$noranges" "$bin" optimize "$work/noranges.bag" --out "$work/opt_noranges" --quiet
[[ ! -e "$work/opt_noranges/run.sqlite" ]] || fail "optimize started on a log without a single range"
"$bin" check "$work/noranges.bag" > "$work/check_noranges.txt" || fail "check on noranges.bag exited $?"
grep -q "^problem no_valid_reading: not one of the 18100 readings of the 100 scans is a range" "$work/check_noranges.txt" ||
  fail "check does not report the log without a range: $(grep -E '^(problem|verdict)' "$work/check_noranges.txt")"

# 5. A rosbag2 folder whose metadata.yaml lists the same split twice: refused, naming both entries.
cp -r "$tests_dir/fixtures/recordings/office_db3" "$work/twice"
sed -i 's/^    - office_db3_0.db3$/    - office_db3_0.db3\n    - office_db3_0.db3/' "$work/twice/metadata.yaml"
expect_line "slamtune: error: $work/twice/metadata.yaml: relative_file_paths lists $work/twice/office_db3_0.db3 twice (entries 1 and 2, \"office_db3_0.db3\" and \"office_db3_0.db3\"): refused, as reading it twice would give every message twice; remove the repeated entry" \
  "$bin" info "$work/twice"

cli_test_end
