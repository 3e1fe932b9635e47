#!/usr/bin/env bash
# Scale series (issue 7): replicate one OSM extract K times as disjoint
# networks side by side (bench/scale_series.py) and time `railodd convert` on
# each replicated file. A benchmark, not a test.
#
#   bench/scale_series.sh [EXTRACT] [FACTORS]
#
# EXTRACT   .osm.pbf / .osm / .opl / ... (default
#           ../shared/data/osm/gh_lauf-200115.osm.pbf)
# FACTORS   replication factors, space separated (default "1 2 4 10")
#
# Environment:
#   RAILODD        railodd binary (default build/railodd)
#   SCALE_WORK     scratch directory (default a new /tmp/railodd-scale.*, kept:
#                  replicated inputs, outputs, logs)
#   SCALE_JSON     result file (default bench/scale-results/NAME.json)
#   SCALE_MARGIN   degrees between copies (default 0.05)
#   SCALE_BBOX=0   skip the two --bbox runs (factor 1 and the largest factor,
#                  each selecting copy 0 only by --bbox), which show whether
#                  peak memory follows the selected network or the input file
#
# Each run: `/usr/bin/time -f "%e %M %U %S" railodd convert FILE -o OUT
# --no-timings` (wall s, peak RSS KB, user and system CPU s), once per factor;
# the 1-minute load average is recorded before every run. Track km is
# geometry.summary.length_km of OUT/report.json. s/km and MB/km are shown
# relative to factor 1: linear growth keeps them near 1.0.
set -euo pipefail

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
EXTRACT=${1:-$ROOT/../shared/data/osm/gh_lauf-200115.osm.pbf}
FACTORS=${2:-"1 2 4 10"}
RAILODD=${RAILODD:-$ROOT/build/railodd}
SCALE_MARGIN=${SCALE_MARGIN:-0.05}
SCALE_BBOX=${SCALE_BBOX:-1}
TIME=/usr/bin/time
PY=/usr/bin/python3

die() { echo "scale_series.sh: $*" >&2; exit 1; }
[[ -f $EXTRACT ]] || die "no such input: $EXTRACT"
[[ -x $RAILODD ]] || die "railodd binary not found: $RAILODD (build it or set RAILODD)"
command -v osmium >/dev/null || die "osmium not found (apt-get install osmium-tool)"
[[ -x $TIME ]] || die "$TIME not found (apt-get install time)"
for f in $FACTORS; do
    [[ $f =~ ^[1-9][0-9]*$ ]] || die "factors must be positive integers, got '$f'"
done

NAME=$(basename "$EXTRACT")
NAME=${NAME%%.*}
WORK=${SCALE_WORK:-$(mktemp -d /tmp/railodd-scale.XXXXXX)}
mkdir -p "$WORK" "$ROOT/bench/scale-results"
OUT_JSON=${SCALE_JSON:-$ROOT/bench/scale-results/$NAME.json}
RUNS_TSV=$WORK/runs.tsv
MAXF=$(for f in $FACTORS; do echo "$f"; done | sort -n | tail -1)

echo "scale series: $EXTRACT, factors: $FACTORS"
echo "railodd: $RAILODD"
echo "work: $WORK"
echo "load at start: $(cut -d' ' -f1-3 /proc/loadavg), $(nproc) cores"

printf 'factor\tbbox\tinput_bytes\twall_s\tmaxrss_kb\tuser_s\tsys_s\texit\tload1\tout\tlayout\n' >"$RUNS_TSV"

run() { # factor bbox(or -) input layout out
    local f=$1 bbox=$2 in=$3 layout=$4 out=$5 load rc tf=$5.time
    local -a sel=()
    [[ $bbox == - ]] || sel=(--bbox "$bbox")
    load=$(cut -d' ' -f1 /proc/loadavg)
    rm -rf "$out"
    rc=0
    $TIME -o "$tf" -f "%e %M %U %S" "$RAILODD" convert "$in" -o "$out" "${sel[@]}" --no-timings \
        >"$out.log" 2>&1 || rc=$?
    read -r wall rss usr sys < <(tail -1 "$tf")
    printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$f" "$bbox" "$(stat -c %s "$in")" \
        "$wall" "$rss" "$usr" "$sys" "$rc" "$load" "$out" "$layout" >>"$RUNS_TSV"
    printf '  x%-3s %-40s %7.2f s wall %8.1f MB exit %d (load %s)\n' "$f" \
        "${sel[*]:-whole file}" "$wall" "$(awk -v k="$rss" 'BEGIN {print k / 1024}')" "$rc" "$load"
    [[ $rc == 0 ]] || echo "    railodd failed, see $out.log" >&2
}

