#!/usr/bin/env bash
# End-to-end test of bad user input: every case must exit 2 with exactly one line on stderr,
# `slamtune: error: FILE[:LINE]: what`, and never crash, print library noise, write garbage or
# drop data without a count. Covers laser geometry (degrees, fov), RAWLASER scans without
# odometry and byte-order marks, ambiguous trajectories, image errors, --out paths,
# directories given as files and a full disk.
# Usage: bad_input_cli_test.sh SLAMTUNE_BINARY DATASETS_DIR   (datasets are not needed)
# Exit 0 = pass, 1 = fail, 77 = skip (binary missing).
set -u
source "$(dirname "$0")/lib.sh"
cli_test_begin bad_input_cli_test "$@"

# expect_error LINE ARGS...: `slamtune ARGS` exits 2 and prints exactly LINE on stderr.
expect_error() {
  local expected=$1
  shift
  "$bin" "$@" >"$work/out.txt" 2>"$work/err.txt"
  local code=$?
  [[ $code -eq 2 ]] || fail "slamtune $*: exit $code, expected 2; stderr: $(cat "$work/err.txt")"
  [[ "$(cat "$work/err.txt")" == "$expected" ]] ||
    fail "slamtune $*: stderr is not the one line
  expected: $expected
  got:      $(cat "$work/err.txt")"
}
# expect_line LINE FILE: FILE holds LINE exactly.
expect_line() { grep -qxF -- "$1" "$2" || fail "no line '$1' in $2: $(cat "$2")"; }

# A command line that cannot be read is bad input like any other: one line, exit 2.
expect_error "slamtune: error: Could not convert: --population = abc (see slamtune --help, or slamtune COMMAND --help)" \
  optimize --population abc --out "$work/never"
expect_error "slamtune: error: --out is required (see slamtune --help, or slamtune COMMAND --help)" run
expect_error "slamtune: error: The following argument was not expected: --no-such-flag (see slamtune --help, or slamtune COMMAND --help)" \
  evaluate map.yaml --no-such-flag

# CARMEN records written here: a FLASER of 180 readings, a ROBOTLASER1/RAWLASER1 of N readings.
flaser() {  # T X
  local r
  r=$(printf ' 2.5%.0s' $(seq 180))
  printf 'FLASER 180%s %s 0 0 %s 0 0 %s h %s\n' "$r" "$2" "$2" "$1" "$1"
}
robotlaser() {  # START FOV RES N T
  local r
  r=$(printf ' 2.5%.0s' $(seq "$4"))
  printf 'ROBOTLASER1 0 %s %s %s 30 0.01 0 %s%s 0 0 0 0 0 0 0 0 0 0 0 0 %s h %s\n' "$1" "$2" "$3" "$4" "$r" "$5" "$5"
}
rawlaser() {  # T
  printf 'RAWLASER1 0 -1.570796 3.141593 0.017453 30 0.01 0 181%s 0 %s h %s\n' "$(printf ' 2.5%.0s' $(seq 181))" "$1" "$1"
}

# A small simulated corridor log for the commands that need a real one.
simulate_world "$work/sim" corridor --seed 3
log="$work/sim/corridor.clf"
fast=(--max-scans 80 --set minimum_travel_distance=0.4 --quiet)

# 4. Laser geometry that no laser can mean.
{ echo "# degrees"; robotlaser -90 180 1 181 1.0; } >"$work/degrees.clf"
expect_error "slamtune: error: $work/degrees.clf:2: ROBOTLASER1 start_angle (field 3) -90 is beyond +-2pi: angles must be radians (written in degrees?)" \
  info "$work/degrees.clf"
