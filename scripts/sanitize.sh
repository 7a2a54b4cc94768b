#!/usr/bin/env bash
# The test suite under AddressSanitizer + UndefinedBehaviorSanitizer (CI runs it after the
# README's test command): unit, CLI and spec tests, the corpus, and the properties with 100
# cases each (the sanitizers slow ref down several times). Any report fails the run. GCC leaves
# float-cast-overflow out of "undefined"; it is named so that a double beyond an int is caught.
set -euo pipefail
cd "$(dirname "$0")/.."
flags="-fsanitize=address,undefined,float-cast-overflow -fno-sanitize-recover=all -fno-omit-frame-pointer"
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS="$flags" -DCUTCOM_KNIFE_WATCH=OFF \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" -DCUTCOM_RC_PARAMS="max_success=100 seed=20261122"
cmake --build build-asan -j"$(nproc)" --target unit_tests cli_tests prop_tests ref_kernel_tests cutcom clause_table
cd build-asan
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --output-on-failure -j"$(nproc)"
