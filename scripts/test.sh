#!/usr/bin/env bash
# Set-up, then the whole test suite: unit and worked examples, CLI, spec coverage, and the
# property tests with 1,000 cases each (CUTCOM_RC_PARAMS in CMakeLists.txt).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cd build
ctest --output-on-failure -j"$(nproc)"
