#!/usr/bin/env bash
# Installs what slamtune needs, builds it (with tests and benchmarks) and runs the whole test suite,
# then builds the io, metrics, nsga3 and optim suites and the fuzz corpus replays with
# AddressSanitizer + UndefinedBehaviorSanitizer and runs them (scripts/sanitize.sh).
# This is the README's test command and what CI runs.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DSLAMTUNE_WARNINGS_AS_ERRORS=ON
cmake --build build -j"$(nproc)"
ctest --test-dir build --output-on-failure -j"$(nproc)" --timeout 900
bash scripts/sanitize.sh
