#!/usr/bin/env bash
# ThreadSanitizer over convert's threads (build-tsan/, clang): the fit's
# workers, the profile's writer thread, map.xodr and the page's map written
# beside the tagging, in every branch of the outputs (streamed profile;
# whole profile with --odd-user-data, --from/--to, --relation; --debug-outputs),
# on the embedded sample route and, where ../shared is, a real extract. The
# first report fails the run (exit 86). Usage: scripts/test_tsan.sh
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build-tsan -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRAILODD_TSAN=ON \
  -DRAILODD_BUILD_TESTS=OFF -DRAILODD_BUILD_BENCH=OFF >/dev/null
cmake --build build-tsan -j"$(nproc)" --target railodd >/dev/null
export TSAN_OPTIONS="halt_on_error=1:exitcode=86:second_deadlock_stack=1:suppressions=$PWD/scripts/tsan.supp"
bin=build-tsan/railodd
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$bin" sample -o "$work/in" >/dev/null
osm=$(ls "$work"/in/*.osm | head -1)
run() {
    echo "tsan: railodd convert $*"
    "$bin" convert "$@" --threads 2 --no-timings >/dev/null
}
run "$osm" -o "$work/net" --debug-outputs
run "$osm" -o "$work/user" --odd-user-data
run "$osm" -o "$work/route" --from Sampleton --to Brookside
run "$osm" -o "$work/windowed" --fit-method windowed
lauf=../shared/data/osm/gh_lauf-200115.osm.pbf
if [ -f "$lauf" ]; then
    run "$lauf" -o "$work/lauf"
    run "$lauf" -o "$work/rel" --relation 539311 --road-corridor 0
else
    echo "tsan: $lauf absent, the real extract skipped"
fi
echo "tsan: no data race"
