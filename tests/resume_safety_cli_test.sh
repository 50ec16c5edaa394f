#!/usr/bin/env bash
# What `slamtune optimize` (and `run`, `sweep`) refuse or say so that a run folder is never
# silently wrong: relations that match no scan of the log, a damaged run database, input files
# changed in place, a second process in the same folder, and SIGINT / SIGTERM (one line saying
# how to continue, then the signal's status; --resume then ends with the uninterrupted run's
# tables).
# Usage: resume_safety_cli_test.sh SLAMTUNE_BINARY [DATASETS_DIR]. Exit 0 pass, 1 fail, 77 skip.
set -u
source "$(dirname "$0")/lib.sh"
cli_test_begin resume_safety_cli_test "$@"

# expect_line EXPECTED CMD...: exit 2 and exactly the one line EXPECTED on stdout and stderr together.
expect_line() {
  local expected=$1; shift
  local out; out=$("$@" 2>&1); local rc=$?
  [[ $rc -eq 2 ]] || fail "exit $rc (want 2): $*"
  [[ "$out" == "$expected" ]] || fail "$*
  got:  $out
  want: $expected"
}
# expect_match REGEX CMD...: exit 2 and one line matching REGEX.
expect_match() {
  local regex=$1; shift
  local out; out=$("$@" 2>&1); local rc=$?
  [[ $rc -eq 2 ]] || fail "exit $rc (want 2): $*"
  [[ "$out" =~ $regex && "$out" != *$'\n'* ]] || fail "$*: got '$out', want one line matching '$regex'"
}

# FLASER scans at t = 1..30 s (x = 0.2 t), each of 180 readings from 2.0 to 2.6 m.
readings=$(awk 'BEGIN { for (i = 0; i < 180; i++) printf " %.1f", 2 + (i % 7) * 0.1 }')
flaser() {  # T X
  printf 'FLASER 180%s %s 0 0 %s 0 0 %s h %s\n' "$readings" "$2" "$2" "$1" "$1"
}
log="$work/line.clf"
for t in $(seq 1 30); do flaser "$t" "$(awk "BEGIN{print 0.2*$t}")"; done >"$log"
relation() { printf '%s %s 0.2 0 0 0 0 0\n' "$1" "$2"; }  # T1 T2: 0.2 m ahead

# 6. Relations whose timestamps match no scan: refused before any SLAM run, naming the file and
# both time spans; partly matching ones counted.
{ relation 1001 1002; relation 1003 1004; } >"$work/other.relations"
none="slamtune: error: $work/other.relations: no relation's timestamps match a scan of the log (the log's scans span 1.000 .. 30.000 s; the 2 relations span 1001.000 .. 1004.000 s)"
expect_line "$none" "$bin" run "$log" --relations "$work/other.relations" --out "$work/run_none" --quiet
expect_line "$none" "$bin" optimize "$log" --relations "$work/other.relations" --out "$work/opt_none" --quiet
[[ ! -e "$work/opt_none/run.sqlite" ]] || fail "optimize started a run with relations that match nothing"
expect_line "$none" "$bin" sweep "$log" --relations "$work/other.relations" --vary g=6:8 --out "$work/sweep_none" --quiet
expect_match "^slamtune: error: $work/other.relations: no relation's timestamps match a scan of the log \(the log's scans span [0-9.]+ \.\. [0-9.]+ s; the 2 relations span 1001.000 \.\. 1004.000 s\)$" \
  "$bin" optimize --relations "$work/other.relations" --out "$work/opt_world" --quiet
{ relation 1 2; relation 2 3; relation 1003 1004; } >"$work/part.relations"
"$bin" run "$log" --relations "$work/part.relations" --out "$work/run_part" >"$work/part.out" 2>"$work/part.err" ||
  fail "run with partly matching relations failed: $(cat "$work/part.err")"
grep -qxF "slamtune: warning: $work/part.relations: 2 of 3 relations match scans of the log; the errors use those only" \
  "$work/part.err" || fail "no count of the matching relations: $(cat "$work/part.err")"
grep -q '(2 relations)' "$work/part.out" || fail "run did not use the 2 matching relations: $(cat "$work/part.out")"

# 14. Input files changed in place (same size) are refused on --resume, naming the file; a run
# recorded without content hashes still resumes.
printf 'loop_search_maximum_distance: 3.0\n' >"$work/base.yaml"
relation 1 5 >"$work/line.relations"
quick=(--population 4 --generations 1 --divisions 2 --seed 3 --jobs 2 --quiet)
"$bin" optimize "$log" --params "$work/base.yaml" --relations "$work/line.relations" --out "$work/hashed" "${quick[@]}" \
  >/dev/null 2>"$work/hashed.err" || fail "optimize on the corridor log failed: $(cat "$work/hashed.err")"
cp -r "$work/hashed" "$work/old_format"
sqlite3 "$work/old_format/run.sqlite" \
  "UPDATE meta SET value = json_remove(value, '\$.input_hashes') WHERE key = 'invocation'" ||
  fail "could not strip the recorded hashes"
"$bin" optimize --resume "$work/old_format" --quiet >/dev/null 2>"$work/old.err" ||
  fail "a run recorded without content hashes did not resume: $(cat "$work/old.err")"
changed() { echo "slamtune: error: $1: changed since the run started (content $2, recorded $3); resuming would mix results of two inputs: restore the file or start a new run with --out"; }
crc() { sqlite3 "$work/hashed/run.sqlite" "SELECT json_extract(value, '\$.input_hashes.$1') FROM meta WHERE key = 'invocation'"; }
crc_of() { python3 -c 'import sys, zlib; print("crc32:%08x" % zlib.crc32(open(sys.argv[1], "rb").read()))' "$1"; }
sed -i 's/3.0/3.5/' "$work/base.yaml"
expect_line "$(changed "$work/base.yaml" "$(crc_of "$work/base.yaml")" "$(crc params)")" \
  "$bin" optimize --resume "$work/hashed"
