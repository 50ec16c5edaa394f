#!/usr/bin/env bash
# End-to-end test of distributed evaluation: `mpirun -np 2 slamtune optimize` on localhost
# gives the same result as one process with the same seed, and input errors stop every rank
# with a clear message instead of hanging.
# Usage: mpi_cli_test.sh SLAMTUNE_BINARY DATASETS_DIR. Exit 0 pass, 1 fail, 77 skip.
set -u
source "$(dirname "$0")/lib.sh"
cli_test_begin mpi_cli_test "$@" -- mpirun
# As root (CI) Open MPI wants to be told; --oversubscribe: 2 ranks even where fewer slots are set.
mpi=(timeout 600 mpirun --allow-run-as-root --oversubscribe -np 2)
office_slice
small=("${slice[@]}" --population 8 --generations 2 --divisions 3 --seed 5)

"${mpi[@]}" "$bin" optimize --out "$work/mpi" "${small[@]}" > "$work/mpi.txt" 2>&1
rc=$?
if grep -q "built without MPI" "$work/mpi.txt"; then echo "SKIP: slamtune built without MPI" >&2; exit 77; fi
[[ $rc -eq 0 ]] || fail "mpirun optimize failed (rc $rc): $(tail -5 "$work/mpi.txt")"
"$bin" optimize --out "$work/one" "${small[@]}" --jobs 2 --quiet > "$work/one.txt" 2>&1 || fail "single-process optimize failed"

# Rank 0 alone writes: one database and one report, in the --out folder.
[[ -s "$work/mpi/run.sqlite" && -s "$work/mpi/report.html" ]] || fail "the 2-rank run wrote no database or report"
# Same result: every table and the parameter file byte for byte.
for f in table3_best_worst_params.csv table4_6_objectives.csv table7_loop_closures.csv table8_loop_scans.csv \
         table9_10_errors.csv best.yaml best_slam_karto.yaml; do
  cmp -s "$work/mpi/$f" "$work/one/$f" || fail "$f differs between 2 ranks and one process"
done
# And every evaluation (rows are in finishing order; index and wall time are not results).
strip() {  # every column but index and wall_s, found by name
  awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) drop[i] = ($i == "index" || $i == "wall_s"); next }
           { row = ""; for (i = 1; i <= NF; i++) if (!drop[i]) row = row "," $i; print row }' "$1" | sort
}
[[ "$(strip "$work/mpi/evaluations.csv")" == "$(strip "$work/one/evaluations.csv")" ]] ||
  fail "evaluations.csv differs between 2 ranks and one process"
# The worker rank did evaluate (the summary counts its runs).
n=$(sed -n 's/^\([0-9]*\) of the SLAM runs ran on the 1 worker ranks$/\1/p' "$work/mpi.txt")
[[ -n "$n" && "$n" -gt 0 ]] || fail "no SLAM run ran on the worker rank: $(tail -3 "$work/mpi.txt")"

# sweep under mpirun: the same table as one process (wall_s is not a result).
sweep=(sweep "${slice[@]}" --vary g=6:20:7 --fix r=2)
"${mpi[@]}" "$bin" "${sweep[@]}" --out "$work/sweep_mpi" > "$work/sweep_mpi.txt" 2>&1 ||
  fail "mpirun sweep failed: $(tail -5 "$work/sweep_mpi.txt")"
"$bin" "${sweep[@]}" --out "$work/sweep_one" --jobs 2 --quiet > /dev/null 2>&1 || fail "single-process sweep failed"
[[ -s "$work/sweep_mpi/sweep.csv" && "$(strip "$work/sweep_mpi/sweep.csv")" == "$(strip "$work/sweep_one/sweep.csv")" ]] ||
  fail "sweep.csv differs between 2 ranks and one process"
n=$(sed -n 's/^\([0-9]*\) of the SLAM runs ran on the 1 worker ranks$/\1/p' "$work/sweep_mpi.txt")
[[ -n "$n" && "$n" -gt 0 ]] || fail "no sweep run ran on the worker rank: $(tail -3 "$work/sweep_mpi.txt")"

# Errors: a clear message and a non-zero exit from every rank, no hang.
expect_error() {  # PATTERN CMD...
  local pattern=$1; shift
  local out; out=$("$@" 2>&1); local rc=$?
  [[ $rc -ne 0 && $rc -ne 124 ]] || fail "expected a prompt failure (rc $rc): $*"
  grep -q -- "$pattern" <<<"$out" || fail "expected '$pattern' from: $* (got: $out)"
}
expect_error "cannot open" "${mpi[@]}" "$bin" optimize "$work/missing.clf" --out "$work/x1" --quiet
touch "$work/afile"
expect_error "cannot create output folder" "${mpi[@]}" "$bin" optimize --out "$work/afile/sub" "${small[@]}"
expect_error "already holds an optimisation" "${mpi[@]}" "$bin" optimize --out "$work/mpi" "${small[@]}"
expect_error "cannot open" "${mpi[@]}" "$bin" sweep "$work/missing.clf" --vary g=6:8 --out "$work/x2" --quiet
expect_error "different settings" "${mpi[@]}" "$bin" optimize --resume "$work/mpi" --seed 6 --population 8 --generations 2 --divisions 3

cli_test_end
