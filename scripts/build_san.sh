#!/usr/bin/env bash
# The sanitizer build: clang, every library and executable with AddressSanitizer
# and UndefinedBehaviorSanitizer (no recovery: the first report ends the
# process) into build-san/. It holds both the libFuzzer harnesses (fuzz/run.sh)
# and the test suite (scripts/test_san.sh). Usage: scripts/build_san.sh [TARGET...]
# (default: everything).
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build-san -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRAILODD_FUZZ=ON \
  -DRAILODD_BUILD_TESTS=ON -DRAILODD_BUILD_BENCH=OFF >/dev/null
if [ $# -eq 0 ]; then
  cmake --build build-san -j"$(nproc)" >/dev/null
else
  cmake --build build-san -j"$(nproc)" --target "$@" >/dev/null
fi
