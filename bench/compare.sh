#!/usr/bin/env bash
# Side by side on one OSM extract: railodd convert, SUMO netconvert (OpenDRIVE
# output) and osmium (the floor of reading the input). A benchmark, not a test.
#
#   bench/compare.sh [OSM_FILE] [RUNS]
#
# OSM_FILE  .osm, .osm.pbf, .osm.gz, .osm.bz2 or .opl (default
#           ../shared/data/osm/gh_lauf-200115.osm.pbf); anything but .osm is
#           first turned into OSM XML with `osmium cat` (SUMO reads OSM XML
#           only) and all three tools read that same XML file.
# RUNS      runs per tool (default 3); the table shows the medians.
#
# Environment:
#   RAILODD_RUNS     runs of railodd only (default RUNS), e.g. 1 on Cologne
#                    (~5 min a run) while netconvert and osmium run RUNS times
#   RAILODD          railodd binary (default build/railodd)
#   NETCONVERT       netconvert binary (default netconvert)
#   SUMO_HOME        default /usr/share/sumo (typemaps, XML schemas)
#   NETCONVERT_RAIL_ONLY=0   skip the second netconvert run that keeps only
#                    rail edges (--keep-edges.by-vclass); default 1
#   NETCONVERT_REPAIR=0      leave out --railway.topology.repair (default 1;
#                    when the first run with it fails, e.g. the assertion in
#                    addBidiEdgesForBufferStops of SUMO 1.15, the failed run is
#                    recorded as netconvert_repair / netconvert_rail_repair
#                    and the measured runs go on without it)
#   RAILODD_SPLIT    where the per-phase timings come from: `extra` (default:
#                    one more railodd run without --no-timings, not counted
#                    in the medians), `last` (the last measured run leaves
#                    out --no-timings; the timers are a few clock reads per
#                    phase), `none`
#   COMPARE_JSON     result file (default bench/compare-results/NAME.json)
#   COMPARE_WORK     scratch directory (default a new /tmp/railodd-compare.*,
#                    kept: it holds the outputs, logs and validate reports)
#
# Each run is timed with `/usr/bin/time -f "%e %M %U %S"` (wall seconds, peak
# RSS in KB, user and system CPU seconds); the 1-minute load average is
# recorded before every run. On a shared machine CPU seconds move less with
# the load than wall time; both are reported.
set -euo pipefail

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
OSM_FILE=${1:-$ROOT/../shared/data/osm/gh_lauf-200115.osm.pbf}
RUNS=${2:-3}
RAILODD_RUNS=${RAILODD_RUNS:-$RUNS}
RAILODD=${RAILODD:-$ROOT/build/railodd}
NETCONVERT=${NETCONVERT:-netconvert}
export SUMO_HOME=${SUMO_HOME:-/usr/share/sumo}
NETCONVERT_RAIL_ONLY=${NETCONVERT_RAIL_ONLY:-1}
NETCONVERT_REPAIR=${NETCONVERT_REPAIR:-1}
RAILODD_SPLIT=${RAILODD_SPLIT:-extra}
TIME=/usr/bin/time

die() { echo "compare.sh: $*" >&2; exit 1; }
[[ -f $OSM_FILE ]] || die "no such input: $OSM_FILE"
[[ $RUNS =~ ^[1-9][0-9]*$ ]] || die "RUNS must be a positive integer, got '$RUNS'"
[[ $RAILODD_RUNS =~ ^[1-9][0-9]*$ ]] || die "RAILODD_RUNS must be a positive integer, got '$RAILODD_RUNS'"
[[ -x $RAILODD ]] || die "railodd binary not found: $RAILODD (build it or set RAILODD)"
command -v "$NETCONVERT" >/dev/null || die "netconvert not found (apt-get install sumo)"
command -v osmium >/dev/null || die "osmium not found (apt-get install osmium-tool)"
[[ -x $TIME ]] || die "$TIME not found (apt-get install time)"
case $RAILODD_SPLIT in extra|last|none) ;; *) die "RAILODD_SPLIT must be extra, last or none";; esac

