#!/usr/bin/env bash
# Installs what slamtune needs, builds it and runs the main job: an optimisation of the loop-closure
# parameters. With no argument it runs on the built-in office world (a few minutes on 2 cores);
# arguments are passed to `slamtune optimize` (e.g. a CARMEN log and --relations FILE).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" --target slamtune
if [ $# -eq 0 ]; then set -- --out runs/office; fi
./build/slamtune optimize "$@"
