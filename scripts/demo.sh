#!/usr/bin/env bash
# Builds halfwing and the examples with CMake and runs the main demo.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"

scripts/setup.sh demo
build=build/demo
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DHALFWING_BUILD_TESTS=OFF >/dev/null
cmake --build "$build" --parallel "$(nproc)" --target tetrahedron
"$build/examples/tetrahedron" "$@"
