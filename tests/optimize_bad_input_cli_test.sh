#!/usr/bin/env bash
# Bad search spaces and parameter sets for `slamtune optimize`, each one line
# `slamtune: error: FILE:LINE: what` and exit 2 before any SLAM run; consistent parameter sets
# accepted whatever their order; runs that produce an empty map never recommended.
# Usage: optimize_bad_input_cli_test.sh SLAMTUNE_BINARY [DATASETS_DIR]. Exit 0 pass, 1 fail, 77 skip.
set -u
source "$(dirname "$0")/lib.sh"
cli_test_begin optimize_bad_input_cli_test "$@"
office_slice
tiny=("${slice[@]}" --population 4 --generations 1 --divisions 2 --jobs 2 --quiet)

# expect_line EXPECTED_STDERR_LINE CMD...: exit 2, exactly that one line on stderr, no run folder left.
n=0
expect_line() {
  local expected=$1; shift
  n=$((n + 1))
  local err; err=$("$@" --out "$work/out$n" "${tiny[@]}" 2>&1 >/dev/null); local rc=$?
  [[ $rc -eq 2 ]] || fail "exit $rc (want 2): $*"
  [[ "$err" == "$expected" ]] || fail "$*: got '$err', want '$expected'"
  [[ ! -e "$work/out$n/run.sqlite" ]] || fail "$*: a run started"
}
space() { printf '%b' "$2" > "$work/$1.yaml"; echo "$work/$1.yaml"; }

# An objective set that does not exist.
expect_line "slamtune: error: --objectives: unknown objective set 'eta' (known: auto, drawn, occupied, consistency, paper)" \
  "$bin" optimize --objectives eta

# Parameters that cannot be searched, and search spaces the engine would refuse.
s=$(space bool 'vary:\n  do_loop_closing: {min: 0, max: 1}\n')
expect_line "slamtune: error: $s:2: 'do_loop_closing' is a bool parameter: only numbers can be searched (set it with fix: or --set)" \
  "$bin" optimize --space "$s"
s=$(space intreal 'vary:\n  loop_match_minimum_chain_size: {min: 3, max: 12, type: real}\n')
expect_line "slamtune: error: $s:2: 'loop_match_minimum_chain_size' is an integer parameter: its type must be int" \
  "$bin" optimize --space "$s"
s=$(space typo 'vary:\n  loop_search_maximum_distance: {min: 2, max: 6}\nfix:\n  loop_match_minimum_respons_coarse: 0.7\n')
expect_line "slamtune: error: $s:4: unknown mapper parameter 'loop_match_minimum_respons_coarse' (did you mean 'loop_match_minimum_response_coarse'?)" \
  "$bin" optimize --space "$s"
s=$(space negative 'vary:\n  loop_search_maximum_distance: {min: -1, max: 6}\n')
expect_line "slamtune: error: $s:2: mapper parameter loop_search_maximum_distance = -1 is out of range: must be >= 0.001 (smaller radii make a scan its own loop candidate, spec §6.2 item 3)" \
  "$bin" optimize --space "$s"
s=$(space gzero 'vary:\n  loop_search_maximum_distance: {min: 2, max: 6}\nfix:\n  loop_match_minimum_chain_size: 0\n')
expect_line "slamtune: error: $s:4: mapper parameter loop_match_minimum_chain_size = 0 is out of range: must be an integer >= 1" \
  "$bin" optimize --space "$s"
expect_line "slamtune: error: unknown mapper parameter 'loop_search_maximum_distanse' (did you mean 'loop_search_maximum_distance'?)" \
  "$bin" optimize --set loop_search_maximum_distanse=3

# A folder given as the search-space file is refused naming it.
mkdir -p "$work/space_dir"
expect_line "slamtune: error: $work/space_dir: cannot open: is a directory" "$bin" optimize --space "$work/space_dir"
# --set values are validated together after the last; a conflict with a value the user did not
# give says that value is the base's.
expect_line "slamtune: error: mapper parameters correlation_search_space_resolution = 1 and correlation_search_space_smear_deviation = 0.03 are inconsistent: the smear deviation must be in [0.5, 10] x the resolution = [0.5, 10] (correlation_search_space_smear_deviation is not given with --set: the base configuration's value; set it too, or choose values that fit it)" \
  "$bin" optimize --set correlation_search_space_dimension=2 --set correlation_search_space_resolution=1.0
"$bin" run "${slice[@]}" --out "$work/run_set" --quiet --set correlation_search_space_dimension=2 \
  --set correlation_search_space_resolution=1.0 --set correlation_search_space_smear_deviation=1.0 >/dev/null 2>"$work/run_set.err" ||
  fail "run refused a consistent --set of the matcher: $(cat "$work/run_set.err")"

# A consistent set is taken whatever the order, from --set, --params and a space's fix: alike.
matcher=(correlation_search_space_smear_deviation=0.2 correlation_search_space_resolution=0.1
         correlation_search_space_dimension=0.6)
