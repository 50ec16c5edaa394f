#!/usr/bin/env bash
# Fuzzes one reader of outside input with libFuzzer (clang, AddressSanitizer and
# UndefinedBehaviorSanitizer).
#
#   bash scripts/fuzz.sh TARGET SECONDS   # e.g. scripts/fuzz.sh mcap 300
#   bash scripts/fuzz.sh --list           # the targets
#
# Configures and builds build-fuzz/ (clang++, -DSLAMTUNE_FUZZ=ON), then runs fuzz_TARGET for
# SECONDS on a copy of fuzz/corpus/TARGET (the committed seeds stay as they are). Inputs that
# crash, leak, hit undefined behaviour, time out or throw anything but InputError are written to
# runs/fuzz/TARGET/ (crash-*, leak-*, timeout-*, oom-*), with the log in runs/fuzz/TARGET/fuzz.log;
# the grown corpus is kept in runs/fuzz/TARGET/corpus. Exit status 0 when nothing was found.
# Replay a finding: build-fuzz/fuzz/fuzz_TARGET runs/fuzz/TARGET/crash-...
set -euo pipefail
cd "$(dirname "$0")/.."

corpus_root=fuzz/corpus
list_targets() { ls "$corpus_root"; }

if [[ $# -eq 1 && "$1" == "--list" ]]; then
  list_targets
  exit 0
fi
if [[ $# -ne 2 || ! "$2" =~ ^[0-9]+$ ]]; then
  echo "usage: scripts/fuzz.sh TARGET SECONDS | --list" >&2
  exit 2
fi
target="$1"
seconds="$2"
if [[ ! -d "$corpus_root/$target" ]]; then
  echo "fuzz.sh: unknown target '$target'; targets: $(list_targets | tr '\n' ' ')" >&2
  exit 2
fi
# What the build needs, and Debian's clang for libFuzzer.
bash scripts/install-deps.sh >/dev/null
if ! command -v clang++ >/dev/null; then
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends clang >/dev/null
fi

jobs="${FUZZ_BUILD_JOBS:-2}"
build=build-fuzz
if [[ ! -f "$build/CMakeCache.txt" ]]; then
  nice cmake -S . -B "$build" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DSLAMTUNE_FUZZ=ON -DSLAMTUNE_BUILD_TESTS=OFF -DSLAMTUNE_BUILD_BENCH=OFF -DSLAMTUNE_WITH_MPI=OFF >/dev/null
fi
nice cmake --build "$build" --target "fuzz_$target" -j"$jobs" >/dev/null

out="runs/fuzz/$target"
mkdir -p "$out"
rm -rf "$out/corpus"
cp -r "$corpus_root/$target" "$out/corpus"
touch "$out/.start"  # findings of earlier runs stay, but only this run's are counted

# Leaks are reported per input; a reader must not take more than 2 GB or 10 s on any input.
set +e
ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}" \
UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}" \
nice "$build/fuzz/fuzz_$target" "$out/corpus" \
  -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
  -artifact_prefix="$out/" -print_final_stats=1 >"$out/fuzz.log" 2>&1
status=$?
set -e

grep -E '^stat::(number_of_executed_units|peak_rss_mb)' "$out/fuzz.log" || true
findings=$(find "$out" -maxdepth 1 -type f -newer "$out/.start" \
  \( -name 'crash-*' -o -name 'leak-*' -o -name 'timeout-*' -o -name 'oom-*' \) | wc -l)
if [[ $status -ne 0 || $findings -ne 0 ]]; then
  echo "fuzz.sh: $target: FOUND $findings input(s) in $out/ (exit $status); see $out/fuzz.log"
  exit 1
fi
echo "fuzz.sh: $target: clean for ${seconds} s ($out/fuzz.log)"
