#!/usr/bin/env bash
# Builds the libFuzzer harnesses (clang, ASan + UBSan) into build-san/ and
# runs each for SECONDS (default 60) on a corpus seeded from the project's
# own files. Prints executions and coverage per harness; exits 1 when any
# harness found a crash, leak, timeout or sanitizer report (the input is in
# build-san/artifacts/). Usage: fuzz/run.sh [SECONDS] [HARNESS...]
set -euo pipefail
cd "$(dirname "$0")/.."
secs="${1:-60}"
shift || true
harnesses=("$@")
if [ ${#harnesses[@]} -eq 0 ]; then
  harnesses=(fuzz_tag_values fuzz_yaml_loaders fuzz_xodr_reader fuzz_polygon fuzz_osm_ingest fuzz_field_mapping
             fuzz_routes_file fuzz_convert fuzz_profile_json)
fi
b=build-san
bash scripts/build_san.sh "${harnesses[@]}"
mkdir -p "$b/artifacts"

seed() { # seed NAME FILE [PREFIX-BYTE]
  local dir="$b/corpus/$1"
  mkdir -p "$dir"
  local out="$dir/seed-$(basename "$2")${3:+-$3}"
  if [ -n "${3:-}" ]; then { printf "\\x$3"; cat "$2"; } >"$out"; else cp "$2" "$out"; fi
}
seeds="$b/seeds"
mkdir -p "$seeds"
i=0
for v in 160 "60 mph" "RU:urban" "15000;25000" "1435;1000" "1520" "16.7" "yes" "no" "contact_line;rail" \
         "GSM-R" "DE-ESO:ks" "railway:signal:main:form" "light" "12.4" "full" "main" "siding" "both" "backward"; do
  printf '%s' "$v" >"$seeds/tag$i"; seed fuzz_tag_values "$seeds/tag$i"; i=$((i + 1))
done
seed fuzz_yaml_loaders data/odd/railway_odd.yaml 00
seed fuzz_yaml_loaders data/odd/example_odd_spec.yaml 01
seed fuzz_yaml_loaders data/scenario/assets.yaml 02
seed fuzz_yaml_loaders data/scenario/templates.yaml 03
printf '{"type":"Polygon","coordinates":[[[10,48],[11,48],[11,49],[10,48]]]}' >"$seeds/poly.geojson"
printf '{"type":"FeatureCollection","features":[{"type":"Feature","geometry":{"type":"MultiPolygon","coordinates":[[[[10,48],[11,48],[11,49],[10,48]]]]},"properties":{}}]}' >"$seeds/multi.geojson"
seed fuzz_polygon "$seeds/poly.geojson"
seed fuzz_polygon "$seeds/multi.geojson"
printf 'n1 v1 x10.0 y48.0\nn2 v1 x10.01 y48.0\nn3 v1 x10.02 y48.001\nw1 v1 Trailway=rail,maxspeed=100 Nn1,n2,n3\n' >"$seeds/track.opl"
seed fuzz_osm_ingest "$seeds/track.opl" 01
if [ -x build/railodd ]; then # the sample route, its map and (cut) its OSM
  build/railodd sample -o "$seeds/sample" >/dev/null
  build/railodd convert "$seeds/sample/sample_route.osm" -o "$seeds/map" --no-report --road-corridor 0 >/dev/null
  seed fuzz_xodr_reader "$seeds/map/map.xodr"
  head -c 60000 "$seeds/sample/sample_route.osm" >"$seeds/sample_head.osm"
  seed fuzz_osm_ingest "$seeds/sample_head.osm" 00
fi
# convert: flag byte (bit 0 OPL, 1 report, 2 cant, 3 --from A --to B) + OSM
seed fuzz_convert "$seeds/track.opl" 01
seed fuzz_convert "$seeds/track.opl" 07
{
  printf '<?xml version="1.0"?>\n<osm version="0.6">\n'
  awk 'BEGIN { for (i = 1; i <= 40; i++)
    printf "<node id=\"%d\" version=\"1\" lat=\"%.7f\" lon=\"%.7f\"/>\n", i, 48 + i * 0.0002 + i * i * 0.000002, 10 + i * 0.0003 }'
  printf '<node id="100" version="1" lat="48.0042" lon="10.0030"><tag k="railway" v="station"/><tag k="name" v="A"/></node>\n'
  printf '<node id="101" version="1" lat="48.0110" lon="10.0110"><tag k="railway" v="station"/><tag k="name" v="B"/></node>\n'
  printf '<node id="102" version="1" lat="48.0010" lon="10.0000"/><node id="103" version="1" lat="48.0050" lon="10.0065"/>\n'
  printf '<way id="1" version="1">'; for i in $(seq 1 25); do printf '<nd ref="%d"/>' "$i"; done
  printf '<tag k="railway" v="rail"/><tag k="maxspeed" v="120"/><tag k="electrified" v="contact_line"/></way>\n'
  printf '<way id="2" version="1">'; for i in $(seq 25 40); do printf '<nd ref="%d"/>' "$i"; done
  printf '<tag k="railway" v="rail"/><tag k="bridge" v="yes"/><tag k="railway:cant" v="80"/></way>\n'
  printf '<way id="3" version="1"><nd ref="102"/><nd ref="10"/><nd ref="103"/><tag k="highway" v="secondary"/></way>\n'
  printf '</osm>\n'
} >"$seeds/small_network.osm"
seed fuzz_convert "$seeds/small_network.osm" 00
seed fuzz_convert "$seeds/small_network.osm" 0e
printf 'layer: gleisachsen\nid_field: gid\ncrs: EPSG:25832\ntags:\n  railway: rail\n  maxspeed: {field: vmax, default: "100"}\n  electrified:\n    field: elek\n    values: {"1": contact_line, "0": "no"}\n  gauge: "1435"\n' >"$seeds/mapping.yaml"
seed fuzz_field_mapping "$seeds/mapping.yaml"
printf 'defaults:\n  estimate_cant: true\n  scenarios: {strategy: pairwise, count: 4}\nroutes:\n  - id: whole\n    input: a.osm\n  - id: west\n    input: a.osm\n    bbox: [10.14, 48.29, 10.20, 48.31]\n  - id: lost\n    input: b.osm\n    scenarios: false\n' >"$seeds/routes.yaml"
seed fuzz_routes_file "$seeds/routes.yaml"
printf '<OpenDRIVE><header revMajor="1" revMinor="7"/><road id="1" length="10" junction="-1"><planView><geometry s="0" x="0" y="0" hdg="0" length="10"><line/></geometry></planView></road></OpenDRIVE>' >"$seeds/tiny.xodr"
seed fuzz_xodr_reader "$seeds/tiny.xodr"
if [ -f "$seeds/map/odd_profile.json" ]; then # the sample route's profile (format 2); a format 1 one below
  seed fuzz_profile_json "$seeds/map/odd_profile.json"
fi
printf '{"railodd":{"format":"odd_profile","format_version":1},"taxonomy":{"name":"t"},"route":{"length_m":10},"elements":[{"odd_element":"A/B","id":"a.b","attributes":{"x":1.5,"y":"z","w":true},"road_id":"1","s_start":0,"s_end":10,"track":0,"chainage_start":0,"chainage_end":10,"point":false,"osm_ids":["way:1"],"source":"osm","reversed":true}],"unparsed":[],"summary":{}}' >"$seeds/profile_v1.json"
seed fuzz_profile_json "$seeds/profile_v1.json"
# Every input a harness once failed on (fuzz/regressions/HARNESS/), fixed since:
# seeded, so a regression is met in the first seconds of a run.
for dir in fuzz/regressions/*/; do
  h=$(basename "$dir")
  for f in "$dir"*; do seed "$h" "$f"; done
done

status=0
printf '%-20s %12s %8s %8s %s\n' harness executions cov ft result
for h in "${harnesses[@]}"; do
  log="$b/artifacts/$h.log"
  if "$b/fuzz/$h" "$b/corpus/$h" -max_total_time="$secs" -timeout=25 -rss_limit_mb=4096 -close_fd_mask=1 -print_final_stats=1 \
       -artifact_prefix="$b/artifacts/$h-" >"$log" 2>&1; then
    result=ok
  else
    result="FOUND (see $log)"
    status=1
  fi
  execs=$(grep -oE 'stat::number_of_executed_units: *[0-9]+' "$log" | grep -oE '[0-9]+$' || echo "?")
  cov=$(grep -oE 'cov: [0-9]+' "$log" | tail -1 | grep -oE '[0-9]+' || echo "?")
  ft=$(grep -oE 'ft: [0-9]+' "$log" | tail -1 | grep -oE '[0-9]+' || echo "?")
  printf '%-20s %12s %8s %8s %s\n' "$h" "$execs" "$cov" "$ft" "$result"
done
exit $status
