#!/usr/bin/env bash
# A broken map end to end (docs/search-spaces.md, "A broken map's budget"): a simulated office
# drive with a 1.5 m odometry jump planted by `slamtune fault` breaks slam_karto's front end;
# `slamtune optimize LOG --relations R` with no budget flags searches the front end with the
# broken-map budget (population 12, stopped once the recommended map is sound and unchanged),
# stops early and says why, and recommends a map whose error is within 2x the untouched log's
# at the defaults. Flags the user gives keep their values.
# Usage: broken_map_cli_test.sh SLAMTUNE_BINARY [DATASETS_DIR]. Exit 0 pass, 1 fail, 77 skip.
set -u
source "$(dirname "$0")/lib.sh"
cli_test_begin broken_map_cli_test "$@" -- python3

simulate_world "$work/sim" office
log="$work/sim/office.clf"
relations="$work/sim/office.relations"
"$bin" fault "$log" --fault jump,20,0.1,1.5 --out "$work/jump.clf" --quiet > /dev/null || { echo "FAIL: fault" >&2; exit 1; }
"$bin" run "$log" --relations "$relations" --out "$work/plain" --quiet > "$work/plain.txt" || { echo "FAIL: run" >&2; exit 1; }
plain=$(sed -n 's/.*, error \([0-9.]*\) +- .*/\1/p' "$work/plain.txt")
[[ -n "$plain" ]] || { echo "FAIL: no error in: $(cat "$work/plain.txt")" >&2; exit 1; }

"$bin" optimize "$work/jump.clf" --relations "$relations" --jobs 2 --out "$work/opt" > "$work/opt.out" 2> "$work/opt.err" ||
  { echo "FAIL: optimize: $(tail -3 "$work/opt.err")" >&2; exit 1; }
grep -q "front end" "$work/opt.err" || fail "no front-end choice said: $(head -3 "$work/opt.err")"
grep -q "population 12," "$work/opt.err" "$work/opt.out" || fail "not the broken-map population: $(grep -h '^optimising' "$work/opt.err" "$work/opt.out")"
grep -q "^NSGA-III stopped after generation [0-9]* of 60: the recommended map was sound" "$work/opt.out" ||
  fail "no sound-answer stop: $(grep '^NSGA-III' "$work/opt.out")"
python3 - "$work/opt/results.json" "$plain" <<'EOF' || fail "the recommended map is not within 2x the untouched log's error"
import json, sys
r = json.load(open(sys.argv[1]))
answer = r["recommended"]["gt_error"]["trans_mean_m"]
defaults = r["default"]["gt_error"]["trans_mean_m"]
plain = float(sys.argv[2])
print(f"broken-map answer {answer:.4f} m, defaults {defaults:.4f} m, untouched log at the defaults {plain:.4f} m")
sys.exit(0 if answer <= 2 * plain and answer < defaults else 1)
EOF
# The budget is stored: a resume of the finished run runs nothing more and says the same.
"$bin" optimize --resume "$work/opt" --jobs 2 > "$work/resume.out" 2> "$work/resume.err" ||
  fail "--resume: $(tail -3 "$work/resume.err")"
cmp -s <(grep '^NSGA-III' "$work/opt.out") <(grep '^NSGA-III' "$work/resume.out") ||
  fail "resume ended differently: $(grep '^NSGA-III' "$work/resume.out")"

# Budget flags the user gives win: --population 8 and the rule off run the whole (small) budget.
"$bin" optimize "$work/jump.clf" --max-scans 600 --population 8 --divisions 3 --sound-answer-window 0 --generations 1 --jobs 2 \
  --out "$work/flags" > "$work/flags.out" 2> "$work/flags.err" || fail "optimize with flags: $(tail -3 "$work/flags.err")"
grep -q "population 8," "$work/flags.err" "$work/flags.out" || fail "--population 8 not used"
grep -q "^NSGA-III ran all 1 generations" "$work/flags.out" || fail "flags run: $(grep '^NSGA-III' "$work/flags.out")"
"$bin" optimize "$work/jump.clf" --sound-answer-window -1 --out "$work/bad" > /dev/null 2> "$work/bad.err"
rc=$?
[[ $rc -eq 2 ]] || fail "--sound-answer-window -1: exit $rc, want 2"
grep -q "^slamtune: error: .*--sound-answer-window = -1 is out of range" "$work/bad.err" || fail "message: $(cat "$work/bad.err")"

cli_test_end
