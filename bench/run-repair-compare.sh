#!/usr/bin/env bash
# Builds the repair benchmark (halfwing's exact vertex merge vs CGAL's polygon-soup merge) in
# Release and runs it on a generated ~1M-triangle torus, unwelded (3M vertices), and the largest
# real models, unwelded.
#
#   bench/run-repair-compare.sh [--quick] [--repeats N] [model files...]
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/build.sh"
build_benchmark repair_compare

options=()
models=()
while (($#)); do
  case "$1" in
    --repeats) options+=("$1" "$2"); shift 2 ;;
    -*) options+=("$1"); shift ;;
    *) models+=("$1"); shift ;;
  esac
done
if ((${#models[@]} == 0)); then
  for model in closed/igl_armadillo.obj closed/luke_dragon.obj open/c3d_stanford-bunny.obj; do
    [[ -f "$data/$model" ]] && models+=("$data/$model")
  done
fi
echo "machine: $(nproc) cores; load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"
"$build/bench/repair_compare" "${options[@]}" "${models[@]}"
