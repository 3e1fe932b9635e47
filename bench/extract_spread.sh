#!/usr/bin/env bash
# The design search's figures on one real extract over a few shifts of the
# local frame (bench_fit_extract --shift-mm: every node moved D mm, D = 0, 1,
# ..., N-1): the fit is the same up to rounding wherever the frame's origin
# lies, so the spread is how far rounding alone moves each figure. One line
# per figure: median [min - max] over the shifts. Compare two builds by
# their medians, and call a difference measured only beyond the spread.
# Usage: [BIN=build/bench/bench_fit_extract] bench/extract_spread.sh EXTRACT [N]
# (default 5 shifts; one thread each, so the fit times are comparable).
set -euo pipefail
cd "$(dirname "$0")/.."
extract=$1
shifts=${2:-5}
bin=${BIN:-build/bench/bench_fit_extract}
for ((d = 0; d < shifts; ++d)); do
  "$bin" "$extract" --method design --threads 1 --shift-mm "$d"
done | python3 -c '
import json, statistics, sys
runs = [json.loads(line) for line in sys.stdin if line.strip()]
figures = [
    ("fit s", lambda r: r["fit_seconds"]),
    ("elements per km", lambda r: r["summary"]["design"]["elements_per_km"]),
    ("joints per km", lambda r: r["summary"]["design"]["joints_per_km"]),
    ("elements under 1 m (%)", lambda r: 100 * r["summary"]["design"]["short_element_share"]),
    ("spirals (% of length)", lambda r: 100 * r["summary"]["design"]["spiral_share"]),
    ("double track: curvature difference p50 (%)", lambda r: 100 * r["summary"]["design"]["parallel_curvature_difference_p50"]),
    ("double track: over 10 % (% of pairs)", lambda r: 100 * r["summary"]["design"]["parallel_share_over_10pct"]),
    ("node distance p95 (sigma-hat)", lambda r: r["summary"]["node_noise"]["node_distance_p95_sigmas"]),
    ("node distance max (m)", lambda r: r["summary"]["node_distance_max_m"]),
    ("spliced ends", lambda r: r["summary"]["links"]["spliced_ends"]),
    ("corner chains", lambda r: r["summary"]["links"]["corner_chains"]),
    ("switch nodes off their fit", lambda r: r["switch_nodes_off"]),
]
print("%s: %d shifts" % (sys.argv[1], len(runs)))
for name, get in figures:
    v = [get(r) for r in runs]
    print("  %-44s %8.3g [%.3g - %.3g]" % (name, statistics.median(v), min(v), max(v)))
' "$(basename "$extract")"
