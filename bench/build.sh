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

# Runs benchmark $1 on the script's arguments ($3 on): options go to it (`--repeats N` and
# `--only NAME` with their values), model files as given, or else those of the default models
# $2 (space-separated, relative to $data) the data holds; `--only` alone runs no real model.
run_benchmark() {
  local target="$1" defaults="$2" only_generated=0
  shift 2
  local options=() models=()
  while (($#)); do
    case "$1" in
      --repeats | --only) options+=("$1" "$2"); [[ "$1" == --only ]] && only_generated=1; shift 2 ;;
      -*) options+=("$1"); shift ;;
      *) models+=("$1"); shift ;;
    esac
  done
  if ((${#models[@]} == 0 && !only_generated)); then
    local model
    for model in $defaults; do
      [[ -f "$data/$model" ]] && models+=("$data/$model")
    done
  fi
  echo "machine: $(nproc) cores; load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"
  "$build/bench/$target" "${options[@]}" "${models[@]}"
}
