#!/usr/bin/env bash
# Configures build/, the one build folder of the README's two commands (scripts/main.sh,
# scripts/test.sh) and of scripts/bench.sh: Release, warnings as errors, every unit-test suite but
# those the test command runs under the sanitizers instead (scripts/sanitize.sh), and unity sources
# (SLAMTUNE_UNITY: a whole build takes far less compile time). The same configuration everywhere,
# so that one command never recompiles what another built.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DSLAMTUNE_WARNINGS_AS_ERRORS=ON \
  -DSLAMTUNE_TEST_SUITES="common;sim;slam;report;tune" -DSLAMTUNE_UNITY=ON "$@"
