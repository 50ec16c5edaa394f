#!/usr/bin/env bash
# The stopping rule against the fixed budget on the shared logs (docs/benchmarks.md, "Stopping
# once the answer has settled"): for each log, the default `slamtune optimize` (population 36,
# at most 60 generations, stops when settled), the same with --no-early-stop, and the seed
# paper's whole budget (mode `paper`: population 66, 10 divisions, 60 generations), one after
# the other, with wall time and peak memory from /usr/bin/time. The relations are given, so
# each answer's translational error is known (they do not steer the search).
#
# Resumable: each run works in runs/settle/LOG-MODE; an interrupted run is continued with
# `optimize --resume` the next time the script runs, and a finished one (results.json written)
# is only reported. Wall times add up over the invocations of a run; peak memory is the
# largest of them.
#   scripts/settle-bench.sh [LOG...]      default: aces mit-csail mit-killian intel
#   SETTLE_MODES="default" scripts/settle-bench.sh intel    one mode only
#   modes: default, no-early-stop, paper (default: all three)
set -euo pipefail
cd "$(dirname "$0")/.."
data=../shared/datasets
out=runs/settle
bin=./build/slamtune
[[ -x $bin ]] || { echo "build slamtune first (scripts/test.sh or cmake --build build)" >&2; exit 2; }
logs=("$@"); [[ ${#logs[@]} -gt 0 ]] || logs=(aces mit-csail mit-killian intel)
read -r -a modes <<< "${SETTLE_MODES:-default no-early-stop paper}"
mkdir -p "$out"

run_one() {  # LOG MODE
  local log=$1 mode=$2 dir=$out/$1-$2
  [[ -f $dir/results.json ]] && return 0
  local n; n=$(ls "$dir"/time-*.txt 2>/dev/null | wc -l || true)
  local cmd=("$bin" optimize --quiet)
  if [[ -f $dir/run.sqlite ]]; then
    cmd+=(--resume "$dir")
  else
    cmd+=("$data/$log.clf.gz" --relations "$data/$log.relations" --out "$dir")
    case $mode in
      default) ;;
      no-early-stop) cmd+=(--no-early-stop) ;;
      paper) cmd+=(--no-early-stop --population 66 --divisions 10) ;;
      *) echo "unknown mode $mode (default, no-early-stop, paper)" >&2; exit 2 ;;
    esac
  fi
  mkdir -p "$dir"
  echo "== $log $mode: ${cmd[*]}"
  /usr/bin/time -v -o "$dir/time-$n.txt" "${cmd[@]}" > "$dir/stdout-$n.txt"
}

for log in "${logs[@]}"; do
  [[ -f $data/$log.clf.gz ]] || { echo "skipping $log: $data/$log.clf.gz not found"; continue; }
  for mode in "${modes[@]}"; do run_one "$log" "$mode"; done
done

python3 - "$out" "${logs[@]}" <<'EOF'
import glob, json, os, re, sys
out, logs = sys.argv[1], sys.argv[2:]

def wall_and_peak(d):
    wall, peak = 0.0, 0
    for f in glob.glob(os.path.join(d, "time-*.txt")):
        text = open(f).read()
        m = re.search(r"Elapsed \(wall clock\) time.*: (?:(\d+):)?(\d+):([\d.]+)", text)
        if m: wall += int(m.group(1) or 0) * 3600 + int(m.group(2)) * 60 + float(m.group(3))
        m = re.search(r"Maximum resident set size \(kbytes\): (\d+)", text)
        if m: peak = max(peak, int(m.group(1)))
    return wall, peak

print("| log | mode | generations | SLAM runs | wall | peak memory | recommended | loops | transl. error (defaults) |")
print("|---|---|---|---|---|---|---|---|---|")
for log in logs:
    for d in sorted(glob.glob(os.path.join(out, log + "-*"))):
        mode = d[len(os.path.join(out, log)) + 1:]
        res = os.path.join(d, "results.json")
        if not os.path.exists(res):
            print(f"| {log} | {mode} | unfinished | | | | | | |"); continue
        r = json.load(open(res))
        wall, peak = wall_and_peak(d)
        rec, base = r["recommended"], r["default"]
        names = re.findall(r"(\w+)\[", r["settings"]["space"].split("fix:")[0])  # "vary:NAME[lo,hi]...;..."
        params = ", ".join(f"{n} {rec['params'][n]:.4g}" for n in names if n in rec["params"])
        err = lambda c: f"{c['gt_error']['trans_mean_m']:.4f} m" if c.get("gt_error") else "-"
        runs = r["evaluations"] if isinstance(r["evaluations"], int) else len(r["evaluations"])
        print(f"| {log} | {mode} | {r['generations_run']} of {r['settings']['generations']} | {runs} | "
              f"{wall:.0f} s | {peak / 1024:.0f} MB | {params} | {rec['loop_closures']} | {err(rec)} ({err(base)}) |")
EOF
