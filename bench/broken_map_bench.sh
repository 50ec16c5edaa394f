#!/usr/bin/env bash
# What the front-end search of `slamtune optimize` costs on maps broken in the front end
# (docs/benchmarks.md, "Front-end search on broken maps"). For each input, the default
# optimisation, `slamtune optimize INPUT --relations R --out DIR` with no other flag, under
# /usr/bin/time -v: wall time, CPU time, SLAM runs, peak memory, and the true error of its answer,
# of slam_karto's defaults and of the fault-free twin at the defaults. The inputs:
#
#   building-broken  the built-in world's log (`slamtune simulate --world building-broken`): a
#                    15-minute drive through a large building with a wheel slip and a reverse
#                    stretch planted; its twin is `slamtune run --world building`
#   intel-reverse    intel with the odometry's travel reported backwards over 3 m from 250 m of
#                    its travel (`slamtune fault intel.clf.gz --fault reverse,250,3`), a break at
#                    slam_karto's defaults; its twin is intel itself
#
# Each input is prepared first (the log written, one `slamtune run` of it and one of its twin at
# slam_karto's defaults: the front-end evidence and the errors), then optimised. Besides the
# answer's error, the table gives the lowest error among the SLAM runs evaluated and how many of
# them came within 2x the twin's error: what the search has found so far, also when a timeout
# stopped it before it answered (the errors only measure; the search never sees them). A run stopped by
# --timeout is reported as such, with the SLAM runs and generations its run database holds.
#
#   bench/broken_map_bench.sh [--binary PATH] [--label NAME] [--only NAME] [--timeout SECONDS]
#                             [--out DIR] [--resume]
#     --binary PATH     slamtune to measure (default build/slamtune); to compare two builds, run
#                       the script once with each: their rows land side by side in one table
#     --label NAME      name of this binary's results (default: the name of the binary's folder,
#                       e.g. build)
#     --only NAME       one input (building-broken or intel-reverse)
#     --timeout S       stop each optimisation after S seconds (SIGINT: every finished SLAM run is
#                       kept in its run database); 0 = none (default)
#     --out DIR         results folder (default runs/bench/broken_map)
#     --resume          continue unfinished optimisations (`optimize --resume`) instead of starting
#                       them again, keeping the prepared inputs; times add up over the invocations
#   INTEL_FAULT=KIND,START_M,LENGTH_M[,MAGNITUDE]   another fault for intel
#   SLAMTUNE_DATASETS_DIR   where intel.clf.gz and intel.relations are (default ../shared/datasets)
#
# Writes DIR/broken_map.csv and DIR/broken_map.md, one row per label and input measured so far,
# and keeps every command's output in DIR/LABEL/{inputs,defaults,twin,optimize,logs}/.
set -euo pipefail
cd "$(dirname "$0")/.."

bin=build/slamtune
label=""
only=""
limit=0
out=runs/bench/broken_map
resume=0
data=${SLAMTUNE_DATASETS_DIR:-../shared/datasets}
intel_fault=${INTEL_FAULT:-reverse,250,3}
usage() { sed -n '/^#   bench\/broken_map_bench.sh/,/^# and keeps/p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
while [[ $# -gt 0 ]]; do
  case $1 in
    --binary) bin=${2:?--binary needs a path}; shift 2 ;;
    --label) label=${2:?--label needs a name}; shift 2 ;;
    --only) only=${2:?--only needs an input name}; shift 2 ;;
    --timeout) limit=${2:?--timeout needs seconds}; shift 2 ;;
    --out) out=${2:?--out needs a folder}; shift 2 ;;
    --resume) resume=1; shift ;;
    -h|--help) usage ;;
    *) echo "broken_map_bench.sh: unknown argument '$1'" >&2; usage ;;
  esac
done
[[ -x $bin ]] || { echo "broken_map_bench.sh: $bin is not an executable (build slamtune first)" >&2; exit 2; }
[[ $limit =~ ^[0-9]+$ ]] || { echo "broken_map_bench.sh: --timeout $limit: whole seconds expected" >&2; exit 2; }
bin=$(realpath "$bin")
[[ -n $label ]] || label=$(basename "$(dirname "$bin")")
all=(building-broken intel-reverse)
if [[ -n $only ]]; then
  [[ " ${all[*]} " == *" $only "* ]] || { echo "broken_map_bench.sh: --only $only: one of ${all[*]}" >&2; exit 2; }
  inputs=("$only")
else
  inputs=("${all[@]}")
fi
dir=$out/$label
mkdir -p "$dir"/{inputs,defaults,twin,optimize,logs}
echo "$bin" > "$dir/binary.txt"
echo "binary $bin ($label); results in $dir"

