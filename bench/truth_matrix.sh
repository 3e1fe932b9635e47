#!/usr/bin/env bash
# The truth bench over every regime issue 37 names: node spacing (OSM-like,
# dense, sparse) x sigma, for one fit method, as one table row per regime.
# Usage: [OUTLIERS=F] [CHAIN=1] [FIRST=SEED] [SPACINGS=...] bench/truth_matrix.sh [design|windowed] [ROUTES] [SIGMAS...]
# (defaults: design, 300 routes, sigma 0.1 0.3 1.0 2.0; OUTLIERS, the
# share of outlier nodes, 0.01; CHAIN=1: each route tied at both ends and
# built as the network's fit builds a chain, with a column of how:
# railway / spliced / patched / corners; FIRST, the first route's seed,
# 1000: two builds level over many routes can differ by ten routes over
# the limit on one draw of 300, so compare them on more than one);
# SPACINGS, the regimes, "osm dense sparse" (very-sparse besides: a
# regime issue 37 names no target for).
set -euo pipefail
cd "$(dirname "$0")/.."
method=${1:-design}
routes=${2:-300}
shift $(( $# > 2 ? 2 : $# ))
sigmas=${*:-0.1 0.3 1.0 2.0}
bin=${BIN:-build/bench/bench_alignment_truth}
chain=()
if [ "${CHAIN:-0}" = 1 ]; then chain=(--chain --tied); fi
echo "| spacing | sigma | routes max > 1 m | over issue 37 limit | route max p50 / p95 / max (m) | route p95 median | radius error p50 / p95 | elements / design p95 / max | spurious sign changes (routes) | noise / sigma p5-p95 | fit s |${chain:+ chains r / s / p / c |}"
echo "|---|---|---|---|---|---|---|---|---|---|---|${chain:+---|}"
for spacing in ${SPACINGS:-osm dense sparse}; do
  for s in $sigmas; do
    "$bin" "$routes" "$s" --spacing "$spacing" --method "$method" --outliers "${OUTLIERS:-0.01}" --first "${FIRST:-1000}" "${chain[@]}" | python3 -c '
import re, sys
t = sys.stdin.read()
g = lambda p: re.search(p, t).groups()
fit, = g(r"fit ([0-9.]+) s")
over, = g(r"routes with max > 1 m: ([0-9]+)")
lim = g(r"over the ([0-9.]+) m limit: ([0-9]+)")
mx = g(r"route max median ([0-9.]+), p95 ([0-9.]+), max ([0-9.]+)")
p95, = g(r"route p95 median ([0-9.]+)")
rad = g(r"arc radius error: p50 ([0-9.]+) %, p95 ([0-9.]+) %")
el = g(r"elements / design: median [0-9.]+, p95 ([0-9.]+), max ([0-9.]+)")
sc = g(r"spurious sign changes: (-?[0-9]+) on ([0-9]+) routes")
nz = g(r"noise / sigma: p5 ([0-9.]+), median [0-9.]+, p95 ([0-9.]+)")
ch = re.search(r"chains: railway ([0-9]+), spliced ([0-9]+), patched ([0-9]+) \(([0-9]+) stretches\), corners ([0-9]+)", t)
row = "| %s | %s | %s | %s (%s m) | %s / %s / %s | %s | %s / %s %% | %s / %s | %s (%s) | %s-%s | %s |" % ((sys.argv[1], sys.argv[2], over, lim[1], lim[0]) + mx + (p95,) + rad + el + sc + nz + (fit,))
print(row + (" %s / %s / %s / %s |" % (ch.group(1), ch.group(2), ch.group(3), ch.group(5)) if ch else ""))
' "$spacing" "$s"
  done
done