NAME=$(basename "$OSM_FILE")
NAME=${NAME%.gz}; NAME=${NAME%.bz2}; NAME=${NAME%.pbf}; NAME=${NAME%.opl}; NAME=${NAME%.osm}
OUT_JSON=${COMPARE_JSON:-$ROOT/bench/compare-results/$NAME.json}
WORK=${COMPARE_WORK:-$(mktemp -d /tmp/railodd-compare.XXXXXX)}
mkdir -p "$WORK"
WORK=$(cd "$WORK" && pwd)
echo "compare.sh: $NAME, $RUNS run(s) per tool ($RAILODD_RUNS of railodd), scratch in $WORK"

load1() { cut -d' ' -f1 /proc/loadavg; }
META=$WORK/meta.tsv
printf 'key\tvalue\n' >"$META"
meta() { printf '%s\t%s\n' "$1" "$2" >>"$META"; }

# -- the common OSM XML input
case $OSM_FILE in
    *.osm) XML=$OSM_FILE ;;
    *) XML=$WORK/$NAME.osm
       echo "  osmium cat $OSM_FILE -o $XML"
       osmium cat "$OSM_FILE" -o "$XML" --overwrite ;;
esac

meta name "$NAME"
meta input "$OSM_FILE"
meta osm_xml "$XML"
meta osm_xml_bytes "$(stat -c %s "$XML")"
meta runs "$RUNS"
meta runs_railodd "$RAILODD_RUNS"
meta date "$(date -u +%Y-%m-%dT%H:%MZ)"
meta machine "$(uname -m), $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'), $(awk '/MemTotal/ {printf "%.0f GiB", $2/1048576}' /proc/meminfo)"
meta nproc "$(nproc)"
meta load_start "$(cut -d' ' -f1-3 /proc/loadavg)"
meta railodd "$RAILODD"
meta railodd_version "$("$RAILODD" --version 2>&1 | head -1)"
meta netconvert_version "$("$NETCONVERT" --version 2>&1 | head -1)"
meta osmium_version "$(osmium --version 2>&1 | head -1)"

TYPEMAPS=$SUMO_HOME/data/typemap/osmNetconvert.typ.xml,$SUMO_HOME/data/typemap/osmNetconvertRailUsage.typ.xml
NETCONVERT_BASE=(--osm-files "$XML" --type-files "$TYPEMAPS" --geometry.remove)
REPAIR=()
[[ $NETCONVERT_REPAIR == 1 ]] && REPAIR=(--railway.topology.repair)
RAIL_CLASSES=rail,rail_urban,rail_electric,rail_fast,tram

RUNS_TSV=$WORK/runs.tsv
printf 'tool\trun\twall_s\tmaxrss_kb\tcpu_s\texit\tload1\n' >"$RUNS_TSV"

# timed TOOL RUN LOG CMD...: one run under /usr/bin/time, appended to runs.tsv
timed() {
    local tool=$1 run=$2 log=$3; shift 3
    local load rc tf=$WORK/time.$tool.$run
    load=$(load1)
    set +e
    "$TIME" -f "%e %M %U %S" -o "$tf" "$@" >"$log" 2>&1
    rc=$?
    set -e
    local wall rss usr sys cpu
    read -r wall rss usr sys < <(tail -1 "$tf")
    cpu=$(awk -v u="$usr" -v s="$sys" 'BEGIN {printf "%.2f", u + s}')
    printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$tool" "$run" "$wall" "$rss" "$cpu" "$rc" "$load" >>"$RUNS_TSV"
    printf '  %-16s run %d: %7.2f s wall %7.2f s cpu %8.1f MB exit %d (load %s)\n' "$tool" "$run" "$wall" "$cpu" \
        "$(awk -v k="$rss" 'BEGIN {print k / 1024}')" "$rc" "$load"
    if [[ $rc -ne 0 ]]; then
        echo "    failed; last lines of $log:"
        tail -5 "$log" | sed 's/^/    /'
    fi
}

