#!/usr/bin/env bash
# The README's main job: install, build, write the embedded sample route and
# convert it. Outputs land in out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
./build/railodd sample -o out/sample
# The sample is drawn with 0.3 m node scatter (sample_route_truth.json).
./build/railodd convert out/sample/sample_route.osm -o out/sample_route --dem out/sample/sample_route_dem.tif --node-noise 0.3 --estimate-cant
./build/railodd validate out/sample_route/map.xodr --netconvert
./build/railodd profile out/sample_route --odd-spec data/odd/example_odd_spec.yaml || [ $? -eq 5 ] # exit 5: outside the ODD (the industrial spur)
./build/railodd scenarios --map out/sample_route -o out/scenarios --odd-spec data/odd/example_odd_spec.yaml --quiet
echo
echo "outputs:"
echo "  sample route (OSM, DEM, ground truth): $(pwd)/out/sample/"
echo "  conversion (map.xodr, odd_profile.json/.geojson/.csv, report.json, ingest.geojson, geometry.geojson, roads.geojson): $(pwd)/out/sample_route/"
echo "  scenarios (ID.xosc, ID.behavior.yaml, catalogs/, distributions/, manifest.json, coverage.json/.txt): $(pwd)/out/scenarios/"
