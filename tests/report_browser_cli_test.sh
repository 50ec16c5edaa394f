#!/usr/bin/env bash
# report.html of `slamtune optimize` in a real browser: headless Chromium at a 1400 px wide
# window. Fails when the page scrolls sideways or any element reaches past the window, when an
# image does not decode, or when the browser logs a console message, also with every collapsed
# section open. Saves screenshots (the top of the page, the maps, the population, the front end,
# the history and the table of evaluations) to $SLAMTUNE_SCREENSHOTS (default ${TMPDIR:-/tmp}/slamtune_report_screenshots).
#
# The product is not touched: a checker page beside report.html loads it in a 1400 px iframe and
# writes what it measured into its own DOM, which --dump-dom prints. A deliberately broken copy
# of the report must make the checker fail, so a checker that silently measures nothing fails
# the test too.
# Usage: report_browser_cli_test.sh SLAMTUNE_BINARY DATASETS_DIR. Exit 0 pass, 1 fail, 77 skip
# (no Chromium: scripts/install-deps.sh installs the Debian package `chromium`).
set -u
source "$(dirname "$0")/lib.sh"
cli_test_begin report_browser_cli_test "$@"
browser=""
for b in chromium chromium-browser google-chrome; do
  if command -v "$b" > /dev/null 2>&1; then browser=$(command -v "$b"); break; fi
done
[[ -n "$browser" ]] || { echo "SKIP: no chromium (apt-get install chromium, or scripts/install-deps.sh)" >&2; exit 77; }
shots=${SLAMTUNE_SCREENSHOTS:-${TMPDIR:-/tmp}/slamtune_report_screenshots}
mkdir -p "$shots"

# A world whose base configuration breaks in the front end: the report has every section
# (front end, ground truth, candidates). The first 800 scans of its log hold the break and the
# drive after it, at about a third of the whole world's cost.
run="$work/run"
simulate_world "$work/office-jump" office-jump
"$bin" optimize "$work/office-jump/office-jump.clf" --relations "$work/office-jump/office-jump.relations" \
  --max-scans 800 --out "$run" --population 8 --generations 2 --seed 5 --jobs 2 --quiet \
  > "$work/optimize.txt" 2>&1 || { echo "FAIL: optimize failed: $(tail -3 "$work/optimize.txt")" >&2; exit 1; }
[[ -s "$run/report.html" ]] || { echo "FAIL: no report.html" >&2; exit 1; }

# The checker: ?page=NAME selects the page to measure (default report.html); ?shot=ID only shows
# the page scrolled to the element with that id, for a screenshot (headless screenshots ignore
# a URL's #fragment).
cat > "$run/check.html" <<'EOF'
<!DOCTYPE html>
<html><head><meta charset="utf-8"><title>report check</title></head>
<body style="margin:0">
<pre id="result">PENDING</pre>
<iframe id="page" style="width:1400px;height:900px;border:0"></iframe>
<script>
const frame = document.getElementById('page');
const query = new URLSearchParams(location.search);
frame.addEventListener('load', () => {
  if (query.get('shot') !== null) {
    document.getElementById('result').style.display = 'none';
    const target = frame.contentDocument.getElementById(query.get('shot'));
    if (target) target.scrollIntoView();
    return;
  }
  const lines = [];
  const d = frame.contentDocument;
  if (!d || !d.body) {
    lines.push('FAIL cannot read the page');
  } else {
    const root = d.documentElement;
    lines.push((root.scrollWidth <= root.clientWidth ? 'OK' : 'FAIL') +
               ` width: content ${root.scrollWidth} px in a ${root.clientWidth} px viewport`);
    const wide = [...d.body.querySelectorAll('*')].filter(e => e.getBoundingClientRect().right > root.clientWidth + 1);
    for (const e of wide.slice(0, 5)) {
      lines.push(`FAIL wide element <${e.tagName.toLowerCase()}> reaches ${Math.round(e.getBoundingClientRect().right)} px: ` +
                 e.textContent.slice(0, 120).replace(/\s+/g, ' '));
    }
    const images = [...d.images];
    const broken = images.filter(i => !(i.complete && i.naturalWidth > 0));
    lines.push((broken.length === 0 && images.length > 0 ? 'OK' : 'FAIL') + ` images: ${images.length}, broken ${broken.length}`);
    for (const i of broken.slice(0, 5)) lines.push(`FAIL broken image alt="${i.alt}"`);
    // The first screen (1400 x 900): the verdict, the base configuration's map and the recommended map.
    const first = [...d.querySelectorAll('.first img')];
    const verdict = d.querySelector('.verdict');
    const seen = e => e && e.getBoundingClientRect().bottom <= 900 && e.getBoundingClientRect().height > 50;
    lines.push((first.length === 2 && first.every(seen) && verdict && verdict.getBoundingClientRect().bottom <= 900 ?
                'OK' : 'FAIL') +
               ` first screen: verdict and ${first.filter(seen).length} of ${first.length} maps within 900 px`);
  }
  document.getElementById('result').textContent = lines.join('\n') + '\nDONE';
});
frame.src = query.get('page') || 'report.html';
</script>
</body></html>
EOF

