#!/usr/bin/env bash
# A resumed optimisation writes what the uninterrupted one writes: after kill -9, SIGINT and
# SIGTERM, and in a finished folder whose results.json was deleted, `optimize --resume` leaves a
# folder equal to the uninterrupted run's file by file (the parameter files, tables, maps,
# figures, front_end.png and front_end_map.png, report.html, results.json with its
# base_front_end block). Every run works in the same folder path (the outputs name it) with
# --jobs 1 (with more, a run killed mid-generation may have finished a later set of it and not an
# earlier one; the resumed run then lists the earlier one after it).
# Left out of the comparison, as they legitimately differ: the run database (run.sqlite and its
# journal: timings) and run.lock (the pid), the times measured (wall_s anywhere in results.json,
# the wall_s column of evaluations.csv, the report's wall time), and what the process did rather
# than what it found (results.json's cache_hits and evaluations, the report's lines of them: a
# resumed process runs only what was not stored).
# Usage: resume_equal_cli_test.sh SLAMTUNE_BINARY [DATASETS_DIR]. Exit 0 pass, 1 fail, 77 skip.
set -u
source "$(dirname "$0")/lib.sh"
cli_test_begin resume_equal_cli_test "$@" -- sqlite3

# generation DIR: the last generation stored in DIR's run database (-1 before the first).
generation() {
  [[ -s "$1/run.sqlite" ]] || { echo -1; return; }
  sqlite3 -cmd '.timeout 2000' "$1/run.sqlite" 'SELECT COALESCE(MAX(gen), -1) FROM generations' 2>/dev/null || echo -1
}
# wait_for DIR PID GEN: until generation GEN of DIR is stored, or the process ended.
wait_for() {
  for _ in $(seq 1 1800); do
    [[ $(generation "$1") -ge $3 ]] && return 0
    kill -0 "$2" 2>/dev/null || return 1
    sleep 0.1
  done
  return 1
}

# same_folder WHOLE RESUMED LABEL: every file of either folder in the other, equal but for the
# fields named at the top.
same_folder() {
  python3 - "$1" "$2" <<'EOF' || fail "$3: the resumed folder differs from the uninterrupted one"
import csv, io, json, os, re, sys
whole, resumed = sys.argv[1], sys.argv[2]
SKIP_FILES = re.compile(r"^run\.sqlite(-wal|-shm|-journal)?$|^run\.lock$")
TIMING_KEYS = {"wall_s", "cache_hits", "evaluations"}
HTML_ROWS = re.compile(r"<tr><t[dh]>(wall time|requests served from the cache|SLAM runs \(evaluations\))</t[dh]>.*?</tr>")

def files(root):
    out = set()
    for d, _, names in os.walk(root):
        for n in names:
            rel = os.path.relpath(os.path.join(d, n), root)
            if not SKIP_FILES.search(os.path.basename(rel)):
                out.add(rel)
    return out

def strip(v):
    if isinstance(v, dict):
        return {k: strip(x) for k, x in v.items() if k not in TIMING_KEYS}
    if isinstance(v, list):
        return [strip(x) for x in v]
    return v

def first_difference(a, b, path="$"):
    if type(a) is not type(b):
        return path
    if isinstance(a, dict):
        for k in sorted(set(a) | set(b)):
            if k not in a or k not in b:
                return f"{path}.{k}"
            d = first_difference(a[k], b[k], f"{path}.{k}")
            if d:
                return d
        return None
    if isinstance(a, list):
        if len(a) != len(b):
            return f"{path} (length)"
        for i, (x, y) in enumerate(zip(a, b)):
            d = first_difference(x, y, f"{path}[{i}]")
            if d:
                return d
        return None
    return None if a == b else path

def csv_without_wall(text):
    rows = list(csv.reader(io.StringIO(text)))
    if rows and "wall_s" in rows[0]:
        k = rows[0].index("wall_s")
        rows = [r[:k] + r[k + 1:] for r in rows]
    return rows

ok = True
a, b = files(whole), files(resumed)
for rel in sorted(a ^ b):
    print(f"  {rel}: only in the {'uninterrupted' if rel in a else 'resumed'} run", file=sys.stderr)
    ok = False
for rel in sorted(a & b):
    x = open(os.path.join(whole, rel), "rb").read()
    y = open(os.path.join(resumed, rel), "rb").read()
    if x == y:
        continue
    if rel.endswith(".json"):
        d = first_difference(strip(json.loads(x)), strip(json.loads(y)))
        if d is None:
            continue
        print(f"  {rel}: differs at {d}", file=sys.stderr)
    elif rel.endswith(".csv"):
        if csv_without_wall(x.decode()) == csv_without_wall(y.decode()):
            continue
        print(f"  {rel}: differs", file=sys.stderr)
    elif rel.endswith(".html"):
        if HTML_ROWS.sub("", x.decode()) == HTML_ROWS.sub("", y.decode()):
            continue
        print(f"  {rel}: differs", file=sys.stderr)
    else:
        print(f"  {rel}: differs", file=sys.stderr)
    ok = False
sys.exit(0 if ok else 1)
EOF
}