# Sets `log` and `rel` to the input's log and relations, prepared unless --resume finds them.
prepare() {  # NAME
  local name=$1
  case $name in
    building-broken)
      log=$dir/inputs/building-broken.clf rel=$dir/inputs/building-broken.relations
      if [[ $resume -eq 0 || ! -f $log ]]; then
        "$bin" simulate --world building-broken --out "$dir/inputs" > "$dir/logs/$name.prepare.txt"
        prepare_runs "$name" --world building
      fi ;;
    intel-reverse)
      log=$dir/inputs/intel-reverse.clf rel=$data/intel.relations
      if [[ $resume -eq 0 || ! -f $log ]]; then
        "$bin" fault "$data/intel.clf.gz" --fault "$intel_fault" --out "$log" --quiet > "$dir/logs/$name.prepare.txt"
        prepare_runs "$name" "$data/intel.clf.gz" --relations "$rel"
      fi ;;
  esac
}

# One run of the broken input ($log, $rel) and one of its twin at slam_karto's defaults.
prepare_runs() {  # NAME TWIN_ARGS...
  local name=$1; shift
  rm -rf "$dir/defaults/$name" "$dir/twin/$name"
  "$bin" run "$log" --relations "$rel" --out "$dir/defaults/$name" --quiet > "$dir/logs/$name.defaults.txt"
  "$bin" run "$@" --out "$dir/twin/$name" --quiet > "$dir/logs/$name.twin.txt"
  sed 's/^/   defaults: /' "$dir/logs/$name.defaults.txt"
  sed -n '1s/^/   twin:     /p' "$dir/logs/$name.twin.txt"
}

for name in "${inputs[@]}"; do
  if [[ $name == intel-reverse && ! ( -f $data/intel.clf.gz && -f $data/intel.relations ) ]]; then
    echo "== $name: skipped, $data/intel.clf.gz or intel.relations not found"
    continue
  fi
  echo "== $name: preparing"
  prepare "$name"
  run_dir=$dir/optimize/$name
  if [[ $resume -eq 1 && -f $run_dir/results.json ]]; then
    echo "== $name: finished before, reported only"
    continue
  fi
  if [[ $resume -eq 1 && -f $run_dir/run.sqlite ]]; then
    cmd=("$bin" optimize --resume "$run_dir")
  else
    rm -rf "$run_dir" "$dir/logs/$name".optimize-*
    cmd=("$bin" optimize "$log" --relations "$rel" --out "$run_dir")
  fi
  n=$(find "$dir/logs" -name "$name.optimize-*.time" | wc -l)
  echo "== $name: ${cmd[*]}$([[ $limit -gt 0 ]] && echo " (timeout $limit s)")"
  rc=0
  timeout --signal=INT --kill-after=120 "$limit" /usr/bin/time -v -o "$dir/logs/$name.optimize-$n.time" \
    "${cmd[@]}" > "$dir/logs/$name.optimize-$n.out" 2> "$dir/logs/$name.optimize-$n.err" || rc=$?
  echo "$rc" > "$dir/logs/$name.optimize-$n.rc"
  case $rc in
    0) echo "== $name: finished" ;;
    124) echo "== $name: stopped by the timeout after $limit s" ;;
    *) echo "== $name: optimize exited $rc: $(tail -n 1 "$dir/logs/$name.optimize-$n.err")" ;;
  esac
done

# The report: every label and input measured so far in $out.
python3 - "$out" "${all[@]}" <<'EOF'
import csv, glob, json, os, re, sqlite3, sys
out, all_inputs = sys.argv[1], sys.argv[2:]

def times(logs, name):
    """Wall, CPU (user + system) summed and peak RSS (the largest) over the invocations."""
    wall = cpu = 0.0
    peak = 0
    for f in glob.glob(os.path.join(logs, name + ".optimize-*.time")):
        text = open(f).read()
        m = re.search(r"Elapsed \(wall clock\) time.*: (?:(\d+):)?(\d+):([\d.]+)", text)
        if m: wall += int(m.group(1) or 0) * 3600 + int(m.group(2)) * 60 + float(m.group(3))
        for key in ("User time", "System time"):
            m = re.search(key + r" \(seconds\): ([\d.]+)", text)
            if m: cpu += float(m.group(1))
        m = re.search(r"Maximum resident set size \(kbytes\): (\d+)", text)
        if m: peak = max(peak, int(m.group(1)))
    return wall, cpu, peak

def last_rc(logs, name):
    files = sorted(glob.glob(os.path.join(logs, name + ".optimize-*.rc")),
                   key=lambda f: int(re.search(r"-(\d+)\.rc$", f).group(1)))
    return int(open(files[-1]).read()) if files else None

def run_error(folder):
    try:
        gt = json.load(open(os.path.join(folder, "run.json"))).get("gt_error") or {}
        return gt.get("trans_mean_m")
    except (OSError, ValueError):
        return None

def front_end(logs, name):
    try:
        text = open(os.path.join(logs, name + ".defaults.txt")).read()
    except OSError:
        return ""
    return " ".join(l.strip() for l in text.splitlines() if l.startswith("front end"))

def database_counts(folder):
    """SLAM runs, and generations evolved after the initial population (results.json's
    generations_run; None while generation 0 is unfinished), in an unfinished run's database."""
    path = os.path.join(folder, "run.sqlite")
    if not os.path.exists(path): return None, None
    db = sqlite3.connect(path)
    try:
        runs = db.execute("SELECT COUNT(*) FROM evaluations").fetchone()[0]
        gens = db.execute("SELECT MAX(gen) FROM generations").fetchone()[0]
    finally:
        db.close()
    return runs, gens

