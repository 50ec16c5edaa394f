#!/usr/bin/env bash
# What `--beams` does with a laser whose beam count changes from scan to scan (docs/recordings.md
# §1.8), measured on the shared CARMEN logs made into such a laser. Every K-th scan of each log is
# rewritten as a ROBOTLASER1 record without its last beam (same first angle and step, one reading
# fewer: the ±1 count of a cheap spinning lidar); the other scans are untouched. Each log is then
# run at slam_karto's defaults with --beams node (what both nodes do: the shorter scans are
# dropped), per-geometry (one Karto laser per beam geometry) and nearest-beam (resampled onto the
# most common geometry), and once as the original log, with the log's relations for the error.
#
#   bench/beam_count_bench.sh [--binary PATH] [--every K] [--logs "intel aces ..."] [--out DIR]
#     --binary PATH   slamtune to run (default build/slamtune)
#     --every K       which scans lose a beam: the K-th, 2K-th, ... FLASER record (default 3)
#     --logs NAMES    shared logs to use (default "intel aces mit-killian"; FLASER logs only)
#     --out DIR       results folder (default runs/bench/beam_count)
#   SLAMTUNE_DATASETS_DIR   where the logs and relations are (default ../shared/datasets)
#
# Writes DIR/beam_count.md (one row per log and choice: scans used, nodes per laser, loop
# closures, error and wall time) and keeps every run's folder in DIR/runs/.
set -euo pipefail
cd "$(dirname "$0")/.."

bin=build/slamtune
every=3
logs="intel aces mit-killian"
out=runs/bench/beam_count
data=${SLAMTUNE_DATASETS_DIR:-../shared/datasets}
usage() { sed -n '/^#   bench\/beam_count_bench.sh/,/^#   SLAMTUNE_DATASETS_DIR/p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
while [[ $# -gt 0 ]]; do
  case $1 in
    --binary) bin=${2:?--binary needs a path}; shift 2 ;;
    --every) every=${2:?--every needs a number}; shift 2 ;;
    --logs) logs=${2:?--logs needs names}; shift 2 ;;
    --out) out=${2:?--out needs a folder}; shift 2 ;;
    -h|--help) usage ;;
    *) echo "beam_count_bench.sh: unknown argument '$1'" >&2; usage ;;
  esac
done
[[ -x $bin ]] || { echo "beam_count_bench.sh: $bin is not an executable (build slamtune first)" >&2; exit 2; }
[[ $every =~ ^[1-9][0-9]*$ ]] || { echo "beam_count_bench.sh: --every $every: a whole number >= 1 expected" >&2; exit 2; }
mkdir -p "$out/runs" "$out/inputs"

# FLASER n r_1..r_n x y theta odom_x odom_y odom_theta ipc_time host logger_time: the FLASER
# angles are -90 deg + i * 180 deg / n for even n, -90 deg + i * 180 deg / (n - 1) for odd n.
# ROBOTLASER1 type start fov step max_range accuracy remission_mode n r_1..r_n 0 (remissions)
# laser x y theta, robot x y theta, tv rv forward_safety side_safety turn_axis, ipc_time host logger_time.
shorten() {  # LOG.clf.gz OUT.clf
  zcat -f "$1" | awk -v every="$every" 'BEGIN { pi = atan2(0, -1) }
    /^FLASER / && ++k % every == 0 {
      n = $2; step = (n % 2 == 0) ? pi / n : pi / (n - 1); m = n - 1
      out = sprintf("ROBOTLASER1 0 %.17g %.17g %.17g 80 0.01 0 %d", -pi / 2, (m - 1) * step, step, m)
      for (i = 1; i <= m; ++i) out = out " " $(2 + i)
      out = out " 0"
      for (j = 3 + n; j <= 8 + n; ++j) out = out " " $j
      out = out " 0 0 0 0 0"
      for (j = 9 + n; j <= 11 + n; ++j) out = out " " $j
      print out; next
    }
    { print }' >"$2"
}

row() {  # LOG CHOICE FOLDER
  python3 - "$@" <<'PY'
import json, sys
log, choice, folder = sys.argv[1:4]
r = json.load(open(folder + "/run.json"))
lasers = r.get("lasers") or []
nodes = "/".join(str(l["nodes"]) for l in lasers) if len(lasers) > 1 else str(r["nodes"])
gt = r.get("gt_error") or {}
print(f"| {log} | {choice} | {r['scans']} | {r['scans_not_used']['wrong_reading_count']['count']} | {nodes} | "
      f"{r['loop_closures']} | {gt.get('trans_mean_m', float('nan')):.4f} | {r['wall_s']:.1f} |")
PY
}

table=$out/beam_count.md
{
  echo "FLASER records $every, $((2 * every)), ... one beam shorter; slam_karto's defaults; $("$bin" --version 2>/dev/null || echo slamtune)"
  echo
  echo "| log | --beams | scans | dropped (count) | nodes (per laser) | loop closures | error (m) | wall (s) |"
  echo "|---|---|---|---|---|---|---|---|"
} >"$table"
for name in $logs; do
  src=$data/$name.clf.gz
  rel=$data/$name.relations
  [[ -r $src && -r $rel ]] || { echo "beam_count_bench.sh: $src or $rel is missing" >&2; exit 2; }
  shorten "$src" "$out/inputs/$name.clf"
  echo "== $name: $(grep -c '^ROBOTLASER1' "$out/inputs/$name.clf") scans shortened" >&2
  "$bin" run "$src" --relations "$rel" --out "$out/runs/$name-original" --quiet >/dev/null
  row "$name" "(original log)" "$out/runs/$name-original" >>"$table"
  for beams in node per-geometry nearest-beam; do
    "$bin" run "$out/inputs/$name.clf" --relations "$rel" --beams "$beams" --out "$out/runs/$name-$beams" --quiet >/dev/null
    row "$name" "$beams" "$out/runs/$name-$beams" >>"$table"
  done
done
cat "$table"
