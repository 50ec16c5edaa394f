#!/usr/bin/env bash
# Checks that every C++ source (src, bench, fuzz) is formatted as .clang-format says: prints the
# files that are not and exits 1 if there is one. Fix them with
#   clang-format -i FILE...        (or `git clang-format` for the lines of a change)
# Uses Debian 12's clang-format (14), which scripts/install-deps.sh installs: another version may
# format some constructs differently.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v clang-format > /dev/null || { echo "check-format: clang-format not installed (scripts/install-deps.sh)" >&2; exit 77; }
files=()
while IFS= read -r -d '' file; do files+=("$file"); done < <(find src bench fuzz \( -name '*.cc' -o -name '*.h' \) -print0 | sort -z)
# One clang-format for all files; each file off gets lines "FILE:LINE:COL: error: code should be clang-formatted".
report=$(clang-format --dry-run -Werror "${files[@]}" 2>&1) && exit 0
off=$(sed -n 's/^\([^:]*\):[0-9]*:[0-9]*: error: code should be clang-formatted.*/\1/p' <<< "$report" | sort -u)
[[ -n "$off" ]] || { echo "check-format: clang-format failed: $(head -3 <<< "$report")" >&2; exit 1; }
echo "$off"
echo "check-format: $(wc -l <<< "$off") files not formatted as .clang-format says (clang-format -i FILE)" >&2
exit 1
