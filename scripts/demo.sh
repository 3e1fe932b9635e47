#!/usr/bin/env bash
# The README's main job: install, build, write the embedded sample route and
# convert it. Outputs land in out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
./build/railodd sample -o out/sample
./build/railodd convert out/sample/sample_route.osm -o out/sample_route --dem out/sample/sample_route_dem.tif
./build/railodd validate out/sample_route/map.xodr --netconvert
echo
echo "outputs:"
echo "  sample route (OSM, DEM, ground truth): $(pwd)/out/sample/"
echo "  conversion (map.xodr, report.json, ingest.geojson, geometry.geojson, roads.geojson): $(pwd)/out/sample_route/"
