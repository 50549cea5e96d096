#!/usr/bin/env bash
# Builds the doctor benchmark (halfwing's doctor vs the CGAL PMP calls for the same findings) in
# Release and runs it on a generated ~1M-triangle torus and the largest real models.
#
#   bench/run-doctor-compare.sh [--quick] [--repeats N] [model files...]
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/build.sh"
build_benchmark doctor_compare

run_benchmark doctor_compare "closed/igl_armadillo.obj closed/luke_dragon.obj open/c3d_stanford-bunny.obj broken/igl_truck.obj broken/c3d_teapot.obj" "$@"
