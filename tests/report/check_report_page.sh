#!/usr/bin/env bash
# `lucent report`'s page as a person opens it: a small report, loaded in headless Chromium (Debian's
# package). The page loads, every picture it references exists and loads (the page's own script counts
# broken ones into body[data-broken-images]), and its table has one row per line of results.csv.
# usage: check_report_page.sh LUCENT_EXECUTABLE
set -euo pipefail
lucent=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$lucent" report --quiet --quick --truth model --shape sphere --size-mm 10 --width 24 --height 24 \
  --out "$work/report" >/dev/null
page="$work/report/index.html"
dom=$(chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
  --disable-background-networking --disable-component-update --disable-sync \
  --user-data-dir="$work/profile" --virtual-time-budget=5000 --dump-dom "file://$page" 2>/dev/null)
fail() { echo "FAIL: $*"; exit 1; }
grep -q '</table>' <<<"$dom" || fail "the page did not load: no table in Chromium's DOM"
grep -q 'data-broken-images="0"' <<<"$dom" || fail "pictures failed to load: $(grep -o 'data-broken-images="[^"]*"' <<<"$dom" || echo 'the check did not run')"
pictures=0
for src in $(grep -o 'src="[^"]*"' "$page" | cut -d'"' -f2); do
  [ -s "$work/report/$src" ] || fail "the page references $src, which is missing or empty"
  pictures=$((pictures + 1))
done
[ "$pictures" -gt 0 ] || fail "the page references no pictures"
rows=$(grep -o '<tr class="setting' <<<"$dom" | wc -l)
settings=$(($(wc -l <"$work/report/results.csv") - 1))
[ "$rows" -gt 0 ] && [ "$rows" -eq "$settings" ] || fail "$rows table rows for $settings settings in results.csv"
echo "report page: $rows settings, $pictures pictures, all loaded in Chromium"
