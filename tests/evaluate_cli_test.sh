#!/usr/bin/env bash
# End-to-end test of `slamtune evaluate` on tiny maps written here with printf.
# Usage: evaluate_cli_test.sh SLAMTUNE_BINARY DATASETS_DIR   (datasets are not needed)
# Exit 0 = pass, 1 = fail, 77 = skip (binary missing).
set -u
source "$(dirname "$0")/lib.sh"
cli_test_begin evaluate_cli_test "$@"

# A 12 x 10 map: one room with walls on columns 1..10 and rows 1..8 (10 x 8 outline = 32
# wall cells), free inside, unknown around. Bytes: wall, free, unknown, then optional gap.
write_room() {  # PATH WALL FREE UNKNOWN GAP(0|1)
  local path=$1 wall=$2 free=$3 unknown=$4 gap=$5 r c
  {
    printf 'P5\n12 10\n255\n'
    for ((r = 0; r < 10; r++)); do
      for ((c = 0; c < 12; c++)); do
        if ((r < 1 || r > 8 || c < 1 || c > 10)); then
          printf "$unknown"
        elif ((gap == 1 && r == 1 && c == 5)); then
          printf "$free"
        elif ((r == 1 || r == 8 || c == 1 || c == 10)); then
          printf "$wall"
        else
          printf "$free"
        fi
      done
    done
  } >"$path"
}
write_room "$work/room.pgm" '\000' '\376' '\315' 0
write_room "$work/open.pgm" '\000' '\376' '\315' 1
mkdir -p "$work/img"
write_room "$work/img/negated.pgm" '\377' '\000' '\200' 0
printf 'image: img/negated.pgm\nresolution: 0.1\norigin: [-1.0, 2.0, 0.0]\nnegate: 1\noccupied_thresh: 0.65\nfree_thresh: 0.196\n' \
  >"$work/negated.yaml"

# Prints the value of "key" in a flat JSON object printed one key per line.
json_value() { grep -o "\"$1\": [^,]*" | head -n 1 | sed 's/.*: //'; }

# 1. Table output.
if out=$("$bin" evaluate "$work/room.pgm" 2>"$work/err"); then
  echo "$out" | grep -q 'corner_px' || fail "table has no header: $out"
  echo "$out" | grep -q 'room.pgm .*12x10' || fail "table has no row for room.pgm: $out"
else
  fail "evaluate room.pgm exited non-zero: $(cat "$work/err")"
fi

# 2. JSON with the known answers for one closed room.
json=$("$bin" evaluate "$work/room.pgm" --json) || fail "evaluate --json exited non-zero"
[[ $(echo "$json" | json_value occupied_cells) == 32 ]] || fail "occupied_cells != 32: $json"
[[ $(echo "$json" | json_value occupied_ratio) == 0.26666666666666666 ]] || fail "occupied_ratio != 32/120: $json"
[[ $(echo "$json" | json_value enclosed_areas) == 1 ]] || fail "enclosed_areas != 1: $json"
[[ $(echo "$json" | json_value contours) == 2 ]] || fail "contours != 2: $json"
[[ $(echo "$json" | json_value corners) == 4 ]] || fail "corners != 4: $json"
for key in map occupied_ratio_known corner_pixels; do
  echo "$json" | grep -q "\"$key\":" || fail "JSON lacks $key"
done

# 3. A one-cell gap opens the room; the negated YAML reads as the same room.
open=$("$bin" evaluate "$work/open.pgm" --json) || fail "evaluate open.pgm exited non-zero"
[[ $(echo "$open" | json_value enclosed_areas) == 0 ]] || fail "gap room still enclosed: $open"
negated=$("$bin" evaluate "$work/negated.yaml" --json) || fail "evaluate negated.yaml exited non-zero"
for key in occupied_cells corner_pixels corners enclosed_areas contours; do
  [[ $(echo "$negated" | json_value $key) == $(echo "$json" | json_value $key) ]] ||
    fail "negated YAML differs in $key: $negated"
done
[[ $(echo "$negated" | json_value resolution) == 0.1 ]] || fail "YAML resolution not used: $negated"

# 4. Several maps, and overlays in --debug-dir.
many=$("$bin" evaluate "$work/room.pgm" "$work/open.pgm" "$work/negated.yaml" --json --debug-dir "$work/debug") ||
  fail "evaluate of three maps exited non-zero"
[[ $(echo "$many" | grep -c '"map":') == 3 ]] || fail "expected 3 JSON entries: $many"
for name in room open negated; do
  png="$work/debug/$name.quality.png"
  [[ -s "$png" && $(head -c 4 "$png" | tail -c 3) == PNG ]] || fail "no overlay PNG $png"
done

# 5. Bad input: one line on stderr naming the problem, non-zero exit, nothing on stdout.
expect_error() {  # PATTERN ARGS...
  local pattern=$1
  shift
  if "$bin" evaluate "$@" >"$work/out" 2>"$work/err"; then
    fail "evaluate $* succeeded"
    return
  fi
  [[ $(wc -l <"$work/err") == 1 ]] || fail "evaluate $*: expected one error line, got: $(cat "$work/err")"
  grep -q -- "$pattern" "$work/err" || fail "evaluate $*: error lacks '$pattern': $(cat "$work/err")"
  [[ ! -s "$work/out" ]] || fail "evaluate $*: printed output despite the error"
}
printf 'not an image\n' >"$work/text.pgm"
printf 'resolution: 0.05\norigin: [0, 0, 0]\noccupied_thresh: 0.65\nfree_thresh: 0.196\n' >"$work/noimage.yaml"
printf 'image: gone.pgm\nresolution: 0.05\norigin: [0, 0, 0]\noccupied_thresh: 0.65\nfree_thresh: 0.196\n' \
  >"$work/gone.yaml"
expect_error "missing.pgm: cannot open map image: no such file" "$work/missing.pgm"
expect_error "text.pgm: not an image" "$work/text.pgm"
expect_error "noimage.yaml: missing required key 'image'" "$work/noimage.yaml"
expect_error "gone.pgm: cannot open map image (named by" "$work/gone.yaml"
expect_error "harris_k = 0.3: must be in (0, 0.25)" "$work/room.pgm" --harris-k 0.3
expect_error "blur_size = 2: must be odd" "$work/room.pgm" "$work/room.pgm" --blur-size 2
expect_error "missing.pgm" "$work/room.pgm" "$work/missing.pgm" --json

cli_test_end
