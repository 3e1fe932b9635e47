#!/usr/bin/env bash
# The HTML report of one extract: how large the page is, how long
# `railodd report` takes and how much memory, and how soon the page is
# interactive in headless Chromium. A benchmark, not a test.
#
#   bench/report_page.sh [OSM_FILE] [RUNS]
#
# OSM_FILE  default ../shared/data/osm/orr_cologne-railway.osm.pbf
# RUNS      runs of `railodd report` and of the browser load (default 3);
#           medians are printed.
# "Interactive" is check_report.mjs's ready_ms: from navigation start until
# the page has drawn the map, the charts and the tables and set
# body[data-ready] (the map and the charts answer input from then on). The
# browser check itself (counts, no console errors, no requests) runs too.
set -euo pipefail
cd "$(dirname "$0")/.."
osm="${1:-../shared/data/osm/orr_cologne-railway.osm.pbf}"
runs="${2:-3}"
railodd="${RAILODD:-build/railodd}"
work="$(mktemp -d /tmp/railodd-report-bench.XXXXXX)"
median() { sort -n | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }

"$railodd" convert "$osm" -o "$work/map" --no-report >/dev/null
wall=(); rss=(); ready=()
for i in $(seq "$runs"); do
  /usr/bin/time -f "%e %M" -o "$work/time" "$railodd" report "$work/map" -o "$work/report.html" >/dev/null
  read -r w m <"$work/time"
  wall+=("$w"); rss+=("$m")
done
for i in $(seq "$runs"); do
  out="$(node tests/report/check_report.mjs "$work/report.html" --map "$work/map" --timing)"
  ready+=("$(echo "$out" | head -1 | sed -E 's/.*"ready_ms":([0-9]+).*/\1/')")
  echo "$out" | tail -1
done
bytes=$(stat -c %s "$work/report.html")
echo "extract: $osm"
echo "page: $bytes bytes ($(awk -v b="$bytes" 'BEGIN {printf "%.1f", b / 1048576}') MiB)"
echo "railodd report: median $(printf '%s\n' "${wall[@]}" | median) s, peak RSS $(printf '%s\n' "${rss[@]}" | median) KB (runs: ${wall[*]})"
echo "interactive in headless Chromium: median $(printf '%s\n' "${ready[@]}" | median) ms (runs: ${ready[*]})"
echo "work folder: $work"
