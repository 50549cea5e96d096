#!/usr/bin/env bash
# Builds the repair benchmark (halfwing's exact vertex merge vs CGAL's polygon-soup merge) in
# Release and runs it on a generated ~1M-triangle torus, unwelded (3M vertices), and the largest
# real models, unwelded.
#
#   bench/run-repair-compare.sh [--quick] [--repeats N] [model files...]
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/build.sh"
build_benchmark repair_compare

run_benchmark repair_compare "closed/igl_armadillo.obj closed/luke_dragon.obj open/c3d_stanford-bunny.obj" "$@"
