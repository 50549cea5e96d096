#!/usr/bin/env bash
# Builds the repair pipeline benchmark (halfwing's repair_mesh vs the sum of the CGAL PMP repair
# calls for the same steps, one thread each) in Release and runs it on a generated ~1M-triangle
# torus, unwelded, and the largest broken and real models, each as it is and unwelded.
#
#   bench/run-repair-mesh-compare.sh [--quick] [--repeats N] [model files...]
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/build.sh"
build_benchmark repair_mesh_compare

RAYON_NUM_THREADS=1 run_benchmark repair_mesh_compare "broken/tm_capsule.obj broken/tm_featuretype.ply broken/c3d_teapot.obj broken/igl_truck.obj closed/igl_armadillo.obj closed/luke_dragon.obj" "$@"
