#!/usr/bin/env bash
# Builds slamtune (Release) and runs every benchmark, writing the outputs to runs/bench/.
# Speed figures are ratios measured side by side in one invocation (e.g. reference matcher vs
# fast matcher, shared vs one-by-one evaluation). Uses ../shared/datasets when present.
#   scripts/bench.sh          full set (hours on 2 cores: the whole-optimisation runs use the
#                             paper's 66 x 60 budget on mit-csail, aces and intel, and the
#                             front-end search on two broken maps runs to the end)
#   scripts/bench.sh --quick  a few minutes
set -euo pipefail
cd "$(dirname "$0")/.."
quick=0; [[ "${1:-}" == "--quick" ]] && quick=1
bash scripts/install-deps.sh
bash scripts/configure.sh >/dev/null
cmake --build build -j"$(nproc)" --target slamtune bench_engine bench_matcher bench_map_quality bench_nsga3_dtlz \
  bench_shared_eval bench_objectives
out=runs/bench; mkdir -p "$out"
data=../shared/datasets
run() { local name=$1; shift; echo "== $name: $*"; "$@" 2>&1 | tee "$out/$name.txt"; }
run matcher ./build/bench/bench_matcher --benchmark_repetitions=$((quick ? 1 : 3)) --benchmark_report_aggregates_only=true
run map_quality ./build/bench/bench_map_quality --benchmark_repetitions=$((quick ? 1 : 3)) --benchmark_report_aggregates_only=true
if [[ $quick -eq 1 ]]; then
  run engine ./build/bench/bench_engine --dataset mit-csail --world office
  run nsga3_dtlz ./build/bench/bench_nsga3_dtlz --seeds 3 --generations-scale 0.25
  run shared_eval_office ./build/bench/bench_shared_eval --quick
  run whole_office ./build/bench/bench_shared_eval --whole --quick
  run objectives_office-jump ./build/bench/bench_objectives --world office-jump --runs 12
else
  run engine ./build/bench/bench_engine --dataset intel --world office --repeat 3
  run nsga3_dtlz ./build/bench/bench_nsga3_dtlz --seeds 20
  run shared_eval_office ./build/bench/bench_shared_eval
  for log in mit-csail intel; do
    [[ -f $data/$log.clf.gz ]] && run shared_eval_$log ./build/bench/bench_shared_eval "$data/$log.clf.gz"
  done
  for log in mit-csail aces intel; do
    [[ -f $data/$log.clf.gz ]] && run whole_$log ./build/bench/bench_shared_eval --whole "$data/$log.clf.gz"
  done
  # Do the objectives rank runs as the true error does (docs/metrics.md)?
  for world in office office-jump office-slip corridor-long; do
    run objectives_$world ./build/bench/bench_objectives --world $world --space front-end --runs 40
  done
  for log in aces mit-csail intel mit-killian; do
    for space in front-end loop; do
      [[ -f $data/$log.clf.gz ]] && run objectives_${log}_$space ./build/bench/bench_objectives "$data/$log.clf.gz" \
        --relations "$data/$log.relations" --space $space --runs 40
    done
  done
  # The default optimize on maps broken in the front end: a 15-minute building, intel with a
  # planted reverse stretch (docs/benchmarks.md, "Front-end search on broken maps").
  run broken_map bash bench/broken_map_bench.sh --out "$out/broken_map"
fi
echo "outputs in $out/"
