#!/usr/bin/env bash
# The README's test command: install, build, run every test. Tests that need
# ../shared/data are labelled `shared` and skip with a message when it is absent.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
cd build
ctest --output-on-failure -j"$(nproc)" "$@"