# -- 1. railodd convert
meta cmd_railodd "$RAILODD convert $XML -o OUT --no-timings"
for ((i = 1; i <= RAILODD_RUNS; i++)); do
    rm -rf "$WORK/railodd_out"
    if [[ $RAILODD_SPLIT == last && $i -eq $RAILODD_RUNS ]]; then
        timed railodd "$i" "$WORK/railodd.$i.log" "$RAILODD" convert "$XML" -o "$WORK/railodd_out"
        rm -rf "$WORK/railodd_timed"; cp -r "$WORK/railodd_out" "$WORK/railodd_timed"
        meta split_source "last measured run (without --no-timings)"
    else
        timed railodd "$i" "$WORK/railodd.$i.log" "$RAILODD" convert "$XML" -o "$WORK/railodd_out" --no-timings
    fi
done
if [[ $RAILODD_SPLIT == extra ]]; then
    echo "  railodd: one more run with timings (not counted)"
    rm -rf "$WORK/railodd_timed"
    "$RAILODD" convert "$XML" -o "$WORK/railodd_timed" >"$WORK/railodd.timed.log" 2>&1 || true
    meta split_source "extra run without --no-timings, load $(load1) after"
fi
if [[ -f $WORK/railodd_out/map.xodr ]]; then
    cp "$WORK/railodd_out/map.xodr" "$WORK/railodd.xodr"
    meta size_railodd "$(stat -c %s "$WORK/railodd.xodr")"
    meta size_railodd_outdir "$(du -sb "$WORK/railodd_out" | cut -f1)"
fi

# -- 2. netconvert, all types of the typemaps, and rail edges only
# netconvert_runs TOOL OUT EXTRA...: RUNS timed runs writing OUT; when the
# first run fails with --railway.topology.repair it is kept as TOOL_repair and
# the runs are repeated without the repair.
netconvert_runs() {
    local tool=$1 out=$2; shift 2
    local -a repair=("${REPAIR[@]}")
    local i=1
    while ((i <= RUNS)); do
        rm -f "$out"
        timed "$tool" "$i" "$WORK/$tool.$i.log" "$NETCONVERT" "${NETCONVERT_BASE[@]}" "${repair[@]}" "$@" --opendrive-output "$out"
        if [[ $i -eq 1 && ${#repair[@]} -gt 0 && $(tail -1 "$RUNS_TSV" | cut -f6) != 0 ]]; then
            sed -i '$ s/^'"$tool"'\t/'"$tool"'_repair\t/' "$RUNS_TSV"
            mv "$WORK/$tool.1.log" "$WORK/${tool}_repair.1.log"
            meta "note_$tool" "with --railway.topology.repair: $(grep -m1 -E 'Assertion|Error' "$WORK/${tool}_repair.1.log" | cut -c1-240); measured without it"
            echo "  $tool: failed with --railway.topology.repair, measuring without it"
            repair=()
            continue
        fi
        i=$((i + 1))
    done
    local -a cmd=("$NETCONVERT" "${NETCONVERT_BASE[@]}" "${repair[@]}" "$@" --opendrive-output OUT.xodr)
    meta "cmd_$tool" "SUMO_HOME=$SUMO_HOME ${cmd[*]}"
    [[ -f $out ]] && meta "size_$tool" "$(stat -c %s "$out")"
    return 0
}
netconvert_runs netconvert "$WORK/netconvert.xodr"
if [[ $NETCONVERT_RAIL_ONLY == 1 ]]; then
    netconvert_runs netconvert_rail "$WORK/netconvert_rail.xodr" --keep-edges.by-vclass "$RAIL_CLASSES"
fi

# -- 3. osmium: read and write every object as OPL, discarded
meta cmd_osmium "osmium cat $XML -o /dev/null -f opl --overwrite"
for ((i = 1; i <= RUNS; i++)); do
    timed osmium "$i" "$WORK/osmium.$i.log" osmium cat "$XML" -o /dev/null -f opl --overwrite
done
meta load_end "$(cut -d' ' -f1-3 /proc/loadavg)"

# -- railodd's own checker on every OpenDRIVE output (not timed)
for t in railodd netconvert netconvert_rail; do
    if [[ -f $WORK/$t.xodr ]]; then
        "$RAILODD" validate "$WORK/$t.xodr" --json >"$WORK/$t.validate.json" 2>"$WORK/$t.validate.err" || true
    fi
done

python3 "$ROOT/bench/compare_geometry.py" report "$WORK" "$OUT_JSON"
