#!/usr/bin/env bash
# Builds the libFuzzer targets of fuzz/ on stable Rust and runs each one for a while: the
# readers, the bulk build, the doctor, edit sequences and the Voronoi diagram.
#
#   scripts/fuzz-smoke.sh [seconds per target]     (default: $HALFWING_FUZZ_SECONDS, else 20)
#
# Coverage comes from LLVM's sanitizer-coverage pass, which stable rustc runs on request, and
# libfuzzer-sys links libFuzzer itself: no nightly toolchain and no cargo-fuzz needed. Rust's
# own checks (bounds, overflow, debug assertions) stand in for AddressSanitizer. A crash stops
# the run with its input in fuzz/artifacts/<target>/; the corpora grow in fuzz/corpus/, so
# later runs go deeper. For hours: scripts/fuzz-smoke.sh 3600.
set -euo pipefail
cd "$(dirname "$0")/../fuzz"
export PATH="$HOME/.cargo/bin:$PATH"
seconds="${1:-${HALFWING_FUZZ_SECONDS:-20}}"
host=$(rustc -vV | sed -n 's/^host: //p')
# The explicit --target keeps these flags off build scripts, which cannot link them.
export RUSTFLAGS="-Cpasses=sancov-module -Cllvm-args=-sanitizer-coverage-level=4 \
-Cllvm-args=-sanitizer-coverage-inline-8bit-counters -Cllvm-args=-sanitizer-coverage-pc-table \
-Cllvm-args=-sanitizer-coverage-trace-compares --cfg fuzzing -Cdebug-assertions -Coverflow-checks"
cargo build --release --bins --target "$host" --quiet

seed() {  # seed <target> <file name> <contents>: a first input, when the corpus is empty
  mkdir -p "corpus/$1"
  [ -n "$(ls -A "corpus/$1")" ] || printf '%b' "$3" >"corpus/$1/$2"
}
seed read_obj tetrahedron.obj 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvn 0 0 1\nvt 0 0\nf 1/1/1 3/1/1 2/1/1\nf 1 2 4\nf 2 3 4\nf 3 1 4\n'
seed read_off tetrahedron.off 'OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 2 0 3\n'
seed read_ply triangle.ply 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n'
seed read_points2d triangle.node '\00014 2 0 0\n1 0 0\n2 1 0\n3 0 1\n4 1 1\n'
for target in build_mesh doctor edits voronoi; do seed "$target" zero '\000\000\000\000'; done

for target in read_obj read_off read_ply read_points2d build_mesh doctor edits voronoi; do
  mkdir -p "artifacts/$target"
  log=$(mktemp)
  if ! "target/$host/release/$target" -max_total_time="$seconds" -rss_limit_mb=2048 \
    -max_len=4096 -artifact_prefix="artifacts/$target/" "corpus/$target" >"$log" 2>&1; then
    tail -n 40 "$log" >&2
    echo "fuzz-smoke: $target crashed; the input is in fuzz/artifacts/$target/" >&2
    rm -f "$log"
    exit 1
  fi
  runs=$(grep -o 'Done [0-9]* runs' "$log" | tail -n 1)
  echo "fuzz-smoke: $target: ${runs:-no runs reported} in ${seconds} s, corpus $(ls "corpus/$target" | wc -l) inputs"
  rm -f "$log"
done