# Runs the browser on URL with the given extra options; stdout to OUT, stderr to ERR.
browse() {  # OUT ERR URL OPTIONS...
  local out=$1 err=$2 url=$3; shift 3
  timeout 180 "$browser" --headless --no-sandbox --disable-gpu --hide-scrollbars --no-first-run \
    --user-data-dir="$work/profile" --allow-file-access-from-files --window-size=1400,900 "$@" "$url" \
    > "$out" 2> "$err"
}

# Prints the checker's result for PAGE (a file in the run folder) and the browser's console lines.
check() {  # PAGE NAME
  local page=$1 name=$2
  browse "$work/$name.dom" "$work/$name.err" "file://$run/check.html?page=$page" \
    --virtual-time-budget=15000 --enable-logging=stderr --v=0 --dump-dom
  sed -n '/<pre id="result">/,/DONE/p' "$work/$name.dom" | sed -e 's/<[^>]*>//g' -e 's/&lt;/</g' -e 's/&gt;/>/g'
  grep ':CONSOLE' "$work/$name.err" | sed 's/^.*:CONSOLE[^]]*] /FAIL console: /'
}

# 1. The report itself.
result=$(check report.html report)
echo "$result"
grep -q '^DONE' <<<"$result" || fail "the checker did not finish (browser output: $(tail -3 "$work/report.err"))"
grep -q '^OK width' <<<"$result" || fail "no width measurement"
grep -q '^OK images' <<<"$result" || fail "no image check"
grep -q '^OK first screen' <<<"$result" || fail "the verdict and both maps are not on the first screen"
if grep -q '^FAIL' <<<"$result"; then fail "report.html in a 1400 px window: $(grep '^FAIL' <<<"$result" | head -5)"; fi

# 2. The checker catches a page that overflows, has a broken image and logs an error.
sed 's|</body>|<div style="width:3000px">wide</div><img src="missing.png" alt="missing"><script>console.error("planted error")</script></body>|' \
  "$run/report.html" > "$run/broken.html"
bad=$(check broken.html broken)
grep -q '^FAIL width' <<<"$bad" || fail "the checker missed a 3000 px wide element: $bad"
grep -q '^FAIL broken image alt="missing"' <<<"$bad" || fail "the checker missed a broken image: $bad"
grep -q '^FAIL console: "planted error"' <<<"$bad" || fail "the console error was not seen: $bad"

# 3. With every collapsed section open (the table of evaluations, the slices, the engine
#    settings) the page still fits the window.
sed 's/<details>/<details open>/g' "$run/report.html" > "$run/open.html"
opened=$(check open.html open)
echo "$opened"
grep -q '^OK width' <<<"$opened" || fail "no width measurement with the details open"
if grep -q '^FAIL' <<<"$opened"; then fail "report.html with its details open: $(grep '^FAIL' <<<"$opened" | head -5)"; fi

# 4. Screenshots: the top of the page, the maps, the population, and (details open) the front
#    end with its map, the search's history and the table of evaluations.
for shot in top maps population; do
  browse "$work/shot_$shot.txt" "$work/shot_$shot.err" "file://$run/check.html?shot=$shot" --virtual-time-budget=15000 \
    --run-all-compositor-stages-before-draw --screenshot="$shots/report_$shot.png"
done
for shot in front-end history evaluations; do
  browse "$work/shot_$shot.txt" "$work/shot_$shot.err" "file://$run/check.html?page=open.html&shot=$shot" \
    --virtual-time-budget=15000 --run-all-compositor-stages-before-draw --screenshot="$shots/report_$shot.png"
done
for f in report_top.png report_maps.png report_population.png report_front-end.png report_history.png \
  report_evaluations.png; do
  [[ -s "$shots/$f" ]] && [[ "$(head -c 8 "$shots/$f" | od -An -tx1 | tr -d ' \n')" == "89504e470d0a1a0a" ]] ||
    fail "screenshot $f was not written"
done
echo "screenshots: $shots/report_top.png $shots/report_maps.png $shots/report_population.png" \
  "$shots/report_front-end.png $shots/report_history.png $shots/report_evaluations.png"

cli_test_end