robotlaser -1.570796 100 0.017453 181 1.0 >"$work/fov5729.clf"
expect_error "slamtune: error: $work/fov5729.clf:1: ROBOTLASER1 fov (field 4) 100 (5730 deg) is more than a full turn: angles must be radians (written in degrees?)" \
  run "$work/fov5729.clf" --out "$work/r4" --quiet
{ robotlaser -1.570796 3.141593 0.017453 181 1.0; robotlaser -1.570796 3.141593 0.008727 181 2.0; } >"$work/fovsteps.clf"
expect_error "slamtune: error: $work/fovsteps.clf:2: ROBOTLASER1 fov (field 4) 3.141593 rad contradicts 181 readings at angular_res 0.008727 rad (they span 1.570860 rad)" \
  info "$work/fovsteps.clf"

# 5. RAWLASER scans after the last ODOM are counted, not clamped; a byte-order mark hides nothing.
{
  printf 'ODOM 0 0 0 0 0 0 1.0 h 1\n'
  rawlaser 1.5
  printf 'ODOM 1 0 0 0 0 0 2.0 h 2\n'
  for ((k = 3; k < 300; k++)); do rawlaser "$k"; done
} >"$work/raw.clf"
"$bin" info "$work/raw.clf" >"$work/raw.txt" 2>&1 || fail "info raw.clf failed: $(cat "$work/raw.txt")"
expect_line "not used                 297 RAWLASER scans outside the time span of the ODOM records, no pose to interpolate (first: line 4 at 3 s; ODOM 1 .. 2 s)" "$work/raw.txt"
expect_line "laser scans              1" "$work/raw.txt"
{ printf '\xef\xbb\xbf'; flaser 1.0 0; flaser 2.0 0.5; } >"$work/bom.clf"
"$bin" info "$work/bom.clf" >"$work/bom.txt" 2>&1 || fail "info bom.clf failed: $(cat "$work/bom.txt")"
expect_line "laser scans              2" "$work/bom.txt"
printf '\xef\xbb\xbf1 0 0 0\n2 0.5 0 0\n' >"$work/bom_traj.txt"
printf '\xef\xbb\xbf1 2 0.5 0 0 0 0 0\n' >"$work/bom.relations"
"$bin" gt-error "$work/bom_traj.txt" "$work/bom.relations" >"$work/gt.txt" 2>&1 || fail "gt-error with BOMs failed: $(cat "$work/gt.txt")"
grep -q "^relations used  *1$" "$work/gt.txt" || fail "gt-error with BOMs did not use the relation: $(cat "$work/gt.txt")"
printf '\xef\xbb\xbfminimum_travel_distance: 0.4\n' >"$work/bom_params.yaml"
"$bin" run "$log" --out "$work/r5" --params "$work/bom_params.yaml" "${fast[@]}" >/dev/null 2>"$work/r5.err" ||
  fail "run --params with a BOM failed: $(cat "$work/r5.err")"
grep -q '"minimum_travel_distance": 0.4' "$work/r5/run.json" || fail "the BOM params file was not applied"

# 7. Two different poses with one timestamp.
printf '# t x y theta\n1 0 0 0\n2 1 0 0\n2 1 0 0\n1 0.5 0 0\n' >"$work/dup.txt"
expect_error "slamtune: error: $work/dup.txt:5: second pose for timestamp 1 (line 2 has 0 0 0, this line 0.5 0 0): a trajectory needs one pose per timestamp" \
  gt-error "$work/dup.txt" "$work/bom.relations"
printf '5 0 0 0\n5.000000 0 0.25 0\n' >"$work/dup2.txt"
expect_error "slamtune: error: $work/dup2.txt:2: second pose for timestamp 5.000000 (line 1 has 0 0 0, this line 0 0.25 0): a trajectory needs one pose per timestamp" \
  render "$log" --poses "$work/dup2.txt" --out "$work/r7"

# 8. Image errors: one line, no OpenCV or libpng text.
printf 'P5\n40 30\n255\n' >"$work/short.pgm"
head -c 500 /dev/zero >>"$work/short.pgm"
expect_error "slamtune: error: $work/short.pgm: truncated: the header declares 40 x 30 = 1200 pixels, the file holds 500" \
  evaluate "$work/short.pgm"