for f in $FACTORS; do
    in=$WORK/$NAME-x$f.osm.pbf
    layout=$WORK/$NAME-x$f.layout.json
    if [[ ! -f $in || ! -f $layout ]]; then
        $PY "$ROOT/bench/scale_series.py" "$EXTRACT" "$f" "$in" --margin "$SCALE_MARGIN" --layout "$layout"
    fi
    run "$f" - "$in" "$layout" "$WORK/out-x$f"
done

if [[ $SCALE_BBOX == 1 ]]; then
    for f in $(for f in $FACTORS; do echo "$f"; done | sort -n | sed -n '1p;$p' | uniq); do
        in=$WORK/$NAME-x$f.osm.pbf
        layout=$WORK/$NAME-x$f.layout.json
        bbox=$($PY -c 'import json,sys; b=json.load(open(sys.argv[1]))["copies"][0]["bbox"]; print(",".join("%.7f" % v for v in b))' "$layout")
        run "$f" "$bbox" "$in" "$layout" "$WORK/out-x$f-bbox0"
    done
fi

echo "load at end: $(cut -d' ' -f1-3 /proc/loadavg)"

$PY - "$RUNS_TSV" "$OUT_JSON" "$EXTRACT" "$RAILODD" "$FACTORS" "$WORK" <<'EOF'
import csv, json, os, platform, subprocess, sys, time
tsv, out_json, extract, railodd, factors, work = sys.argv[1:]
rows = []
for r in csv.DictReader(open(tsv), delimiter="\t"):
    rep = {}
    p = os.path.join(r["out"], "report.json")
    if r["exit"] == "0" and os.path.exists(p):
        rep = json.load(open(p))
    g = rep.get("geometry", {}).get("summary", {})
    i = rep.get("input", {})
    rows.append({
        "factor": int(r["factor"]),
        "bbox": None if r["bbox"] == "-" else r["bbox"],
        "input_mb": int(r["input_bytes"]) / 1e6,
        "track_km": g.get("length_km"),
        "edges": g.get("edges"),
        "input_nodes": i.get("nodes"),
        "input_track_ways": i.get("track_ways"),
        "input_road_ways": i.get("road_ways"),
        "wall_s": float(r["wall_s"]),
        "cpu_s": float(r["user_s"]) + float(r["sys_s"]),
        "peak_mb": int(r["maxrss_kb"]) / 1024,
        "exit": int(r["exit"]),
        "load1": float(r["load1"]),
    })
base = next((x for x in rows if x["factor"] == 1 and x["bbox"] is None and x["track_km"]), None)
for x in rows:
    km = x["track_km"]
    x["s_per_km"] = x["wall_s"] / km if km else None
    x["mb_per_km"] = x["peak_mb"] / km if km else None
    if base and km:
        x["s_per_km_rel"] = x["s_per_km"] / base["s_per_km"]
        x["mb_per_km_rel"] = x["mb_per_km"] / base["mb_per_km"]
    else:
        x["s_per_km_rel"] = x["mb_per_km_rel"] = None

def f(v, fmt):
    return "-" if v is None else fmt % v

print()
print("| factor | selection | input MB | track km | wall s | CPU s | peak MB | s/km | MB/km | s/km rel. | MB/km rel. | load1 |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|")
for x in rows:
    print("| %d | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
        x["factor"], "--bbox copy 0" if x["bbox"] else "whole file",
        f(x["input_mb"], "%.1f"), f(x["track_km"], "%.1f"), f(x["wall_s"], "%.2f"),
        f(x["cpu_s"], "%.2f"), f(x["peak_mb"], "%.0f"), f(x["s_per_km"], "%.3f"),
        f(x["mb_per_km"], "%.2f"), f(x["s_per_km_rel"], "%.2f"),
        f(x["mb_per_km_rel"], "%.2f"), f(x["load1"], "%.2f")))

ver = subprocess.run([railodd, "--version"], capture_output=True, text=True).stdout.strip()
cpu = ""
try:
    for line in open("/proc/cpuinfo"):
        if line.startswith("model name"):
            cpu = line.split(":", 1)[1].strip()
            break
except OSError:
    pass
json.dump({
    "extract": extract, "factors": [int(v) for v in factors.split()],
    "railodd": railodd, "railodd_version": ver, "work": work,
    "date": time.strftime("%Y-%m-%dT%H:%M:%S%z"),
    "machine": {"cpu": cpu, "cores": os.cpu_count(), "kernel": platform.release(),
                "loadavg_end": open("/proc/loadavg").read().split()[:3]},
    "runs": rows,
}, open(out_json, "w"), indent=1)
print()
print("results:", out_json)
EOF
