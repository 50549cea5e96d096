#!/usr/bin/env bash
# Builds the side-by-side benchmark (halfwing vs OpenMesh vs CGAL) in Release and runs it on the
# generated ~1M-face models and the largest clean real models of the test data (tests/data, or
# $HALFWING_DATA; models it lacks are left out).
#
#   bench/run-mesh-compare.sh [mesh_compare options] [model files...]
#
# Options go to mesh_compare (--quick, --warm, --repeats N, --only GENERATED-MODEL). Model files
# given on the command line replace the default real models (--only alone runs no real model). The build directory is build-bench/ (override with
# HALFWING_BENCH_BUILD_DIR).
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/build.sh"
build_benchmark mesh_compare

# The largest closed and open real models (all manifold, so every library builds them).
run_benchmark mesh_compare "closed/igl_armadillo.obj closed/c3d_nefertiti.obj closed/luke_dragon.obj open/c3d_stanford-bunny.obj" "$@"
