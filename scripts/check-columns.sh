#!/usr/bin/env bash
# Checks the C++ sources against .clang-format's column limit (120): prints FILE:LINE for each
# longer line and exits 1 if there is one. clang-format fixes them:
#   clang-format -i --lines=N:N FILE
set -euo pipefail
cd "$(dirname "$0")/.."
limit=$(sed -n 's/^ColumnLimit: *//p' .clang-format)
long=$(grep -rn --include='*.cc' --include='*.h' ".\{$((limit + 1)),\}" src bench fuzz | cut -d: -f1,2 || true)
if [[ -n $long ]]; then
  echo "$long"
  echo "check-columns: $(wc -l <<< "$long") lines over $limit columns" >&2
  exit 1
fi
