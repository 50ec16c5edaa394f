# The set-up every end-to-end CLI test (tests/*_cli_test.sh) shares; each script sources it first:
#
#   source "$(dirname "$0")/lib.sh"
#   cli_test_begin fault_cli_test "$@" -- python3   # NAME, the script's arguments, then the commands it needs
#   ... checks, each failing one calls: fail "what went wrong"
#   cli_test_end                                    # exit 1 after any failure, else "NAME: all checks passed"
#
# After cli_test_begin: $bin is the slamtune executable (the first argument), $datasets the shared
# datasets folder (the second, may be absent), $tests_dir this folder (its fixtures/), $work a fresh temporary folder removed at exit, and
# $failures the count of failed checks; a test that leaves a run in the background adds its pid to
# $background, and it is killed at exit. A test skips (exit 77, CTest's SKIP_RETURN_CODE) when the
# binary is not executable or a needed command is not installed (scripts/install-deps.sh installs them).

# cli_test_begin NAME [BINARY [DATASETS]] [-- COMMAND...]
cli_test_begin() {
  test_name=$1
  shift
  bin=""
  datasets=""
  local needed=()
  if [[ $# -gt 0 && $1 != "--" ]]; then bin=$1; shift; fi
  if [[ $# -gt 0 && $1 != "--" ]]; then datasets=$1; shift; fi
  if [[ $# -gt 0 && $1 == "--" ]]; then shift; needed=("$@"); fi
  tests_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
  [[ -n "$bin" ]] || { echo "usage: $test_name.sh SLAMTUNE_BINARY [DATASETS_DIR]" >&2; exit 2; }
  [[ -x "$bin" ]] || { echo "SKIP: $bin is not an executable" >&2; exit 77; }
  local tool
  for tool in "${needed[@]}"; do
    command -v "$tool" > /dev/null || { echo "SKIP: $tool not installed (scripts/install-deps.sh)" >&2; exit 77; }
  done
  work=$(mktemp -d "${TMPDIR:-/tmp}/slamtune_${test_name}.XXXXXX")
  failures=0
  background=()
  trap cli_test_cleanup EXIT
}

cli_test_cleanup() {
  local pid
  for pid in "${background[@]}"; do kill -9 "$pid" 2> /dev/null || true; done
  # Tests of unreadable inputs take permissions away; give them back so that the folder can go.
  chmod -R u+w "$work" 2> /dev/null || true
  rm -rf "$work"
}

fail() {
  echo "FAIL: $*" >&2
  failures=$((failures + 1))
}

# cli_test_end [SUMMARY]: the last line of the test and its exit status.
cli_test_end() {
  if [[ $failures -gt 0 ]]; then
    echo "$test_name: $failures failure(s)" >&2
    exit 1
  fi
  echo "$test_name: all checks passed${1:+ ($1)}"
  exit 0
}

# simulate_world FOLDER WORLD [SIMULATE FLAGS...]: a simulated log of a built-in world in FOLDER
# (FOLDER/WORLD.clf and its relations); a test that cannot simulate cannot go on.
simulate_world() {
  local folder=$1 world=$2
  shift 2
  "$bin" simulate --world "$world" --out "$folder" "$@" > /dev/null 2>&1 || {
    echo "FAIL: slamtune simulate --world $world $*" >&2
    exit 1
  }
}

# office_slice [SCANS]: sets $slice to the arguments of a short log for tests of the plumbing
# (outputs, resume, flags) rather than of the answer: the first SCANS (default 600) scans of the
# simulated office world with its true relations, in $work/office. A SLAM run of it costs about a
# fifth of the whole world's, and it still closes a loop.
office_slice() {
  [[ -s "$work/office/office.clf" ]] || simulate_world "$work/office" office
  slice=("$work/office/office.clf" --relations "$work/office/office.relations" --max-scans "${1:-600}")
}
