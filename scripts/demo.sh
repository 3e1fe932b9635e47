#!/usr/bin/env bash
# The README's main job: install, build, write the embedded sample route and
# convert it. Outputs land in out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
./build/railodd sample -o out/sample
# The sample is drawn with 0.3 m node scatter (sample_route_truth.json).
./build/railodd convert out/sample/sample_route.osm -o out/sample_route --dem out/sample/sample_route_dem.tif --node-noise 0.3 --estimate-cant \
  --debug-outputs
./build/railodd validate out/sample_route/map.xodr --netconvert
./build/railodd profile out/sample_route --odd-spec data/odd/example_odd_spec.yaml || [ $? -eq 5 ] # exit 5: outside the ODD (the industrial spur)
./build/railodd scenarios --map out/sample_route -o out/scenarios --odd-spec data/odd/example_odd_spec.yaml --quiet
# Play them where an OpenSCENARIO player (esmini) is at hand: ../shared/tools or the PATH.
if [ -x ../shared/tools/esmini/bin/esmini ] || command -v esmini >/dev/null || [ -n "${RAILODD_ESMINI:-}" ]; then
  ./build/railodd play out/scenarios --plot --quiet
else
  echo "no esmini: scenarios not played (railodd play --player PATH)"
fi
# The route on one page, with the scenarios, their play results and the spec check.
./build/railodd report out/sample_route --scenarios out/scenarios --odd-spec data/odd/example_odd_spec.yaml
echo
echo "outputs:"
echo "  sample route (OSM, DEM, ground truth): $(pwd)/out/sample/"
echo "  the route on one page (open in a browser): $(pwd)/out/sample_route/report.html"
echo "  conversion (map.xodr, odd_profile.json/.geojson/.csv, report.json; with --debug-outputs ingest.geojson, geometry.geojson, roads.geojson): $(pwd)/out/sample_route/"
echo "  scenarios (ID.xosc, ID.behavior.yaml, catalogs/, distributions/, manifest.json, coverage.json/.txt; play.json/.txt, play/ when played): $(pwd)/out/scenarios/"