def run_errors(folder):
    """The true error of every successful SLAM run in the run database (for reference only: the
    search never sees it)."""
    path = os.path.join(folder, "run.sqlite")
    if not os.path.exists(path): return []
    db = sqlite3.connect(path)
    try:
        records = [r for (r,) in db.execute("SELECT record FROM evaluations WHERE status = 'ok'")]
    finally:
        db.close()
    errors = []
    for text in records:
        gt = json.loads(text).get("gt_error") or {}
        if gt.get("trans_mean_m") is not None: errors.append(gt["trans_mean_m"])
    return errors

err = lambda v: "" if v is None else f"{v:.4f}"
rows = []
for name in all_inputs:
    for label_dir in sorted(glob.glob(os.path.join(out, "*", ""))):
        logs = os.path.join(label_dir, "logs")
        if not glob.glob(os.path.join(logs, name + ".*")): continue
        label = os.path.basename(os.path.dirname(label_dir))
        try:
            binary = open(os.path.join(label_dir, "binary.txt")).read().strip()
        except OSError:
            binary = ""
        folder = os.path.join(label_dir, "optimize", name)
        wall, cpu, peak = times(logs, name)
        rc = last_rc(logs, name)
        row = {"label": label, "binary": binary, "input": name, "status": "", "wall_s": f"{wall:.1f}",
               "cpu_s": f"{cpu:.1f}", "slam_runs": "", "generations": "", "peak_rss_mb": f"{peak / 1024:.0f}",
               "answer_error_m": "", "defaults_error_m": "", "twin_error_m": "",
               "front_end_at_defaults": front_end(logs, name)}
        results = os.path.join(folder, "results.json")
        if os.path.exists(results):
            r = json.load(open(results))
            row["status"] = "finished"
            row["slam_runs"] = r["evaluations"] if isinstance(r["evaluations"], int) else len(r["evaluations"])
            row["generations"] = r.get("generations_run", "")
            row["answer_error_m"] = err((r["recommended"].get("gt_error") or {}).get("trans_mean_m"))
            row["defaults_error_m"] = err((r["default"].get("gt_error") or {}).get("trans_mean_m"))
        else:
            runs, gens = database_counts(folder)
            row["status"] = "timeout" if rc == 124 else "not run" if rc is None else f"failed (exit {rc})"
            row["slam_runs"] = "" if runs is None else runs
            row["generations"] = "" if gens is None else gens
        if not row["defaults_error_m"]:  # the preparation's run at the defaults: the same run
            row["defaults_error_m"] = err(run_error(os.path.join(label_dir, "defaults", name)))
        row["twin_error_m"] = err(run_error(os.path.join(label_dir, "twin", name)))
        errors = run_errors(folder)
        row["best_run_error_m"] = err(min(errors)) if errors else ""
        twin = run_error(os.path.join(label_dir, "twin", name))
        row["runs_within_2x_twin"] = "" if twin is None else sum(1 for e in errors if e <= 2 * twin)
        rows.append(row)

csv_path, md_path = os.path.join(out, "broken_map.csv"), os.path.join(out, "broken_map.md")
with open(csv_path, "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=list(rows[0].keys()) if rows else ["label"])
    w.writeheader()
    w.writerows(rows)

def wall_text(row):
    s = float(row["wall_s"])
    text = f"{s / 60:.1f} min" if s >= 120 else f"{s:.0f} s"
    return text if row["status"] == "finished" else f"{text}, {row['status']}"

def runs_text(row):
    if row["generations"] == "":
        return f"{row['slam_runs']}" + ("" if row["status"] == "finished" else " (initial population unfinished)")
    done = "" if row["status"] == "finished" else " done"
    plural = "" if row["generations"] == 1 else "s"
    return f"{row['slam_runs']} ({row['generations']} generation{plural}{done})"

m = lambda v: f"{v} m" if v else "-"
md = ["| input | binary | wall | CPU (user + system) | SLAM runs | peak memory | answer's error | defaults' error | "
      "twin's error at the defaults | best run's error | runs within 2x the twin's |",
      "|---|---|---|---|---|---|---|---|---|---|---|"]
for row in rows:
    md.append(f"| {row['input']} | {row['label']} | {wall_text(row)} | {float(row['cpu_s']):.0f} s | {runs_text(row)} | "
              f"{row['peak_rss_mb']} MB | {m(row['answer_error_m'])} | {m(row['defaults_error_m'])} | "
              f"{m(row['twin_error_m'])} | {m(row['best_run_error_m'])} | {row['runs_within_2x_twin']} |")
md.append("")
seen = set()
for row in rows:
    if row["front_end_at_defaults"] and row["input"] not in seen:
        seen.add(row["input"])
        md.append(f"- {row['input']} at slam_karto's defaults: {row['front_end_at_defaults']}")
open(md_path, "w").write("\n".join(md) + "\n")
print("\n".join(md))
print(f"wrote {csv_path} and {md_path}")
EOF
