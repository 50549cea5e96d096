# Sourced by the run-*-compare.sh scripts: the paths they share, and the Release build of one
# benchmark target (build-bench/, or $HALFWING_BENCH_BUILD_DIR).
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${HALFWING_BENCH_BUILD_DIR:-$root/build-bench}"
# The test data: the repository's copy, or a fuller set named by HALFWING_DATA.
data="${HALFWING_DATA:-$root/tests/data}/meshes"

build_benchmark() {
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DHALFWING_BUILD_BENCHMARKS=ON \
    -DHALFWING_BUILD_TESTS=OFF -DHALFWING_BUILD_EXAMPLES=OFF >/dev/null
  cmake --build "$build" --target "$1" -j 2 >/dev/null
}