"$bin" optimize --out "$work/set" "${tiny[@]}" --set "${matcher[0]}" --set "${matcher[1]}" --set "${matcher[2]}" \
  >/dev/null 2>"$work/set.err" || fail "--set of a consistent matcher set refused: $(cat "$work/set.err")"
printf '%s\n' "${matcher[@]}" | sed 's/=/: /' > "$work/matcher.yaml"
"$bin" optimize --out "$work/params" "${tiny[@]}" --params "$work/matcher.yaml" >/dev/null 2>"$work/params.err" ||
  fail "--params of a consistent matcher set refused: $(cat "$work/params.err")"
{ printf 'vary:\n  loop_search_maximum_distance: {min: 2, max: 6}\nfix:\n'; printf '  %s\n' "${matcher[@]}" | sed 's/=/: /'; } \
  > "$work/fix.yaml"
"$bin" optimize --out "$work/fix" "${tiny[@]}" --space "$work/fix.yaml" >/dev/null 2>"$work/fix.err" ||
  fail "fix: of a consistent matcher set refused: $(cat "$work/fix.err")"

# The search space from the command line: --vary NAME=MIN:MAX[:STEP] and --fix NAME=VALUE.
expect_line "slamtune: error: --vary r: write NAME=MIN:MAX or NAME=MIN:MAX:STEP" "$bin" optimize --vary r
expect_line "slamtune: error: --vary loop_search_maximum_distance MAX: 'x' is not a number" "$bin" optimize --vary r=2:x
expect_line "slamtune: error: --vary: unknown mapper parameter 'loop_search_maximum_distanc' (did you mean 'loop_search_maximum_distance'?)" \
  "$bin" optimize --vary loop_search_maximum_distanc=2:6
expect_line "slamtune: error: --vary: 'loop_match_minimum_chain_size': an int parameter needs a whole-number step, got 0.5" \
  "$bin" optimize --vary g=6:20:0.5
expect_line "slamtune: error: --fix goes with --vary (it holds a value while others are searched); to change a base value, use --set NAME=VALUE" \
  "$bin" optimize --fix p=0.7
expect_line "slamtune: error: give the search space either with --space or with --vary/--fix, not both" \
  "$bin" optimize --space loop --vary r=2:6
expect_line "slamtune: error: --vary/--fix: mapper parameter loop_match_minimum_chain_size = 0 is out of range: must be an integer >= 1" \
  "$bin" optimize --vary r=2:6 --fix g=0
# A consistent space from flags runs, and a resume rebuilds it from the folder alone.
"$bin" optimize --out "$work/flags" "${tiny[@]}" --vary r=2:6:0.01 --vary g=6:20 --fix p=0.7 >/dev/null 2>"$work/flags.err" ||
  fail "--vary/--fix refused: $(cat "$work/flags.err")"
grep -q '"loop_match_minimum_response_coarse": 0.7' "$work/flags/results.json" || fail "--fix p=0.7 not in results.json"
"$bin" optimize --resume "$work/flags" --quiet >/dev/null 2>"$work/flags_resume.err" ||
  fail "resume of a --vary run failed: $(cat "$work/flags_resume.err")"

# A slice of the built-in world is refused, not ignored: the world is simulated whole.
for cmd in optimize run; do
  err=$("$bin" $cmd --max-scans 40 --out "$work/world_slice_$cmd" 2>&1 >/dev/null); rc=$?
  [[ $rc -eq 2 && "$err" == "slamtune: error: --max-scans 40: reads the first scans of a LOG; the built-in world 'office' is simulated whole (write it to a log with \`slamtune simulate --world office --out DIR\` and give that log)" ]] ||
    fail "$cmd --max-scans without a LOG: exit $rc, '$err'"
  [[ ! -e "$work/world_slice_$cmd/run.sqlite" && ! -e "$work/world_slice_$cmd/run.json" ]] || fail "$cmd --max-scans without a LOG wrote a run"
done

# Readings all filtered out give an empty map: such runs fail, and one is never recommended.
s=$(space minrange 'vary:\n  min_laser_range: {min: 0, max: 37}\n')
"$bin" optimize "${slice[@]}" --space "$s" --out "$work/minrange" --population 8 --generations 2 --divisions 3 --jobs 2 --quiet \
  >/dev/null 2>"$work/minrange.err" || fail "optimize over min_laser_range failed: $(cat "$work/minrange.err")"
grep -q ',failed,the map has no occupied cell' "$work/minrange/evaluations.csv" ||
  fail "no run with an empty map was marked failed"
rec=$(sed -n '/"recommended": {/,/"status"/p' "$work/minrange/results.json" | grep '"status"')
[[ "$rec" == *'"ok"'* ]] || fail "an empty map was recommended: $rec"

cli_test_end
