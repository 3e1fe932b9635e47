#!/usr/bin/env bash
# The README's test command: install, build, run every test. Tests that need
# ../shared/data are labelled `shared` and skip with a message when it is absent.
# Then the sanitizer build (clang, ASan + UBSan, build-san/): the unit and CLI
# tests again (scripts/test_san.sh; RAILODD_SANITIZE=0 skips them), convert's
# threads under ThreadSanitizer (scripts/test_tsan.sh, build-tsan/;
# RAILODD_TSAN=0 skips it) and a smoke of every libFuzzer harness
# (fuzz/run.sh): RAILODD_FUZZ_SECONDS each (default 20; 0 skips it).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
(cd build && ctest --output-on-failure -j"$(nproc)" "$@")
if [ "${RAILODD_SANITIZE:-1}" != 0 ]; then
  bash scripts/test_san.sh
fi
if [ "${RAILODD_TSAN:-1}" != 0 ]; then
  bash scripts/test_tsan.sh
fi
if [ "${RAILODD_FUZZ_SECONDS:-20}" != 0 ]; then
  bash fuzz/run.sh "${RAILODD_FUZZ_SECONDS:-20}"
fi
