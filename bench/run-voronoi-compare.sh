#!/usr/bin/env bash
# Side-by-side benchmark of issue 5: halfwing's Delaunay triangulation and full clipped Voronoi
# diagram against CGAL (Delaunay_triangulation_2, EPICK, range insert; + Voronoi_diagram_2 face
# walk), spade (bulk load; + voronoi_faces walk), delaunator and voronoice, on 10k, 100k and 1M
# uniform random sites and the 1000×1000 integer grid.
#
# The Rust libraries are timed in one process (benches/voronoi_compare.rs), CGAL in another
# (bench/voronoi/voronoi_cgal.cpp), back to back, on identical generated inputs (same LCG, same
# seed). The two processes alternate for a few rounds, and each time is the best of all its runs
# (per round 201 for 10k sites, 31 for 100k, 3 for the 1M and grid inputs): on a shared machine a
# quiet or a busy minute would otherwise favour whichever side ran in it.
#
# Usage: bench/run-voronoi-compare.sh [input-filter]   (e.g. "uniform_1000000")
# Env:   BUILD_DIR (default build/bench) for the CMake build of the CGAL side;
#        ROUNDS (default 3) for the number of alternated rounds.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"
filter="${1:-}"
build="${BUILD_DIR:-build/bench}"

cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DHALFWING_BUILD_BENCHMARKS=ON \
  -DHALFWING_BUILD_TESTS=OFF -DHALFWING_BUILD_EXAMPLES=OFF > /dev/null
cmake --build "$build" --target voronoi_cgal > /dev/null
cargo bench --bench voronoi_compare --no-run --quiet 2> /dev/null || cargo bench --bench voronoi_compare --no-run

echo "load before: $(uptime)"
results=$(mktemp)
trap 'rm -f "$results"' EXIT
for ((round = 1; round <= ${ROUNDS:-3}; round++)); do
  cargo bench --quiet --bench voronoi_compare -- $filter | grep '^RESULT' >> "$results"
  "$build/bench/voronoi/voronoi_cgal" $filter | grep '^RESULT' >> "$results"
done
echo "load after:  $(uptime)"
echo

awk '
  { k = $2 " " $3 " " $4
    # The best of the rounds; "failed" only when every round failed.
    if (!(k in t) || t[k] == "failed" || ($5 != "failed" && $5 + 0 < t[k] + 0)) t[k] = $5
    if (!($2 in seen)) { seen[$2] = 1; order[n++] = $2 } }
  function ms(key) { return (key in t) ? t[key] : "-" }
  function ratio(a, b) { return (a in t && b in t && t[a] != "failed" && t[b] != "failed" && t[b] > 0) ? sprintf("%.2f", t[a] / t[b]) : "-" }
  END {
    print "Delaunay triangulation (ms, best of all runs)"
    printf "| %-15s | %9s | %9s | %9s | %10s | %-16s |\n", "input", "halfwing", "CGAL", "spade", "delaunator", "halfwing / CGAL"
    print "|-----------------|-----------|-----------|-----------|------------|------------------|"
    for (i = 0; i < n; i++) { s = order[i]
      printf "| %-15s | %9s | %9s | %9s | %10s | %-16s |\n", s, ms(s " halfwing delaunay"), ms(s " cgal delaunay"),
        ms(s " spade delaunay"), ms(s " delaunator delaunay"), ratio(s " halfwing delaunay", s " cgal delaunay") }
    print ""
    print "Full Voronoi diagram, every cell a polygon (ms; halfwing and voronoice clip to the box, CGAL and spade walk open faces)"
    printf "| %-15s | %9s | %11s | %11s | %9s | %-24s | %-24s |\n", "input", "halfwing", "CGAL DT+VD", "spade+faces", "voronoice", "halfwing / CGAL DT only", "halfwing / CGAL DT+VD"
    print "|-----------------|-----------|-------------|-------------|-----------|--------------------------|--------------------------|"
    for (i = 0; i < n; i++) { s = order[i]
      printf "| %-15s | %9s | %11s | %11s | %9s | %-24s | %-24s |\n", s, ms(s " halfwing voronoi"), ms(s " cgal voronoi"),
        ms(s " spade voronoi"), ms(s " voronoice voronoi"), ratio(s " halfwing voronoi", s " cgal delaunay"),
        ratio(s " halfwing voronoi", s " cgal voronoi") }
  }' "$results"
