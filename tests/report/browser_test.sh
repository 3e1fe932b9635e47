#!/usr/bin/env bash
# The sample route's report.html in headless Chromium: the sample converted,
# its scenarios generated (and played where esmini is at hand), the page
# written by `railodd report`, then opened and checked by check_report.mjs
# (console errors, network requests, what is drawn against the map folder).
# With MODE `relation`, a real extract instead: the Lauf extract converted
# along the S1 route relation (one chain, the relation's length), the page
# written by convert itself.
# Usage: browser_test.sh RAILODD WORKDIR [sample|relation]. Exit 77 (skip)
# without node, chromium or the installed puppeteer-core, and for `relation`
# without ../shared/data.
set -euo pipefail
railodd="$1"
work="$2"
mode="${3:-sample}"
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(cd "$here/../.." && pwd)"
chromium="${CHROMIUM:-$(command -v chromium || command -v chromium-browser || true)}"
if ! command -v node >/dev/null || [ -z "$chromium" ] || [ ! -d "$repo/report/web/node_modules/puppeteer-core" ]; then
  echo "SKIP: node, chromium or report/web/node_modules/puppeteer-core is missing (scripts/install-deps.sh installs them)"
  exit 77
fi
rm -rf "$work"
mkdir -p "$work"
if [ "$mode" = relation ]; then
  lauf="${RAILODD_SHARED_DATA:-$repo/../shared/data}/osm/gh_lauf-200115.osm.pbf"
  if [ ! -f "$lauf" ]; then
    echo "SKIP: $lauf is absent (../shared/data)"
    exit 77
  fi
  "$railodd" convert "$lauf" -o "$work/map" --relation 539311 --road-corridor 0 --no-timings >/dev/null
  CHROMIUM="$chromium" node "$here/check_report.mjs" --map "$work/map" "$work/map/report.html"
  exit 0
fi
"$railodd" sample -o "$work/sample" >/dev/null
"$railodd" convert "$work/sample/sample_route.osm" -o "$work/map" --dem "$work/sample/sample_route_dem.tif" \
  --node-noise 0.3 --estimate-cant --no-timings --debug-outputs >/dev/null
"$railodd" scenarios --map "$work/map" -o "$work/scen" --odd-spec "$repo/data/odd/example_odd_spec.yaml" --quiet >/dev/null
esmini="$repo/../shared/tools/esmini/bin/esmini"
if [ -x "$esmini" ]; then
  "$railodd" play "$work/scen" --player "$esmini" --jobs 2 --quiet >/dev/null || true # failures are shown in the page
fi
"$railodd" report "$work/map" --scenarios "$work/scen" --odd-spec "$repo/data/odd/example_odd_spec.yaml" \
  -o "$work/report.html"
CHROMIUM="$chromium" node "$here/check_report.mjs" --map "$work/map" --scenarios "$work/scen" "$work/report.html"
