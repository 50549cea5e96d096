#!/usr/bin/env bash
# Runs every test: cargo's (Rust unit, property and integration tests, the C smoke test, the
# README's Rust example), the header check, the API references built with warnings as errors
# (scripts/docs.sh: Doxygen and rustdoc), a fuzzing smoke run of every libFuzzer target (scripts/fuzz-smoke.sh), then the CMake build and CTest (C/C++ API tests under AddressSanitizer and UBSan,
# comparisons against CGAL and OpenMesh, examples, the installed-package consumer tests).
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"

scripts/setup.sh test
scripts/gen-header.sh --check
scripts/docs.sh
cargo test --quiet
# Each fuzz target for $HALFWING_FUZZ_SECONDS (default 20) seconds: a crash fails the run.
scripts/fuzz-smoke.sh
build=build/test
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DHALFWING_SANITIZE=ON
cmake --build "$build" --parallel "$(nproc)"
ctest --test-dir "$build" --output-on-failure --parallel "$(nproc)"
