#!/usr/bin/env bash
# Builds the hole-filling benchmark (halfwing's fill_hole vs CGAL's triangulate_hole) in Release
# and runs it on a capless sphere and a wavy tube, each with a hole of 1,000 edges (or of each
# size given, e.g. `500 1000 2000` for a growth check), single thread.
#
#   bench/run-hole-fill-compare.sh [--quick] [--repeats N] [EDGES...]
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/build.sh"
build_benchmark hole_fill_compare

export RAYON_NUM_THREADS=1
echo "machine: $(nproc) cores; load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"
"$build/bench/hole_fill_compare" "$@"
