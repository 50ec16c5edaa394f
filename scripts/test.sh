#!/usr/bin/env bash
# Installs what slamtune needs, builds it (with tests and benchmarks) and runs the tests: the CLI
# tests, the house checks and the common, sim, slam, report and tune unit suites in the release build;
# then the io, metrics, nsga3 and optim unit suites and the fuzz corpus replays built with
# AddressSanitizer + UndefinedBehaviorSanitizer (scripts/sanitize.sh). Each suite is compiled and
# run once.
# This is the README's test command and what CI runs.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/configure.sh
cmake --build build -j"$(nproc)"
ctest --test-dir build --output-on-failure -j"$(nproc)" --timeout 900
bash scripts/sanitize.sh
