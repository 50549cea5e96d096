/* The one-ring valence sum over every vertex, written in C the ways a C user of halfwing can
 * write it (bench/valence_sums.c), for the side-by-side benchmark. Each returns the sum, or
 * (size_t)-1 when halfwing refuses the mesh. */
#ifndef HALFWING_BENCH_VALENCE_SUMS_H
#define HALFWING_BENCH_VALENCE_SUMS_H

#include <stddef.h>

#include "halfwing.h"

#ifdef __cplusplus
extern "C" {
#endif

/** With the checked stack circulators: hw_circ_around_vertex() + hw_circ_next_vertex(). */
size_t valence_sum_checked_circulator(const hw_mesh *mesh);
/** With the inline circulators: hw_nav_around_vertex() + hw_nav_circ_next_vertex(). */
size_t valence_sum_inline_circulator(const hw_mesh *mesh);
/** As the textbooks write it: from each vertex's half-edge, twin(prev(h)) by hand until back. */
size_t valence_sum_by_hand(const hw_mesh *mesh);

#ifdef __cplusplus
}
#endif

#endif