office_slice
small=("${slice[@]}" --population 4 --generations 2 --divisions 2 --seed 5 --jobs 1)
run="$work/run"
"$bin" optimize --out "$run" "${small[@]}" --quiet >/dev/null 2>"$work/whole.err" ||
  { fail "the uninterrupted run failed: $(cat "$work/whole.err")"; exit 1; }
mv "$run" "$work/whole"
for f in front_end.png front_end_map.png; do
  [[ -s "$work/whole/$f" ]] || fail "the uninterrupted run wrote no $f"
done
python3 -c 'import json, sys; json.load(open(sys.argv[1]))["base_front_end"]' "$work/whole/results.json" ||
  fail "the uninterrupted run's results.json has no base_front_end"

# kill -9 once generation 0 is stored.
"$bin" optimize --out "$run" "${small[@]}" --quiet >/dev/null 2>&1 &
pid=$!
background+=("$pid")
if wait_for "$run" "$pid" 0 && kill -9 "$pid" 2>/dev/null; then
  wait "$pid" 2>/dev/null
  "$bin" optimize --resume "$run" --jobs 1 --quiet >/dev/null 2>"$work/kill.err" ||
    fail "--resume after kill -9 failed: $(cat "$work/kill.err")"
  same_folder "$work/whole" "$run" "kill -9"
else
  fail "the run to kill ended before generation 0 was stored"
fi
rm -rf "$run"

# SIGINT once generation 1 is stored (background jobs get SIGINT only with job control on).
set -m
"$bin" optimize --out "$run" "${small[@]}" --quiet >/dev/null 2>&1 &
pid=$!
background+=("$pid")
if wait_for "$run" "$pid" 1 && kill -INT "$pid" 2>/dev/null; then
  wait "$pid"; rc=$?
  [[ $rc -eq 130 ]] || fail "SIGINT: exit $rc, want 130"
  "$bin" optimize --resume "$run" --jobs 1 --quiet >/dev/null 2>"$work/int.err" ||
    fail "--resume after SIGINT failed: $(cat "$work/int.err")"
  same_folder "$work/whole" "$run" "SIGINT"
else
  fail "the run to interrupt ended before generation 1 was stored"
fi
rm -rf "$run"

# SIGTERM during generation 0 (its start is committed before that line is printed).
"$bin" optimize --out "$run" "${small[@]}" >/dev/null 2>"$work/term.err" &
pid=$!
background+=("$pid")
for _ in $(seq 1 1800); do
  grep -q '^generation 0: ' "$work/term.err" && break
  kill -0 "$pid" 2>/dev/null || break
  sleep 0.1
done
if kill -TERM "$pid" 2>/dev/null; then
  wait "$pid"; rc=$?
  [[ $rc -eq 143 ]] || fail "SIGTERM: exit $rc, want 143"
  "$bin" optimize --resume "$run" --jobs 1 --quiet >/dev/null 2>"$work/term_resume.err" ||
    fail "--resume after SIGTERM failed: $(cat "$work/term_resume.err")"
  same_folder "$work/whole" "$run" "SIGTERM"
else
  fail "the run to stop with SIGTERM ended before it could be stopped"
fi
rm -rf "$run"

# A finished folder whose results.json was deleted.
cp -r "$work/whole" "$run"
rm "$run/results.json"
"$bin" optimize --resume "$run" --jobs 1 --quiet >/dev/null 2>"$work/finished.err" ||
  fail "--resume of a finished folder failed: $(cat "$work/finished.err")"
same_folder "$work/whole" "$run" "results.json deleted"

cli_test_end
