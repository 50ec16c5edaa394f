#!/usr/bin/env bash
# Installs what slamtune needs, builds it and runs the main job: `slamtune optimize`. With no
# argument it runs on the built-in world office-jump, whose odometry reports 1 m of travel that
# did not happen: at slam_karto's defaults the sequential match cannot follow and walls come out
# doubled; the optimisation sees the break, searches the front-end parameters and repairs the map
# (about 2 minutes on 2 cores). Arguments are passed to `slamtune optimize` (e.g. a recording and
# --out DIR). Run again, it continues (or reports) the same folder.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
# The same configuration as scripts/test.sh, so that the test command rebuilds nothing this built.
bash scripts/configure.sh >/dev/null
cmake --build build -j"$(nproc)" --target slamtune
if [ $# -eq 0 ]; then
  if [ -e runs/office-jump/run.sqlite ]; then
    set -- --resume runs/office-jump
  else
    set -- --world office-jump --out runs/office-jump
  fi
fi
./build/slamtune optimize "$@"
