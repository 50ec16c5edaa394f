#!/usr/bin/env bash
# Builds the library and its tests with AddressSanitizer and UndefinedBehaviorSanitizer (GCC, in
# build-asan/) and runs the io, metrics, nsga3 and optim test executables and the fuzz corpus replays
# (fuzz/CMakeLists.txt) under them.
#
#   bash scripts/sanitize.sh            # io, metrics, nsga3 and optim suites, fuzz corpus replays
#   bash scripts/sanitize.sh REGEX      # the CTest tests matching REGEX (ctest -R REGEX)
#
# Any sanitizer report fails its test (halt_on_error, leaks included). Exit status 0 when the run
# is clean. Tests that need the shared datasets skip themselves when those are absent.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh >/dev/null

jobs="${SANITIZE_BUILD_JOBS:-$(nproc)}"
build=build-asan
regex="${1:-}"
start=$(date +%s)

# -O1, as the sanitizers' documentation advises: it compiles about a third faster than -O2 and
# keeps the stack traces exact; the line tables come from SLAMTUNE_SANITIZE (-g1). Unity sources
# (SLAMTUNE_UNITY), as in build/: the suites compile in far less time.
if [[ ! -f "$build/CMakeCache.txt" ]]; then
  nice cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -DNDEBUG" \
    -DSLAMTUNE_SANITIZE=ON -DSLAMTUNE_UNITY=ON \
    -DSLAMTUNE_BUILD_BENCH=OFF -DSLAMTUNE_WITH_MPI=OFF >/dev/null
fi
if [[ -z "$regex" ]]; then
  nice cmake --build "$build" --target io_tests metrics_tests nsga3_tests optim_tests fuzz_all -j"$jobs"
  # Test names are the GoogleTest names; the executables carry them as CTest labels.
  select=(-L '^(io|metrics|nsga3|optim|fuzz)$')
else
  nice cmake --build "$build" -j"$jobs"
  select=(-R "$regex")
fi

export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:halt_on_error=1:abort_on_error=0}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
set +e
nice ctest --test-dir "$build" "${select[@]}" --output-on-failure -j"$jobs" --timeout 1800
status=$?
set -e
echo "sanitize.sh: $(( $(date +%s) - start )) s; $([[ $status -eq 0 ]] && echo clean || echo 'FAILED (see above)')"
exit $status
