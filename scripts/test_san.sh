#!/usr/bin/env bash
# The unit and CLI tests again, in the ASan + UBSan build (scripts/build_san.sh):
# the executables the CLI tests run are sanitized too. A sanitizer report
# exits 86, a code no railodd command uses, so a test that expects a failing
# exit cannot mistake one for the failure it expects. Leaks are reported
# (LeakSanitizer) and fail the test. Usage: scripts/test_san.sh [CTEST ARGS...]
#
# Left out here (they run in the Release suite): the five tests that take
# over a minute each under the sanitizers, 575 of the suite's 2,990 CPU-s.
# Each repeats on more data code that shorter tests run sanitized: 24 dense
# truth routes (the design search), a second track guided by a sparse first,
# a 50,000-node zigzag, the report page in chromium (not sanitized), and a
# batch route killed by its time limit. CI's 90 minutes need the margin.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build_san.sh
export ASAN_OPTIONS="exitcode=86:detect_leaks=1:check_initialization_order=1:detect_stack_use_after_return=1"
export UBSAN_OPTIONS="exitcode=86:print_stacktrace=1"
long='^(DesignFit\.DenseNoisyNodesKeepTheRadii|ParallelTracks\.ASparseSecondTrackTakesTheFirstTracksTransitions'
long+='|CliDegenerateInput\.AFiftyThousandNodeZigZagConverts|report_browser_sample'
long+='|CliBatch\.ARouteOverItsTimeIsKilledAndTheRerunResumesIt)$'
(cd build-san && ctest --output-on-failure -j"$(nproc)" -L "unit|cli" -E "$long" "$@")