printf '\x89PNG\r\n\x1a\n\x00\x00\x00\x0dIHDR\x00\xff\xff\xff\x00\xff\xff\xff\x08\x00\x00\x00\x00\x00\x00\x00\x00' >"$work/huge.png"
expect_error "slamtune: error: $work/huge.png: declares 16777215 x 16777215 pixels, more than the 1073741824 an image may have" \
  evaluate "$work/huge.png"
"$bin" render "$log" --poses odometry --out "$work/r8" >/dev/null 2>&1 || fail "render for a PNG failed"
head -c 300 "$work/r8/map.png" >"$work/cut.png"
"$bin" evaluate "$work/cut.png" >/dev/null 2>"$work/err.txt"
[[ $? -eq 2 && $(wc -l <"$work/err.txt") -eq 1 ]] || fail "evaluate cut.png: not exit 2 with one line: $(cat "$work/err.txt")"
grep -q "^slamtune: error: $work/cut.png: truncated: the header declares [0-9]* x [0-9]* pixels" "$work/err.txt" ||
  fail "evaluate cut.png: $(cat "$work/err.txt")"

# 9. --out that cannot be a folder.
echo x >"$work/a_file"
expect_error "slamtune: error: $work/a_file: cannot create output folder: is a file" run "$log" --out "$work/a_file" --quiet
expect_error "slamtune: error: --out: empty folder name; give the folder to write to" run "$log" --out '' --quiet
"$bin" run "$log" --out /proc/slamtune_out --quiet >/dev/null 2>"$work/err.txt"
[[ $? -eq 2 && $(wc -l <"$work/err.txt") -eq 1 ]] || fail "run --out /proc/...: not exit 2 with one line: $(cat "$work/err.txt")"
grep -q "^slamtune: error: /proc/slamtune_out: cannot create output folder: " "$work/err.txt" ||
  fail "run --out /proc/...: $(cat "$work/err.txt")"

# 10. A directory given as a file.
mkdir -p "$work/adir"
expect_error "slamtune: error: $work/adir: cannot open: is a directory" run "$log" --out "$work/r10" --params "$work/adir" --quiet
expect_error "slamtune: error: $work/adir: cannot open: is a directory" render "$log" --poses odometry --out "$work/r10" --params "$work/adir"
expect_error "slamtune: error: $work/adir: cannot open: is a directory" gt-error "$work/adir" "$work/bom.relations"

# 12. A full disk (the file size limit, with SIGXFSZ ignored so writes fail with EFBIG): the map
# that cannot be written is named and nothing half-written is left under its name.
(trap '' XFSZ; ulimit -f 8; "$bin" run "$log" --out "$work/r12" "${fast[@]}") >/dev/null 2>"$work/err.txt"
code=$?
[[ $code -eq 2 ]] || fail "run on a full disk: exit $code, expected 2: $(cat "$work/err.txt")"
[[ "$(cat "$work/err.txt")" == "slamtune: error: $work/r12/map.pgm: cannot write (File too large)" ]] ||
  fail "run on a full disk: $(cat "$work/err.txt")"
[[ ! -e "$work/r12/map.pgm" && ! -e "$work/r12/map.pgm.partial" && ! -e "$work/r12/map.yaml" ]] ||
  fail "run on a full disk left $(ls "$work/r12")"
(trap '' XFSZ; ulimit -f 8; "$bin" render "$log" --poses odometry --out "$work/r12b") >/dev/null 2>"$work/err.txt"
code=$?
[[ $code -eq 2 ]] || fail "render on a full disk: exit $code, expected 2"
[[ "$(tail -n 1 "$work/err.txt")" == "slamtune: error: $work/r12b/map.pgm: cannot write (File too large)" ]] ||
  fail "render on a full disk: $(cat "$work/err.txt")"
[[ -z "$(ls "$work/r12b")" ]] || fail "render on a full disk left $(ls "$work/r12b")"

cli_test_end