sed -i 's/3.5/3.0/' "$work/base.yaml"
sed -i '7s/ 2.3 / 2.4 /' "$log"
expect_line "$(changed "$log" "$(crc_of "$log")" "$(crc log)")" "$bin" optimize --resume "$work/hashed"
sed -i '7s/ 2.4 / 2.3 /' "$log"
sed -i 's/^1 5 /2 5 /' "$work/line.relations"
expect_line "$(changed "$work/line.relations" "$(crc_of "$work/line.relations")" "$(crc relations)")" \
  "$bin" optimize --resume "$work/hashed" --jobs 2
sed -i 's/^2 5 /1 5 /' "$work/line.relations"

# 13. A damaged run database is refused on --resume, naming it, before anything else is printed.
cp -r "$work/hashed" "$work/page"
size=$(stat -c %s "$work/page/run.sqlite")
[[ $size -ge 12288 ]] || fail "run.sqlite has only $size bytes"
head -c 4096 /dev/zero | tr '\0' 'Z' | dd of="$work/page/run.sqlite" bs=4096 seek=2 conv=notrunc status=none
expect_match "^slamtune: error: $work/page/run.sqlite: the run database is damaged \(.+\); it cannot be resumed: start again with a new --out \(the report files beside it stay readable\)$" \
  "$bin" optimize --resume "$work/page"
cp -r "$work/hashed" "$work/header"
printf 'not a database header' | dd of="$work/header/run.sqlite" conv=notrunc status=none
expect_line "slamtune: error: $work/header/run.sqlite: the run database is damaged (file is not a database); it cannot be resumed: start again with a new --out (the report files beside it stay readable)" \
  "$bin" optimize --resume "$work/header"

# generation DIR: the last generation stored in DIR's run database (-1 before the first).
# (sqlite3 would create a missing database: ask only once the run has made it)
generation() {
  [[ -s "$1/run.sqlite" ]] || { echo -1; return; }
  sqlite3 -cmd '.timeout 2000' "$1/run.sqlite" 'SELECT COALESCE(MAX(gen), -1) FROM generations' 2>/dev/null || echo -1
}
# wait_for DIR PID GEN: until generation GEN of DIR is stored, or the process ended.
wait_for() {
  for _ in $(seq 1 900); do
    [[ $(generation "$1") -ge $3 ]] && return 0
    kill -0 "$2" 2>/dev/null || return 1
    sleep 0.1
  done
  return 1
}

# 15 and 16. A run on a slice of the office world is stopped by SIGINT after its first
# generation; while it works, a second process is refused naming the folder and the pid.
set -m  # background jobs get SIGINT only with job control on
office_slice 1200  # long enough a generation to be stopped in the next
small=("${slice[@]}" --population 4 --generations 2 --divisions 2 --seed 5 --jobs 2)
"$bin" optimize --out "$work/whole" "${small[@]}" --quiet >/dev/null 2>&1 &
whole_pid=$!
background+=("$whole_pid")
"$bin" optimize --out "$work/cut" "${small[@]}" >"$work/cut.out" 2>"$work/cut.err" &
pid=$!
background+=("$pid")
if wait_for "$work/cut" "$pid" 0; then
  held="slamtune: error: $work/cut: another slamtune process (pid $pid) is working in this folder; wait for it to end or stop it"
  expect_line "$held" "$bin" optimize --resume "$work/cut"
  expect_line "$held" "$bin" optimize --out "$work/cut" "${small[@]}"
else
  fail "the run to interrupt ended early: $(cat "$work/cut.err")"
fi
wait_for "$work/cut" "$pid" 1 || fail "generation 1 was never stored: $(cat "$work/cut.err")"
kill -INT "$pid"
wait "$pid"; rc=$?
[[ $rc -eq 130 ]] || fail "SIGINT: exit $rc, want 130"
[[ "$(tail -n 1 "$work/cut.err")" == "slamtune: stopped by SIGINT; every finished evaluation is saved: continue with \`slamtune optimize --resume $work/cut\`" ]] ||
  fail "SIGINT: last line '$(tail -n 1 "$work/cut.err")'"
[[ $(generation "$work/cut") -ge 1 ]] || fail "the stored generations were lost"
"$bin" optimize --resume "$work/cut" --jobs 2 --quiet >/dev/null 2>"$work/resume.err" ||
  fail "--resume after SIGINT failed: $(cat "$work/resume.err")"

# SIGTERM during generation 0 (its start is committed before that line is printed): the same
# line, status 143.
"$bin" optimize --out "$work/term" "${small[@]}" >/dev/null 2>"$work/term.err" &
pid=$!
background+=("$pid")
for _ in $(seq 1 600); do
  grep -q '^generation 0: ' "$work/term.err" && break
  sleep 0.1
done
kill -TERM "$pid"
wait "$pid"; rc=$?
[[ $rc -eq 143 ]] || fail "SIGTERM: exit $rc, want 143"
[[ "$(tail -n 1 "$work/term.err")" == "slamtune: stopped by SIGTERM; every finished evaluation is saved: continue with \`slamtune optimize --resume $work/term\`" ]] ||
  fail "SIGTERM: stderr '$(cat "$work/term.err")'"

wait "$whole_pid" || fail "the uninterrupted run failed"
for f in table3_best_worst_params.csv table4_6_objectives.csv table7_loop_closures.csv table8_loop_scans.csv \
         table9_10_errors.csv best.yaml; do
  cmp -s "$work/whole/$f" "$work/cut/$f" || fail "$f differs between the uninterrupted and the resumed run"
done

cli_test_end
