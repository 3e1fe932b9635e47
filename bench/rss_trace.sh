#!/usr/bin/env bash
# Resident set of a command over time: /proc/PID/status VmRSS every 20 ms,
# as "seconds MB" lines, then the peak. A benchmark aid, not a test: read it
# against the phase timings of the run's report.json (docs/BENCHMARKS.md,
# "Where Cologne's memory and output go").
#
#   bench/rss_trace.sh OUT.txt COMMAND [ARGS...]
set -euo pipefail
[ $# -ge 2 ] || { echo "usage: $0 OUT.txt COMMAND [ARGS...]" >&2; exit 2; }
out=$1
shift
"$@" >/dev/null 2>&1 &
pid=$!
t0=$(date +%s%N)
: >"$out"
while kill -0 "$pid" 2>/dev/null; do
    if kb=$(awk '/^VmRSS/ {print $2}' "/proc/$pid/status" 2>/dev/null) && [ -n "$kb" ]; then
        echo "$(( ($(date +%s%N) - t0) / 1000000 )) $kb" | awk '{printf "%.2f %.1f\n", $1 / 1000, $2 / 1024}' >>"$out"
    fi
    sleep 0.02
done
status=0
wait "$pid" || status=$?
awk '$2 > m {m = $2} END {printf "peak %.1f MB\n", m}' "$out"
exit "$status"
