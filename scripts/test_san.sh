#!/usr/bin/env bash
# The unit and CLI tests again, in the ASan + UBSan build (scripts/build_san.sh):
# the executables the CLI tests run are sanitized too. A sanitizer report
# exits 86, a code no railodd command uses, so a test that expects a failing
# exit cannot mistake one for the failure it expects. Leaks are reported
# (LeakSanitizer) and fail the test. Usage: scripts/test_san.sh [CTEST ARGS...]
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build_san.sh
export ASAN_OPTIONS="exitcode=86:detect_leaks=1:check_initialization_order=1:detect_stack_use_after_return=1"
export UBSAN_OPTIONS="exitcode=86:print_stacktrace=1"
(cd build-san && ctest --output-on-failure -j"$(nproc)" -L "unit|cli" "$@")
