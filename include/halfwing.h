/**
 * @file halfwing.h
 * @brief halfwing: half-edge and winged-edge mesh kernels and a 2D Voronoi diagram, in C.
 *
 * Conventions, stated once for every function below:
 *
 * Errors. Every fallible function returns an ::hw_status; ::HW_OK (0) is success. On failure
 * hw_last_error_message() gives a thread-local message naming the problem (argument, index,
 * face...; of a long list, the first few and the count of the rest), never longer than
 * ::HW_MAX_MESSAGE_SIZE bytes, and hw_status_str() a static description of the code. Output
 * arguments (`out_*`) are written only on success, but for the size a copy needs
 * (`out_needed`, below). A Rust panic never crosses this boundary: it
 * becomes ::HW_ERR_PANIC. Functions that return a value instead of a status (counts, navigation)
 * return an invalid id (::HW_INVALID_INDEX), 0 or false on a bad argument and record the message.
 * Counts given (cells, pixels, sites, a file's declared records) are checked against the data
 * given before memory proportional to them is allocated, and memory the system refuses gives
 * ::HW_ERR_OUT_OF_MEMORY, never an abort.
 *
 * Ownership. Objects (`hw_mesh *`, ...) are created by `hw_<type>_new`, `_build` or `_from_*`
 * and released by `hw_<type>_free`. `_free(NULL)` is a no-op, and `_free` refuses any pointer
 * that is not a live object of its type (one already freed, one never created) and records why
 * (hw_last_error_message()). A stale pointer cannot be told from a new object that has the same
 * address, so halfwing keeps the address of each freed object from reuse for the next
 * ::HW_FREED_ADDRESSES_KEPT frees: a second `_free` within that many is always refused; a later
 * one may free whichever object then has that address. Other calls do not check: passing them a
 * freed object is undefined behaviour. Pointers passed in are borrowed for the call only; views
 * returned (`const T *`) belong to the object and stay valid until its next mutating call.
 * Strings returned are static unless stated otherwise.
 *
 * Threads. A `const hw_mesh *` (and every other `const` object) may be used from several threads
 * at once; a non-const object needs exclusive access for the call. The last-error message is
 * per thread.
 *
 * Element ids (`hw_vertex`, `hw_halfedge`, `hw_edge`, `hw_face`) are small structs passed by
 * value, so the compiler keeps their kinds apart; `idx == HW_INVALID_INDEX` means none.
 *
 * Many ids at once, five ways: copies into a caller's buffer, every one of the shape
 * `(T *out_..., size_t capacity, size_t *out_needed)`, where `capacity` is what the buffer holds
 * and `*out_needed` (when not NULL) always receives what the whole result needs, in the same
 * unit (bytes with the terminating NUL for text), also when the call fails with
 * ::HW_ERR_BUFFER_TOO_SMALL, so a caller can ask with `NULL, 0`, allocate and call again;
 * zero-copy views of the internal arrays
 * (hw_mesh_view(), valid until the next mutating call); stack circulators (`hw_circ_*`, for the
 * textbook `do { ... } while (h != start);` loops); the inline navigation (hw_mesh_nav() and the
 * `static inline` `hw_nav_*` steps and circulators of halfwing_nav.h, included at the end of this
 * header: the same walks at the speed of array code, over trusted ids); and callbacks
 * (hw_mesh_visit(), hw_circ_visit(): a function and a `void *userdata`; the function stops a
 * visit by returning false and must not throw or `longjmp` through the call).
 */

/**
 * @defgroup errors Status, errors, version and threads
 * Status codes, the last error's message, the library's version and the threads heavy calls use.
 *
 * @defgroup ids Element ids
 * Vertex, half-edge, edge and face ids: small structs passed by value.
 *
 * @defgroup mesh Half-edge meshes
 * Creating, building (with a policy for bad input), counting and freeing meshes; the build
 * diagnostic.
 *
 * @defgroup navigation Half-edge navigation
 * Checked single steps between a mesh's elements, and zero-copy views of its arrays.
 *
 * @defgroup nav Inline half-edge navigation
 * halfwing_nav.h: `static inline` steps and circulators over trusted ids, at the speed of array
 * code.
 *
 * @defgroup circulators Half-edge circulators and callbacks
 * Stack circulators around a vertex, around a face or along a loop, and the same walks with a
 * callback.
 *
 * @defgroup topology Half-edge topology
 * Validation, boundary loops and connected components.
 *
 * @defgroup edit Half-edge editing
 * Adding and deleting elements, flip, split, collapse, triangulation and garbage collection.
 *
 * @defgroup attributes Half-edge positions and attributes
 * Vertex positions, corner normals and uvs, and typed user attributes.
 *
 * @defgroup normals Half-edge normals
 * Face, vertex and crease-angle corner normals.
 *
 * @defgroup io Files
 * Reading and writing OBJ, OFF and PLY.
 *
 * @defgroup winged Winged-edge meshes
 * Baumgart's winged-edge kernel: construction, conversions, counts, the invariant check.
 *
 * @defgroup winged_navigation Winged-edge navigation
 * Live-element tests, edge records, a vertex's and a face's edge.
 *
 * @defgroup winged_circulators Winged-edge circulators
 * A face's loop and a vertex's ring, with the per-edge orientation test.
 *
 * @defgroup winged_edit Euler operators
 * Baumgart's make and kill operators, and garbage collection after the kills.
 *
 * @defgroup winged_attributes Winged-edge positions
 * Reading and moving vertex positions.
 *
 * @defgroup winged_normals Winged-edge normals
 * Face normals and vertex normals with the half-edge kernel's weightings (Baumgart's is uniform).
 *
 * @defgroup winged_io Winged-edge tables
 * The vertex, face and edge tables in three naming conventions, as text, Markdown or CSV.
 *
 * @defgroup voronoi Voronoi diagrams
 * 2D point files, Delaunay triangulation, Voronoi diagram, clipped cells, queries, Lloyd
 * relaxation, rasters and SVG.
 *
 * @defgroup doctor Mesh doctor
 * Every defect of a face list or a mesh, named with its elements; self-intersections.
 *
 * @defgroup repair Repairs
 * Merging vertices, removing duplicate faces, unreferenced vertices and small components,
 * stitching borders.
 *
 * @defgroup surfaces Surfaces
 * Swept, revolved and ruled surfaces and primitives as meshes.
 *
 * @defgroup render Rendering buffers
 * Triangles, normals and line buffers ready for `glBufferData`.
 */

#ifndef HALFWING_H
#define HALFWING_H

/* Generated by cbindgen from the halfwing crate (see cbindgen.toml). Do not edit. */

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/**
 * The largest message halfwing gives C, in bytes with its terminating NUL: the last-error
 * message (hw_last_error_message()) and a diagnostic's summary (hw_diagnostic_summary()) never
 * need more, so a buffer of this size always takes them. Lists of elements in a message name the
 * first few and count the rest, so a message reaches this size only when it quotes a very long
 * string of the caller's (an attribute name, a path); it is then cut, and ends with
 * `… (cut)`.
 * \ingroup errors
 */
#define HW_MAX_MESSAGE_SIZE 8192

/**
 * How many of the most recently freed objects keep their address out of reuse: a second
 * `_free` of an object is refused as long as fewer objects than this were freed since its first.
 * Each keeps a few hundred bytes (its large arrays are released at once): 2 MB at most in all.
 * \ingroup mesh
 */
#define HW_FREED_ADDRESSES_KEPT 4096

/**
 * The largest count hw_set_thread_count() accepts. Above the core count of any machine halfwing
 * targets, so it limits no real use; it stops a mistaken value (`(size_t)-1`, a byte count)
 * from trying to start that many threads, each with its own stack, and rayon from silently
 * capping it.
 * \ingroup errors
 */
#define HW_MAX_THREAD_COUNT 1024

/**
 * Major version: incompatible API changes.
 * \ingroup errors
 */
#define HW_VERSION_MAJOR 0

/**
 * Minor version: added functionality.
 * \ingroup errors
 */
#define HW_VERSION_MINOR 2

/**
 * Patch version: bug fixes.
 * \ingroup errors
 */
#define HW_VERSION_PATCH 0

/**
 * `MAJOR * 10000 + MINOR * 100 + PATCH`, for `#if HW_VERSION_NUMBER >= ...` checks.
 * \ingroup errors
 */
#define HW_VERSION_NUMBER (((HW_VERSION_MAJOR * 10000) + (HW_VERSION_MINOR * 100)) + HW_VERSION_PATCH)

/**
 * The raw value of "no element": an id whose `idx` is this is invalid.
 * \ingroup ids
 */
#define HW_INVALID_INDEX UINT32_MAX

/**
 * A 2D Delaunay triangulation, without its Voronoi diagram. Opaque; build it with
 * hw_delaunay_build() and release it with hw_delaunay_free(). It never changes after
 * construction, so every function taking a `const hw_delaunay *` may run concurrently.
 *
 * Numbering as for ::hw_voronoi: sites keep their input index, a duplicated site is represented
 * by the smallest index of its group, and the arrays are those of the same names in
 * ::hw_voronoi_view() (the triangulation is the same one).
 * \ingroup voronoi
 */
typedef struct hw_delaunay hw_delaunay;

/**
 * The defects of an indexed face list, by index. Opaque; from hw_mesh_from_indexed(),
 * hw_diagnose_indexed() and the other builders; release with hw_diagnostic_free().
 *
 * Two kinds of lists: the findings describe the input as it is, whatever the policy (they are
 * the same for a build and for hw_diagnose_indexed()); ::HW_DIAGNOSTIC_LIST_SKIPPED_FACES,
 * ::HW_DIAGNOSTIC_LIST_REORIENTED_FACES and ::HW_DIAGNOSTIC_LIST_VERTEX_COPIES list what the
 * policy changed. Face indices refer to the input face list, vertex indices to the input
 * positions. Faces with fewer than 3 corners, an out-of-range index or a repeated vertex are
 * listed as such and left out of the edge, fan and area findings. Every list is sorted ascending.
 * \ingroup mesh
 */
typedef struct hw_diagnostic hw_diagnostic;

/**
 * Everything the doctor found. Opaque; from hw_doctor_examine_indexed() or
 * hw_doctor_examine_mesh(); release with hw_doctor_report_free().
 *
 * Indices are input indices: faces of the face list, vertices of its positions (for a mesh,
 * those of the face list hw_mesh_write() would write: the mesh's own ids when nothing is
 * deleted). Malformed faces are listed in the report's diagnostic and left out of every other
 * finding. The report's size follows the findings, not the mesh.
 * \ingroup doctor
 */
typedef struct hw_doctor_report hw_doctor_report;

/**
 * Pairs of faces. Opaque; from hw_self_intersections_indexed(); read with hw_face_pairs_view();
 * release with hw_face_pairs_free().
 * \ingroup doctor
 */
typedef struct hw_face_pairs hw_face_pairs;

/**
 * The old-to-new id maps of a compaction (see hw_mesh_garbage_collect()). Opaque; read with
 * hw_index_maps_view(), release with hw_index_maps_free().
 * \ingroup edit
 */
typedef struct hw_index_maps hw_index_maps;

/**
 * A half-edge polygon mesh. Opaque; create it with hw_mesh_new() or hw_mesh_from_indexed() and
 * release it with hw_mesh_free().
 * \ingroup mesh
 */
typedef struct hw_mesh hw_mesh;

/**
 * The points of a 2D point file, in file order. Opaque; read with hw_points2d_read(), look at
 * with hw_points2d_view(), release with hw_points2d_free().
 * \ingroup voronoi
 */
typedef struct hw_points2d hw_points2d;

/**
 * GPU-ready arrays of a mesh or a polygon list. Opaque; from hw_render_buffers_build(),
 * hw_render_buffers_from_polygons() or hw_render_buffers_from_voronoi_cells(); release with
 * hw_render_buffers_free(). Immutable: its views stay valid until it is freed, also after the mesh
 * it came from changes or is freed.
 * \ingroup render
 */
typedef struct hw_render_buffers hw_render_buffers;

/**
 * What hw_repair_mesh() did to every input element. Opaque; read with hw_repair_fates_list()
 * and hw_repair_fates_counts(), release with hw_repair_fates_free().
 * \ingroup repair
 */
typedef struct hw_repair_fates hw_repair_fates;

/**
 * What a repair changed. Opaque; from the `hw_soup_*` repairs, hw_mesh_remove_degenerate_faces(),
 * hw_mesh_remove_t_vertices() and hw_mesh_stitch_borders();
 * read with hw_repair_report_list() and hw_repair_report_maps(), release with
 * hw_repair_report_free(). Ids are those of the input.
 * \ingroup repair
 */
typedef struct hw_repair_report hw_repair_report;

/**
 * An indexed face list read from a file, exactly as the file numbers its vertices (nothing
 * welded, reordered or dropped). Opaque; read with hw_soup_read(), look at with hw_soup_view(),
 * release with hw_soup_free().
 * \ingroup io
 */
typedef struct hw_soup hw_soup;

/**
 * A 2D Voronoi diagram and its Delaunay triangulation. Opaque; build it with hw_voronoi_build()
 * and release it with hw_voronoi_free(). It never changes after construction, so every function
 * taking a `const hw_voronoi *` may run concurrently.
 *
 * Numbering: sites keep their input index. A duplicated site is represented by the smallest
 * index of its group (::HW_VORONOI_ARRAY_REPRESENTATIVE); the other copies have no cell, no
 * incident Delaunay edge and no Voronoi half-edge. Voronoi half-edges come in twin pairs
 * (`twin = h ^ 1`); half-edge `h` bounds the cell of `site[h]` (on its left) and separates it
 * from `site[h ^ 1]`.
 * \ingroup voronoi
 */
typedef struct hw_voronoi hw_voronoi;

/**
 * The cells of a Voronoi diagram clipped to a convex region. Opaque; made by
 * hw_voronoi_clip_rect() or hw_voronoi_clip_convex(), released with hw_voronoi_cells_free(). It
 * owns its data: it stays valid after its diagram is freed, and never changes.
 *
 * The cells tile the region without gaps or overlaps; a corner shared by several cells is one
 * entry of hw_voronoi_cells_positions(). Cells are indexed by site and counter-clockwise; a
 * duplicate site, or a site whose cell misses the region or meets it only along its boundary,
 * has an empty cell. A cell narrower than the spacing of doubles is still listed (its corners
 * may coincide once rounded; where rounding collapses it, it is rebuilt from its exact polygon
 * with corners of its own); one narrower than the rounding of its own corners can come out
 * clockwise, with twice its area within `4nε·X·D` (n corners, largest coordinate magnitude X,
 * largest offset D from the first corner, ε = DBL_EPSILON).
 * \ingroup voronoi
 */
typedef struct hw_voronoi_cells hw_voronoi_cells;

/**
 * A winged-edge (Baumgart) polygon mesh: one record per edge with its two vertices, its two
 * faces and its four wings. Opaque; create it with hw_winged_new(), hw_winged_from_indexed() or
 * hw_winged_from_mesh() and release it with hw_winged_free().
 * \ingroup winged
 */
typedef struct hw_winged hw_winged;

#ifdef __cplusplus
extern "C" {
#endif // __cplusplus

/* ----------------------------------------------------------------------------------------------
 * Status, errors, version and threads
 * ---------------------------------------------------------------------------------------------- */

/**
 * The result of a fallible C call. `HW_OK` (0) is success; every other value is an error whose
 * details `hw_last_error_message` gives.
 *
 * A plain integer type with named constants, not a Rust enum, so that a value coming back from C
 * (as in `hw_status_str`) can never be an invalid enum discriminant. Every other enumeration's
 * constants start with its type's name (`hw_normal_weighting`: `HW_NORMAL_WEIGHTING_*`); status
 * codes keep the short `HW_OK` / `HW_ERR_*` that C libraries give them, success told from
 * failure at a glance.
 * \ingroup errors
 */
typedef uint32_t hw_status;

/**
 * Success.
 * \ingroup errors
 */
#define HW_OK 0

/**
 * A required pointer argument was NULL.
 * \ingroup errors
 */
#define HW_ERR_NULL_ARGUMENT 1

/**
 * An element id (vertex, half-edge, edge, face) is out of range or deleted, or an object handle
 * was already freed.
 * \ingroup errors
 */
#define HW_ERR_INVALID_HANDLE 2

/**
 * The input data are malformed: bad sizes or counts, indices out of range, NaN or infinite
 * coordinates, an unknown enum value.
 * \ingroup errors
 */
#define HW_ERR_INVALID_INPUT 3

/**
 * The input is not a manifold and the chosen policy refuses it.
 * \ingroup errors
 */
#define HW_ERR_NON_MANIFOLD 4

/**
 * A caller's buffer is too small; the needed size was reported.
 * \ingroup errors
 */
#define HW_ERR_BUFFER_TOO_SMALL 5

/**
 * Reading or writing a file failed.
 * \ingroup errors
 */
#define HW_ERR_IO 6

/**
 * A file's contents could not be parsed.
 * \ingroup errors
 */
#define HW_ERR_PARSE 7

/**
 * A mesh operation's precondition does not hold (e.g. flipping a boundary edge); nothing changed.
 * \ingroup errors
 */
#define HW_ERR_REFUSED 8

/**
 * A Rust panic was caught at the C boundary: a bug in halfwing. The object passed in is left
 * as it was before the call only if the call does not mutate it.
 * \ingroup errors
 */
#define HW_ERR_PANIC 9

/**
 * A named item (an attribute) does not exist.
 * \ingroup errors
 */
#define HW_ERR_NOT_FOUND 10

/**
 * The system refused memory the call needed (an array proportional to a count given: cells,
 * pixels, vertices); the message names the size. Nothing was changed, and calls needing less
 * memory still work.
 * \ingroup errors
 */
#define HW_ERR_OUT_OF_MEMORY 11

/**
 * The fate of an element, in the kinds lists of hw_repair_fates_list().
 * \ingroup repair
 */
typedef uint32_t hw_fate;

/**
 * Kept: its id is the output element.
 * \ingroup repair
 */
#define HW_FATE_KEPT 0

/**
 * A vertex merged into another: its id is the output vertex it went into.
 * \ingroup repair
 */
#define HW_FATE_MERGED 1

/**
 * A face kept, reversed: its id is the output face.
 * \ingroup repair
 */
#define HW_FATE_REVERSED 2

/**
 * A face removed: fewer than 3 distinct corners after merging (id `UINT32_MAX`).
 * \ingroup repair
 */
#define HW_FATE_COLLAPSED 3

/**
 * A face removed as a duplicate: its id is the input face kept in its place.
 * \ingroup repair
 */
#define HW_FATE_DUPLICATE 4

/**
 * Removed: a face the repairing build could not keep, or a vertex with a non-finite
 * coordinate (id `UINT32_MAX`).
 * \ingroup repair
 */
#define HW_FATE_UNBUILDABLE 5

/**
 * Removed with a small component (id `UINT32_MAX`).
 * \ingroup repair
 */
#define HW_FATE_SMALL_COMPONENT 6

/**
 * A vertex removed because no kept face names it (id `UINT32_MAX`).
 * \ingroup repair
 */
#define HW_FATE_UNREFERENCED 7

/**
 * A face removed as degenerate: its corners on one line, collapsed with a short edge or
 * removed by hw_mesh_remove_degenerate_faces() (id `UINT32_MAX`).
 * \ingroup repair
 */
#define HW_FATE_DEGENERATE 8

/**
 * Copies the message of the last failed call on this thread into `out_text`, NUL-terminated.
 *
 * `*out_needed` (when `out_needed` is not NULL) always receives the size the message needs,
 * terminator included — also when the buffer is too small, so a caller can allocate and call
 * again; it is never more than ::HW_MAX_MESSAGE_SIZE, so a buffer of that size always suffices.
 * The message is empty (`out_needed` = 1) when no call has failed on this thread yet. Successful
 * calls do not clear it, and neither does this function, so it can be read as often as wanted.
 * Calls made from a thread-local destructor after this thread's storage is torn down still return
 * their status, but record no message (it reads empty).
 *
 * Returns `HW_OK`, or `HW_ERR_BUFFER_TOO_SMALL` when `out_text` is NULL or `capacity` is less than
 * the size needed (nothing is written to `out_text` then).
 *
 * # Safety
 * `out_text` must be NULL or point to `capacity` writable bytes; `out_needed` must be NULL or
 * point to a writable `size_t`.
 * \ingroup errors
 */
hw_status hw_last_error_message(char *out_text, size_t capacity, size_t *out_needed);

/**
 * A short, static, NUL-terminated English description of `status`. Unknown values give
 * `"unknown status"`. Never returns NULL; the string must not be freed.
 * \ingroup errors
 */
const char *hw_status_str(hw_status status);

/**
 * Sets how many threads bulk construction and normal computation use from now on, for every
 * thread of the process: 1 runs them single-threaded, 0 restores the default (one per core).
 * A count above ::HW_MAX_THREAD_COUNT gives `HW_ERR_INVALID_INPUT` and keeps the current
 * setting. In a build without the `parallel` feature everything is single-threaded and a valid
 * count changes nothing.
 * \ingroup errors
 */
hw_status hw_set_thread_count(size_t count);

/**
 * The version number of the library actually linked, in the form of `HW_VERSION_NUMBER`.
 * Compare with `HW_VERSION_NUMBER` to detect a header/library mismatch.
 * \ingroup errors
 */
uint32_t hw_version_number(void);

/**
 * The version of the library actually linked, as a static NUL-terminated string such as
 * `"0.2.0"`. Never NULL; must not be freed.
 * \ingroup errors
 */
const char *hw_version_string(void);

/* ----------------------------------------------------------------------------------------------
 * Half-edge meshes
 * ---------------------------------------------------------------------------------------------- */

/**
 * What hw_mesh_from_indexed() does with faces that cannot be placed in a half-edge structure.
 * \ingroup mesh
 */
typedef uint32_t hw_build_policy;

/**
 * Build the input exactly as it is, or refuse it whole: `HW_ERR_INVALID_INPUT` for a malformed
 * face or a NaN/infinite coordinate, `HW_ERR_NON_MANIFOLD` for a non-manifold or inconsistently
 * oriented edge or a non-manifold vertex. The message names the offending faces, edges and
 * vertices.
 * \ingroup mesh
 */
#define HW_BUILD_POLICY_STRICT 0

/**
 * Leave out what cannot be placed, and list it (::HW_DIAGNOSTIC_LIST_SKIPPED_FACES): malformed
 * faces, faces on a NaN/infinite vertex, then, in input order, a face whose edge is already used
 * in its direction; split non-manifold vertices (one vertex per fan,
 * ::HW_DIAGNOSTIC_LIST_VERTEX_COPIES).
 * \ingroup mesh
 */
#define HW_BUILD_POLICY_SKIP 1

/**
 * Keep every face that can be kept, and make it fit: collapse repeated corners, reverse faces so
 * neighbours agree (::HW_DIAGNOSTIC_LIST_REORIENTED_FACES), cut the surface along edges still
 * non-manifold or inconsistent and give each fan its own vertex, split non-manifold vertices, and
 * turn every closed component to face outward. Faces that cannot be kept (fewer than 3 distinct
 * corners, an out-of-range index, a corner on a NaN/infinite vertex) are left out and listed
 * (::HW_DIAGNOSTIC_LIST_SKIPPED_FACES). Accepts every input ::HW_BUILD_POLICY_SKIP accepts.
 * \ingroup mesh
 */
#define HW_BUILD_POLICY_REPAIR 2

/**
 * One list of element ids in a diagnostic (see hw_diagnostic_ids()). The values run from
 * ::HW_DIAGNOSTIC_LIST_FIRST to `HW_DIAGNOSTIC_LIST_FIRST + HW_DIAGNOSTIC_LIST_COUNT - 1`, apart
 * from the edge lists' (::hw_diagnostic_edges) and the doctor's findings' (::hw_doctor_finding),
 * so a value of one family passed where another is expected is refused, never read as a different
 * list.
 * \ingroup mesh
 */
typedef uint32_t hw_diagnostic_list;

/**
 * The first id list.
 * \ingroup mesh
 */
#define HW_DIAGNOSTIC_LIST_FIRST 16

/**
 * Faces with fewer than 3 corners.
 * \ingroup mesh
 */
#define HW_DIAGNOSTIC_LIST_FACES_TOO_SMALL 16

/**
 * Faces with a vertex index beyond the positions.
 * \ingroup mesh
 */
#define HW_DIAGNOSTIC_LIST_FACES_OUT_OF_RANGE 17

/**
 * Faces naming one vertex more than once.
 * \ingroup mesh
 */
#define HW_DIAGNOSTIC_LIST_FACES_REPEATED_VERTEX 18

/**
 * Vertices with a NaN or infinite coordinate.
 * \ingroup mesh
 */
#define HW_DIAGNOSTIC_LIST_NON_FINITE_VERTICES 19

/**
 * Vertices whose faces form more than one fan, faces being in one fan when they share an edge
 * at the vertex (two cones touching at their tips). ::HW_BUILD_POLICY_STRICT refuses them;
 * ::HW_BUILD_POLICY_SKIP and ::HW_BUILD_POLICY_REPAIR give every fan but the first a copy of the
 * vertex.
 * \ingroup mesh
 */
#define HW_DIAGNOSTIC_LIST_NON_MANIFOLD_VERTICES 20

/**
 * Vertices no face names (a vertex whose every face a policy left out is in the mesh without a
 * face, but not listed here).
 * \ingroup mesh
 */
#define HW_DIAGNOSTIC_LIST_ISOLATED_VERTICES 21

/**
 * Faces with zero area.
 * \ingroup mesh
 */
#define HW_DIAGNOSTIC_LIST_DEGENERATE_FACES 22

/**
 * Faces left out of the mesh by ::HW_BUILD_POLICY_SKIP or ::HW_BUILD_POLICY_REPAIR: mesh face `i`
 * is the `i`-th input face not listed here.
 * \ingroup mesh
 */
#define HW_DIAGNOSTIC_LIST_SKIPPED_FACES 23

/**
 * Vertices added by ::HW_BUILD_POLICY_SKIP or ::HW_BUILD_POLICY_REPAIR: mesh vertex
 * `n_input_vertices + i` copies input vertex `ids[i]` (same position).
 * \ingroup mesh
 */
#define HW_DIAGNOSTIC_LIST_VERTEX_COPIES 24

/**
 * Faces ::HW_BUILD_POLICY_REPAIR built the other way round from the input (to agree with their
 * neighbours, or to turn a closed component outward).
 * \ingroup mesh
 */
#define HW_DIAGNOSTIC_LIST_REORIENTED_FACES 25

/**
 * The number of id lists.
 * \ingroup mesh
 */
#define HW_DIAGNOSTIC_LIST_COUNT 10

/**
 * One list of edges in a diagnostic (see hw_diagnostic_edge()). The values run from
 * ::HW_DIAGNOSTIC_EDGES_FIRST to `HW_DIAGNOSTIC_EDGES_FIRST + HW_DIAGNOSTIC_EDGES_COUNT - 1`,
 * apart from the id lists' (::hw_diagnostic_list) and the doctor's findings'
 * (::hw_doctor_finding).
 * \ingroup mesh
 */
typedef uint32_t hw_diagnostic_edges;

/**
 * The first edge list.
 * \ingroup mesh
 */
#define HW_DIAGNOSTIC_EDGES_FIRST 32

/**
 * Edges used by three or more faces.
 * \ingroup mesh
 */
#define HW_DIAGNOSTIC_EDGES_NON_MANIFOLD 32

/**
 * Edges whose two faces traverse them in the same direction.
 * \ingroup mesh
 */
#define HW_DIAGNOSTIC_EDGES_INCONSISTENT 33

/**
 * The number of edge lists.
 * \ingroup mesh
 */
#define HW_DIAGNOSTIC_EDGES_COUNT 2

/**
 * Creates an empty mesh. Returns NULL only if the allocation fails.
 * \ingroup mesh
 */
hw_mesh *hw_mesh_new(void);

/**
 * Builds a mesh from an indexed polygon list.
 *
 * `positions` holds `3 * n_vertices` doubles (x, y, z per vertex); `face_sizes` holds the corner
 * count of each of the `n_faces` faces; `indices` holds the `n_indices` vertex indices of all
 * corners, face after face (so `n_indices` must equal the sum of `face_sizes`). Faces are
 * counter-clockwise seen from outside. Pairing is done in bulk by sorting edge keys.
 *
 * `policy` decides what happens to faces that do not fit a half-edge structure (see
 * ::HW_BUILD_POLICY_STRICT, ::HW_BUILD_POLICY_SKIP, ::HW_BUILD_POLICY_REPAIR). Malformed data —
 * sizes below 3 or not summing to `n_indices`, indices out of range, NaN or infinite coordinates —
 * give `HW_ERR_INVALID_INPUT` under ::HW_BUILD_POLICY_STRICT; the message names the faces and
 * vertices.
 *
 * Whatever the policy, the mesh holds no NaN or infinite coordinate (such a vertex is there as a
 * deleted vertex, its id kept) and no non-manifold vertex: every vertex query (valence,
 * circulators, normals) sees every face at its vertex.
 *
 * On success `*out_mesh` receives a new mesh to release with hw_mesh_free(), and, when
 * `out_diagnostic` is not NULL, `*out_diagnostic` a diagnostic of the input and of what the
 * policy changed, to release with hw_diagnostic_free(). When the policy refuses the input,
 * `*out_mesh` is not written but `*out_diagnostic` (when asked for) receives the refusal's
 * diagnostic, to release the same way; on any other failure neither is written.
 *
 * # Safety
 * Array arguments must point to at least as many elements as their counts say (they may be NULL
 * when the count is 0); `out_mesh` must be writable; `out_diagnostic` NULL or writable.
 * \ingroup mesh
 */
hw_status hw_mesh_from_indexed(const double *positions,
                               size_t n_vertices,
                               const uint32_t *face_sizes,
                               size_t n_faces,
                               const uint32_t *indices,
                               size_t n_indices,
                               hw_build_policy policy,
                               hw_mesh **out_mesh,
                               hw_diagnostic **out_diagnostic);

/**
 * Releases a mesh. NULL is a no-op; a mesh freed already is refused, the last error saying so
 * (within the limits the ownership conventions at the top of the header state).
 *
 * # Safety
 * `mesh` must be NULL or a mesh from this library not in use by another thread.
 * \ingroup mesh
 */
void hw_mesh_free(hw_mesh *mesh);

/**
 * Number of vertices (deleted ones not counted); 0 for a NULL mesh.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh.
 * \ingroup mesh
 */
size_t hw_mesh_n_vertices(const hw_mesh *mesh);

/**
 * Number of faces (deleted ones not counted); 0 for a NULL mesh.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh.
 * \ingroup mesh
 */
size_t hw_mesh_n_faces(const hw_mesh *mesh);

/**
 * Number of undirected edges (deleted ones not counted); 0 for a NULL mesh.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh.
 * \ingroup mesh
 */
size_t hw_mesh_n_edges(const hw_mesh *mesh);

/**
 * Number of half-edges, boundary ones included (twice the edge count); 0 for a NULL mesh.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh.
 * \ingroup mesh
 */
size_t hw_mesh_n_halfedges(const hw_mesh *mesh);

/**
 * Number of vertex slots: vertex ids run from 0 to this minus one. Equal to the vertex count
 * unless vertices were deleted and not yet garbage-collected; arrays indexed by vertex id (views,
 * normals) have this length. 0 for a NULL mesh.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh.
 * \ingroup mesh
 */
size_t hw_mesh_n_vertex_slots(const hw_mesh *mesh);

/**
 * Number of half-edge slots (twice the edge slots), as hw_mesh_n_vertex_slots() counts vertex
 * slots; 0 for a NULL mesh.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh.
 * \ingroup mesh
 */
size_t hw_mesh_n_halfedge_slots(const hw_mesh *mesh);

/**
 * Number of edge slots, as hw_mesh_n_vertex_slots() counts vertex slots; 0 for a NULL mesh.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh.
 * \ingroup mesh
 */
size_t hw_mesh_n_edge_slots(const hw_mesh *mesh);

/**
 * Number of face slots, as hw_mesh_n_vertex_slots() counts vertex slots; 0 for a NULL mesh.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh.
 * \ingroup mesh
 */
size_t hw_mesh_n_face_slots(const hw_mesh *mesh);

/**
 * The name of an id list ("isolated vertices", …) as static text; NULL for an unknown list.
 * \ingroup mesh
 */
const char *hw_diagnostic_list_name(hw_diagnostic_list list);

/**
 * The name of an edge list ("non-manifold edges (3+ faces)", …) as static text; NULL for an
 * unknown list.
 * \ingroup mesh
 */
const char *hw_diagnostic_edges_name(hw_diagnostic_edges edges);

/**
 * Analyses an indexed face list without building anything (same arguments as
 * hw_mesh_from_indexed()). Malformed data are not an error here — they are what the diagnostic
 * reports; only NULL or impossible array arguments fail, and `HW_ERR_OUT_OF_MEMORY` when the
 * analysis needs more memory than the system gives. On success `*out_diagnostic` receives
 * a diagnostic to release with hw_diagnostic_free().
 *
 * # Safety
 * As for hw_mesh_from_indexed().
 * \ingroup mesh
 */
hw_status hw_diagnose_indexed(const double *positions,
                              size_t n_vertices,
                              const uint32_t *face_sizes,
                              size_t n_faces,
                              const uint32_t *indices,
                              size_t n_indices,
                              hw_diagnostic **out_diagnostic);

/**
 * Releases a diagnostic. NULL is a no-op; a second free is refused (within the limits the
 * ownership conventions at the top of the header state).
 *
 * # Safety
 * `diagnostic` must be NULL or a diagnostic from this library, not in use by another thread.
 * \ingroup mesh
 */
void hw_diagnostic_free(hw_diagnostic *diagnostic);

/**
 * `true` when nothing at all was found; `false` otherwise or for a NULL diagnostic.
 *
 * # Safety
 * `diagnostic` must be NULL or live.
 * \ingroup mesh
 */
bool hw_diagnostic_is_clean(const hw_diagnostic *diagnostic);

/**
 * A zero-copy view of one id list (`*out_ids`, `*out_len` elements; `*out_ids` is NULL when the
 * list is empty). The view lives as long as the diagnostic.
 *
 * # Safety
 * `diagnostic` must be NULL or live; `out_ids` and `out_len` writable.
 * \ingroup mesh
 */
hw_status hw_diagnostic_ids(const hw_diagnostic *diagnostic,
                            hw_diagnostic_list list,
                            const uint32_t **out_ids,
                            size_t *out_len);

/**
 * Counts the edges in one edge list into `*out_count`; `HW_ERR_INVALID_INPUT` for an unknown
 * list.
 *
 * # Safety
 * `diagnostic` must be NULL or live; `out_count` writable.
 * \ingroup mesh
 */
hw_status hw_diagnostic_count_edges(const hw_diagnostic *diagnostic,
                                    hw_diagnostic_edges edges,
                                    size_t *out_count);

/**
 * Edge `index` of an edge list: its two input vertices (smaller first) in `out_vertices[0..2]`
 * and a zero-copy view of the input faces using it (ascending; NULL when empty), valid as long as
 * the diagnostic.
 *
 * # Safety
 * `diagnostic` must be NULL or live; `out_vertices` must hold 2 writable `uint32_t`;
 * `out_faces` and `out_n_faces` writable.
 * \ingroup mesh
 */
hw_status hw_diagnostic_edge(const hw_diagnostic *diagnostic,
                             hw_diagnostic_edges edges,
                             size_t index,
                             uint32_t *out_vertices,
                             const uint32_t **out_faces,
                             size_t *out_n_faces);

/**
 * A human-readable account, copied NUL-terminated into `out_text`: one line per non-empty list,
 * with its count and its first 8 elements
 * (`12 isolated vertices: v0 v1 v2 v3 v4 v5 v6 v7 … and 4 more`); an edge names its first 8
 * faces the same way. `*out_needed` receives the size needed even when `out_text` is too small
 * (then `HW_ERR_BUFFER_TOO_SMALL` and nothing is written to `out_text`); it is never more than
 * ::HW_MAX_MESSAGE_SIZE, whatever the input.
 *
 * # Safety
 * `diagnostic` must be NULL or live; `out_text` NULL or `capacity` writable bytes; `out_needed`
 * NULL or writable.
 * \ingroup mesh
 */
hw_status hw_diagnostic_summary(const hw_diagnostic *diagnostic,
                                char *out_text,
                                size_t capacity,
                                size_t *out_needed);

/* ----------------------------------------------------------------------------------------------
 * Half-edge navigation
 * ---------------------------------------------------------------------------------------------- */

/**
 * A vertex id.
 * \ingroup ids
 */
typedef struct {
  /**
   * The index; `HW_INVALID_INDEX` means none.
   */
  uint32_t idx;
} hw_vertex;

/**
 * A half-edge id. Half-edges come in pairs: the twin of `h` is `h.idx ^ 1`, its edge `h.idx >> 1`.
 * \ingroup ids
 */
typedef struct {
  /**
   * The index; `HW_INVALID_INDEX` means none.
   */
  uint32_t idx;
} hw_halfedge;

/**
 * A face id.
 * \ingroup ids
 */
typedef struct {
  /**
   * The index; `HW_INVALID_INDEX` means none.
   */
  uint32_t idx;
} hw_face;

/**
 * An (undirected) edge id: edge `e` has the half-edges `2 e` and `2 e + 1`.
 * \ingroup ids
 */
typedef struct {
  /**
   * The index; `HW_INVALID_INDEX` means none.
   */
  uint32_t idx;
} hw_edge;

/**
 * Which internal array hw_mesh_view() shows.
 * \ingroup navigation
 */
typedef uint32_t hw_mesh_array;

/**
 * Per half-edge: the vertex it leaves.
 * \ingroup navigation
 */
#define HW_MESH_ARRAY_HALFEDGE_ORIGIN 0

/**
 * Per half-edge: the next half-edge around its face or boundary loop.
 * \ingroup navigation
 */
#define HW_MESH_ARRAY_HALFEDGE_NEXT 1

/**
 * Per half-edge: the previous half-edge around its face or boundary loop.
 * \ingroup navigation
 */
#define HW_MESH_ARRAY_HALFEDGE_PREV 2

/**
 * Per half-edge: its face (`HW_INVALID_INDEX` on a boundary).
 * \ingroup navigation
 */
#define HW_MESH_ARRAY_HALFEDGE_FACE 3

/**
 * Per vertex: its outgoing half-edge (the boundary one on a boundary; invalid when isolated).
 * \ingroup navigation
 */
#define HW_MESH_ARRAY_VERTEX_HALFEDGE 4

/**
 * Per face: one of its half-edges.
 * \ingroup navigation
 */
#define HW_MESH_ARRAY_FACE_HALFEDGE 5

/**
 * The vertex half-edge `h` leaves (`Origin` or `v` in textbook notation).
 *
 * # Safety
 * `mesh` must be NULL or a live mesh.
 * \ingroup navigation
 */
hw_vertex hw_mesh_he_origin(const hw_mesh *mesh, hw_halfedge h);

/**
 * The vertex half-edge `h` points to.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh.
 * \ingroup navigation
 */
hw_vertex hw_mesh_he_target(const hw_mesh *mesh, hw_halfedge h);

/**
 * The opposite half-edge of `h` (`h.idx ^ 1`; `Twin` or `sym` in textbook notation).
 *
 * # Safety
 * `mesh` must be NULL or a live mesh.
 * \ingroup navigation
 */
hw_halfedge hw_mesh_he_twin(const hw_mesh *mesh, hw_halfedge h);

/**
 * The next half-edge around `h`'s face (counter-clockwise seen from outside), or along its
 * boundary loop when `h` is a boundary half-edge.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh.
 * \ingroup navigation
 */
hw_halfedge hw_mesh_he_next(const hw_mesh *mesh, hw_halfedge h);

/**
 * The previous half-edge around `h`'s face or boundary loop.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh.
 * \ingroup navigation
 */
hw_halfedge hw_mesh_he_prev(const hw_mesh *mesh, hw_halfedge h);

/**
 * The face `h` borders; an invalid face (without an error) for a boundary half-edge.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh.
 * \ingroup navigation
 */
hw_face hw_mesh_he_face(const hw_mesh *mesh, hw_halfedge h);

/**
 * The undirected edge of `h` (`h.idx >> 1`).
 *
 * # Safety
 * `mesh` must be NULL or a live mesh.
 * \ingroup navigation
 */
hw_edge hw_mesh_he_edge(const hw_mesh *mesh, hw_halfedge h);

/**
 * One of the two half-edges of `e`: `side` 0 gives `2 e`, 1 gives `2 e + 1`.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh.
 * \ingroup navigation
 */
hw_halfedge hw_mesh_edge_halfedge(const hw_mesh *mesh, hw_edge e, uint32_t side);

/**
 * The outgoing half-edge stored at `v` (its boundary half-edge when `v` is on a boundary, so
 * circulating from it visits the whole fan); invalid, without an error, for an isolated vertex.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh.
 * \ingroup navigation
 */
hw_halfedge hw_mesh_vertex_halfedge(const hw_mesh *mesh, hw_vertex v);

/**
 * One half-edge of `f` (where its loops start).
 *
 * # Safety
 * `mesh` must be NULL or a live mesh.
 * \ingroup navigation
 */
hw_halfedge hw_mesh_face_halfedge(const hw_mesh *mesh, hw_face f);

/**
 * `true` when `h` has no face (it lies on a boundary loop).
 *
 * # Safety
 * `mesh` must be NULL or a live mesh.
 * \ingroup navigation
 */
bool hw_mesh_he_is_boundary(const hw_mesh *mesh, hw_halfedge h);

/**
 * `true` when one side of `e` has no face.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh.
 * \ingroup navigation
 */
bool hw_mesh_edge_is_boundary(const hw_mesh *mesh, hw_edge e);

/**
 * `true` when `v` is on a boundary (or isolated).
 *
 * # Safety
 * `mesh` must be NULL or a live mesh.
 * \ingroup navigation
 */
bool hw_mesh_vertex_is_boundary(const hw_mesh *mesh, hw_vertex v);

/**
 * `true` when a side of `f` is on a boundary.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh.
 * \ingroup navigation
 */
bool hw_mesh_face_is_boundary(const hw_mesh *mesh, hw_face f);

/**
 * Number of edges at `v` (0 when isolated, or for an invalid id).
 *
 * # Safety
 * `mesh` must be NULL or a live mesh.
 * \ingroup navigation
 */
uint32_t hw_mesh_vertex_valence(const hw_mesh *mesh, hw_vertex v);

/**
 * Number of sides of `f` (0 for an invalid id).
 *
 * # Safety
 * `mesh` must be NULL or a live mesh.
 * \ingroup navigation
 */
uint32_t hw_mesh_face_degree(const hw_mesh *mesh, hw_face f);

/**
 * A read-only view of one connectivity array: `*out_data` (NULL when empty) and its length
 * `*out_len`.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh; `out_data` and `out_len` writable.
 * \ingroup navigation
 */
hw_status hw_mesh_view(const hw_mesh *mesh,
                       hw_mesh_array which,
                       const uint32_t **out_data,
                       size_t *out_len);

/**
 * A read-only view of the vertex positions: `*out_xyz` holds `3 * *out_n_vertices` doubles
 * (x, y, z per vertex; NULL when there are none).
 *
 * # Safety
 * `mesh` must be NULL or a live mesh; `out_xyz` and `out_n_vertices` writable.
 * \ingroup navigation
 */
hw_status hw_mesh_view_positions(const hw_mesh *mesh,
                                 const double **out_xyz,
                                 size_t *out_n_vertices);

/* ----------------------------------------------------------------------------------------------
 * Inline half-edge navigation
 * ---------------------------------------------------------------------------------------------- */

/**
 * A navigation view of a mesh: its connectivity arrays (zero-copy, as hw_mesh_view() gives them)
 * and their sizes, filled by hw_mesh_nav() and read by the inline `hw_nav_*` functions of
 * halfwing_nav.h. Valid until the next call that modifies the mesh (or frees it). Arrays are
 * indexed by id, deleted slots included until hw_mesh_garbage_collect(); an unused slot holds
 * `HW_INVALID_INDEX`. A pointer is NULL when its array is empty.
 * \ingroup nav
 */
typedef struct {
  /**
   * Per half-edge: the vertex it leaves.
   */
  const uint32_t *origin;
  /**
   * Per half-edge: the next half-edge around its face or boundary loop.
   */
  const uint32_t *next;
  /**
   * Per half-edge: the previous half-edge around its face or boundary loop.
   */
  const uint32_t *prev;
  /**
   * Per half-edge: its face (`HW_INVALID_INDEX` on a boundary).
   */
  const uint32_t *face;
  /**
   * Per vertex: its outgoing half-edge (the boundary one on a boundary; invalid when isolated
   * or deleted).
   */
  const uint32_t *vertex_halfedge;
  /**
   * Per face: one of its half-edges.
   */
  const uint32_t *face_halfedge;
  /**
   * Per vertex slot: `true` when deleted; NULL while no vertex has been deleted.
   */
  const bool *vertex_deleted;
  /**
   * Per edge slot: `true` when deleted (both half-edges); NULL while no edge has been deleted.
   */
  const bool *edge_deleted;
  /**
   * Per face slot: `true` when deleted; NULL while no face has been deleted.
   */
  const bool *face_deleted;
  /**
   * Vertex slots (valid vertex ids are below this), deleted ones included.
   */
  size_t n_vertex_slots;
  /**
   * Half-edge slots, deleted ones included.
   */
  size_t n_halfedge_slots;
  /**
   * Face slots, deleted ones included.
   */
  size_t n_face_slots;
} hw_nav;

/**
 * Fills `*out` with the navigation view of `mesh` (see ::hw_nav and halfwing_nav.h).
 *
 * # Safety
 * `mesh` must be NULL or a live mesh; `out` NULL or writable.
 * \ingroup nav
 */
hw_status hw_mesh_nav(const hw_mesh *mesh, hw_nav *out);

/* ----------------------------------------------------------------------------------------------
 * Half-edge circulators and callbacks
 * ---------------------------------------------------------------------------------------------- */

/**
 * What a circulator yields.
 * \ingroup circulators
 */
typedef uint32_t hw_circulator_kind;

/**
 * Half-edges: a vertex's outgoing ones, a face's sides, a loop's members.
 * \ingroup circulators
 */
#define HW_CIRCULATOR_KIND_HALFEDGES 0

/**
 * Around a vertex only: the incoming half-edges (twins of the outgoing ones).
 * \ingroup circulators
 */
#define HW_CIRCULATOR_KIND_INCOMING 1

/**
 * Vertices: a vertex's neighbours, a face's corners.
 * \ingroup circulators
 */
#define HW_CIRCULATOR_KIND_VERTICES 2

/**
 * Edges: at a vertex, or the sides of a face.
 * \ingroup circulators
 */
#define HW_CIRCULATOR_KIND_EDGES 3

/**
 * Faces: around a vertex (outside skipped), or across a face's sides (boundary sides skipped).
 * \ingroup circulators
 */
#define HW_CIRCULATOR_KIND_FACES 4

/**
 * A circulator's state, kept on the caller's stack. Fill it with hw_circ_around_vertex(),
 * hw_circ_around_face() or hw_circ_along_loop(); read it with the `hw_circ_next_*` call of its
 * kind. Treat the fields as private. It borrows the mesh: do not modify the mesh while walking.
 * \ingroup circulators
 */
typedef struct {
  /**
   * The mesh walked.
   */
  const hw_mesh *mesh;
  /**
   * The half-edge the walk started at; reaching it again ends the walk.
   */
  uint32_t start;
  /**
   * The half-edge the walk yields next, or `HW_INVALID_INDEX` once it is over.
   */
  uint32_t current;
  /**
   * Steps left before the bound on a walk's length stops it (a corrupt cycle cannot hang).
   */
  uint32_t remaining;
  /**
   * What it walks around: a vertex, a face or a boundary loop (internal code).
   */
  uint32_t center;
  /**
   * What it yields.
   */
  hw_circulator_kind kind;
} hw_circulator;

/**
 * An element kind, to pick one of several per-kind arrays.
 * \ingroup ids
 */
typedef uint32_t hw_element_kind;

/**
 * Vertices.
 * \ingroup ids
 */
#define HW_ELEMENT_KIND_VERTEX 0

/**
 * Half-edges.
 * \ingroup ids
 */
#define HW_ELEMENT_KIND_HALFEDGE 1

/**
 * Edges.
 * \ingroup ids
 */
#define HW_ELEMENT_KIND_EDGE 2

/**
 * Faces.
 * \ingroup ids
 */
#define HW_ELEMENT_KIND_FACE 3

/**
 * A caller's function called once per id by the `_visit` calls, with the `userdata` given to
 * them. Returns `true` to go on, `false` to stop the visit there.
 * \ingroup circulators
 */
typedef bool (*hw_visit_fn)(uint32_t idx, void *userdata);

/**
 * Starts a walk around vertex `v`. An isolated vertex gives an empty walk.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh; `out` writable.
 * \ingroup circulators
 */
hw_status hw_circ_around_vertex(const hw_mesh *mesh,
                                hw_vertex v,
                                hw_circulator_kind kind,
                                hw_circulator *out);

/**
 * Starts a walk around face `f`.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh; `out` writable.
 * \ingroup circulators
 */
hw_status hw_circ_around_face(const hw_mesh *mesh,
                              hw_face f,
                              hw_circulator_kind kind,
                              hw_circulator *out);

/**
 * Starts a walk by `next` from `h`: a face's sides, or a whole boundary loop when `h` is a
 * boundary half-edge. Yields half-edges (`kind` is ::HW_CIRCULATOR_KIND_HALFEDGES).
 *
 * # Safety
 * `mesh` must be NULL or a live mesh; `out` writable.
 * \ingroup circulators
 */
hw_status hw_circ_along_loop(const hw_mesh *mesh, hw_halfedge h, hw_circulator *out);

/**
 * Next half-edge of a ::HW_CIRCULATOR_KIND_HALFEDGES or ::HW_CIRCULATOR_KIND_INCOMING circulator.
 *
 * # Safety
 * `circulator` must be NULL or a circulator over a live, unmodified mesh; `out` writable.
 * \ingroup circulators
 */
bool hw_circ_next_halfedge(hw_circulator *circulator, hw_halfedge *out);

/**
 * Next vertex of a ::HW_CIRCULATOR_KIND_VERTICES circulator.
 *
 * # Safety
 * `circulator` must be NULL or a circulator over a live, unmodified mesh; `out` writable.
 * \ingroup circulators
 */
bool hw_circ_next_vertex(hw_circulator *circulator, hw_vertex *out);

/**
 * Next edge of a ::HW_CIRCULATOR_KIND_EDGES circulator.
 *
 * # Safety
 * `circulator` must be NULL or a circulator over a live, unmodified mesh; `out` writable.
 * \ingroup circulators
 */
bool hw_circ_next_edge(hw_circulator *circulator, hw_edge *out);

/**
 * Next face of a ::HW_CIRCULATOR_KIND_FACES circulator.
 *
 * # Safety
 * `circulator` must be NULL or a circulator over a live, unmodified mesh; `out` writable.
 * \ingroup circulators
 */
bool hw_circ_next_face(hw_circulator *circulator, hw_face *out);

/**
 * Calls `visit(id, userdata)` for every live (not deleted) element of `kind`
 * (::HW_ELEMENT_KIND_VERTEX, ::HW_ELEMENT_KIND_HALFEDGE, ::HW_ELEMENT_KIND_EDGE or
 * ::HW_ELEMENT_KIND_FACE), in increasing id order, until `visit` returns `false`. `*out_visited`,
 * when `out_visited` is not NULL, receives the number of calls made. `visit` may read the mesh but
 * must not free it, and must not throw or `longjmp` through this call. An empty mesh makes no
 * call.
 *
 * Returns `HW_ERR_NULL_ARGUMENT` for a NULL mesh or `visit`, `HW_ERR_INVALID_INPUT` for an
 * unknown kind (no call is made then).
 *
 * # Safety
 * `mesh` must be NULL or a live mesh; `out_visited` NULL or writable.
 * \ingroup circulators
 */
hw_status hw_mesh_visit(const hw_mesh *mesh,
                        hw_element_kind kind,
                        hw_visit_fn visit,
                        void *userdata,
                        size_t *out_visited);

/**
 * Calls `visit(id, userdata)` for each element `circulator` yields (ids of the kind it was
 * started with: half-edges, vertices, edges or faces), until the walk ends or `visit` returns
 * `false`; the circulator is left where the visit stopped. `*out_visited`, when `out_visited` is
 * not NULL, receives the number of calls made. `visit` may read the mesh but must not modify or
 * free it, and must not throw or `longjmp` through this call.
 *
 * Returns `HW_ERR_NULL_ARGUMENT` for a NULL circulator or `visit`.
 *
 * # Safety
 * `circulator` must be NULL or a circulator over a live, unmodified mesh; `out_visited` NULL or
 * writable.
 * \ingroup circulators
 */
hw_status hw_circ_visit(hw_circulator *circulator,
                        hw_visit_fn visit,
                        void *userdata,
                        size_t *out_visited);

/* ----------------------------------------------------------------------------------------------
 * Half-edge topology
 * ---------------------------------------------------------------------------------------------- */

/**
 * Validates every invariant of the half-edge structure (twins, next/prev, closed face and
 * boundary loops, vertex half-edges outgoing and on the boundary when there is one, ids in
 * range), with every walk bounded. `HW_OK`, or `HW_ERR_INVALID_INPUT` with a message naming the
 * first broken invariant and its element.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh.
 * \ingroup topology
 */
hw_status hw_mesh_check(const hw_mesh *mesh);

/**
 * Counts the boundary loops (holes and open borders) into `*out_count`: a walk over the
 * half-edges, not a stored count.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh; `out_count` writable.
 * \ingroup topology
 */
hw_status hw_mesh_count_boundary_loops(const hw_mesh *mesh, size_t *out_count);

/**
 * One half-edge of every boundary loop (the lowest id of the loop), ascending, copied into
 * `out_halfedges` (`capacity` elements). `*out_needed` always receives the loop count; walk a loop
 * with hw_mesh_he_next() or hw_circ_along_loop().
 *
 * # Safety
 * `mesh` must be NULL or a live mesh; `out_halfedges` NULL or `capacity` writable elements;
 * `out_needed` NULL or writable.
 * \ingroup topology
 */
hw_status hw_mesh_boundary_loops(const hw_mesh *mesh,
                                 hw_halfedge *out_halfedges,
                                 size_t capacity,
                                 size_t *out_needed);

/**
 * Counts the connected components (faces connected across edges, as CGAL and OpenMesh count
 * them; fans that only touch at a vertex are separate) into `*out_count`: a pass over the
 * faces, not a stored count.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh; `out_count` writable.
 * \ingroup topology
 */
hw_status hw_mesh_count_components(const hw_mesh *mesh, size_t *out_count);

/**
 * The component of every face (`0..count`, numbered by lowest face; `HW_INVALID_INDEX` for a
 * deleted face), indexed by face id, copied into `out_components` (`capacity` elements).
 * `*out_needed` always receives the number of face slots.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh; `out_components` NULL or `capacity` writable elements;
 * `out_needed` NULL or writable.
 * \ingroup topology
 */
hw_status hw_mesh_face_components(const hw_mesh *mesh,
                                  uint32_t *out_components,
                                  size_t capacity,
                                  size_t *out_needed);

/* ----------------------------------------------------------------------------------------------
 * Half-edge editing
 * ---------------------------------------------------------------------------------------------- */

/**
 * Adds an isolated vertex at `xyz[0..3]` (finite) and gives its id in `*out_vertex`.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh no other thread uses; `xyz` 3 doubles; `out_vertex`
 * writable.
 * \ingroup edit
 */
hw_status hw_mesh_add_vertex(hw_mesh *mesh, const double *xyz, hw_vertex *out_vertex);

/**
 * Adds the face with corners `vertices[0..n]` (counter-clockwise seen from outside; at least 3,
 * distinct, live) and gives its id in `*out_face`; its loop starts at `vertices[0]`. Existing
 * boundary sides are reused, missing edges created; the face and its corners have zero
 * attributes. `HW_ERR_INVALID_HANDLE` for a bad vertex id; `HW_ERR_REFUSED`, with the mesh
 * unchanged, for fewer than 3 or repeated corners, a side that has a face on this side already
 * (complex edge), or a corner with no gap for the face (complex vertex).
 *
 * # Safety
 * `mesh` must be NULL or a live mesh no other thread uses; `vertices` NULL (when `n` is 0) or
 * `n` ids; `out_face` writable.
 * \ingroup edit
 */
hw_status hw_mesh_add_face(hw_mesh *mesh, const hw_vertex *vertices, size_t n, hw_face *out_face);

/**
 * Deletes face `f`; its edges with no face left go too, and, when `delete_isolated_vertices`,
 * its vertices left without edges.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh no other thread uses.
 * \ingroup edit
 */
hw_status hw_mesh_delete_face(hw_mesh *mesh, hw_face f, bool delete_isolated_vertices);

/**
 * Deletes edge `e` with the faces on both its sides (see hw_mesh_delete_face()).
 *
 * # Safety
 * `mesh` must be NULL or a live mesh no other thread uses.
 * \ingroup edit
 */
hw_status hw_mesh_delete_edge(hw_mesh *mesh, hw_edge e, bool delete_isolated_vertices);

/**
 * Deletes vertex `v` with every face around it.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh no other thread uses.
 * \ingroup edit
 */
hw_status hw_mesh_delete_vertex(hw_mesh *mesh, hw_vertex v);

/**
 * Flips interior edge `e` between two triangles to join their other two corners. Refused on a
 * boundary edge, between non-triangles, or when the new edge exists already.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh no other thread uses.
 * \ingroup edit
 */
hw_status hw_mesh_flip_edge(hw_mesh *mesh, hw_edge e);

/**
 * Splits edge `e` at a new vertex placed at `xyz[0..3]`, given in `*out_vertex`; the faces beside
 * the edge gain a corner (they are not triangulated).
 *
 * # Safety
 * `mesh` must be NULL or a live mesh no other thread uses; `xyz` 3 doubles; `out_vertex`
 * writable.
 * \ingroup edit
 */
hw_status hw_mesh_split_edge(hw_mesh *mesh, hw_edge e, const double *xyz, hw_vertex *out_vertex);

/**
 * Splits the face holding half-edges `h0` and `h1` with a new edge from `target(h0)` to
 * `target(h1)`; `*out_halfedge` receives the new half-edge inside the original face.
 * `HW_ERR_REFUSED`, the mesh unchanged, when the two corners are one vertex or already joined
 * by an edge, or a side would have fewer than 3 corners.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh no other thread uses; `out_halfedge` writable.
 * \ingroup edit
 */
hw_status hw_mesh_split_face(hw_mesh *mesh,
                             hw_halfedge h0,
                             hw_halfedge h1,
                             hw_halfedge *out_halfedge);

/**
 * Collapses half-edge `h`: its origin merges into its target (which keeps its position, given in
 * `*out_vertex`); a polygon beside the edge loses a corner. Refused unless the link condition
 * holds and the triangles beside the edge can vanish without breaking the surface.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh no other thread uses; `out_vertex` writable.
 * \ingroup edit
 */
hw_status hw_mesh_collapse_halfedge(hw_mesh *mesh, hw_halfedge h, hw_vertex *out_vertex);

/**
 * Splits polygon `f` into triangles, the ones the render buffers draw for it (none folded on a
 * non-convex face; O(n log n) for n corners); `*out_n_faces`, when not NULL, receives the number
 * of triangles (`f` is the first of them). When a diagonal of those triangles is an edge
 * already, a few other triangulations are tried; `HW_ERR_REFUSED`, the mesh unchanged, when
 * each needs an existing edge or joins a vertex to itself.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh no other thread uses; `out_n_faces` NULL or writable.
 * \ingroup edit
 */
hw_status hw_mesh_triangulate_face(hw_mesh *mesh, hw_face f, size_t *out_n_faces);

/**
 * Removes deleted elements for good, renumbering the live ones in their order. When
 * `out_maps` is not NULL it receives the old-to-new maps (deleted → `HW_INVALID_INDEX`).
 *
 * # Safety
 * `mesh` must be NULL or a live mesh no other thread uses; `out_maps` NULL or writable.
 * \ingroup edit
 */
hw_status hw_mesh_garbage_collect(hw_mesh *mesh, hw_index_maps **out_maps);

/**
 * A read-only view of the old-to-new map of one element kind (`*out_map`, NULL when empty, with
 * `*out_len` entries, one per old id slot). Lives as long as the maps.
 *
 * # Safety
 * `maps` must be NULL or live; `out_map` and `out_len` writable.
 * \ingroup edit
 */
hw_status hw_index_maps_view(const hw_index_maps *maps,
                             hw_element_kind kind,
                             const uint32_t **out_map,
                             size_t *out_len);

/**
 * Releases index maps. NULL is a no-op; a second free is refused (within the limits the
 * ownership conventions at the top of the header state).
 *
 * # Safety
 * `maps` must be NULL or maps from this library, not in use by another thread.
 * \ingroup edit
 */
void hw_index_maps_free(hw_index_maps *maps);

/* ----------------------------------------------------------------------------------------------
 * Half-edge positions and attributes
 * ---------------------------------------------------------------------------------------------- */

/**
 * The numeric type of an attribute column.
 * \ingroup attributes
 */
typedef uint32_t hw_scalar_type;

/**
 * `double`.
 * \ingroup attributes
 */
#define HW_SCALAR_TYPE_F64 0

/**
 * `float`.
 * \ingroup attributes
 */
#define HW_SCALAR_TYPE_F32 1

/**
 * `int32_t`.
 * \ingroup attributes
 */
#define HW_SCALAR_TYPE_I32 2

/**
 * `uint32_t`.
 * \ingroup attributes
 */
#define HW_SCALAR_TYPE_U32 3

/**
 * Copies the position of `v` into `out_xyz[0..3]`.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh; `out_xyz` must hold 3 writable doubles.
 * \ingroup attributes
 */
hw_status hw_mesh_vertex_position(const hw_mesh *mesh, hw_vertex v, double *out_xyz);

/**
 * Moves `v` to `xyz[0..3]`. Non-finite coordinates are refused (`HW_ERR_INVALID_INPUT`).
 *
 * # Safety
 * `mesh` must be NULL or a live mesh used by no other thread; `xyz` must hold 3 doubles.
 * \ingroup attributes
 */
hw_status hw_mesh_set_vertex_position(hw_mesh *mesh, hw_vertex v, const double *xyz);

/**
 * Adds a zero-filled attribute `name` of `components` (1 to 16) values of type `scalar` per
 * element of `kind`. `HW_ERR_INVALID_INPUT` when the name is taken, empty, not UTF-8 or starts
 * with `hw:` (reserved), or the kind, type or count is out of range.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh no other thread uses; `name` NULL or NUL-terminated.
 * \ingroup attributes
 */
hw_status hw_mesh_attribute_add(hw_mesh *mesh,
                                hw_element_kind kind,
                                const char *name,
                                hw_scalar_type scalar,
                                size_t components);

/**
 * Removes attribute `name` of `kind` (`"hw:corner_normal"` and `"hw:corner_uv"` included).
 * `HW_ERR_NOT_FOUND` when there is none.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh no other thread uses; `name` NULL or NUL-terminated.
 * \ingroup attributes
 */
hw_status hw_mesh_attribute_remove(hw_mesh *mesh, hw_element_kind kind, const char *name);

/**
 * The type and component count of attribute `name` of `kind` (`HW_ERR_NOT_FOUND` when there is
 * none; a way to test for one). Either output may be NULL.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh; `name` NULL or NUL-terminated; outputs NULL or writable.
 * \ingroup attributes
 */
hw_status hw_mesh_attribute_info(const hw_mesh *mesh,
                                 hw_element_kind kind,
                                 const char *name,
                                 hw_scalar_type *out_scalar,
                                 size_t *out_components);

/**
 * A read-only view of attribute `name` of `kind`, which must hold `scalar` values:
 * `*out_data` (cast it to `const double *`, `const float *`, ...; NULL when empty) holds
 * `*out_len` scalars, `components` per element slot. `HW_ERR_NOT_FOUND` for an unknown name,
 * `HW_ERR_INVALID_INPUT` for another type.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh; `name` NULL or NUL-terminated; `out_data`, `out_len`
 * writable.
 * \ingroup attributes
 */
hw_status hw_mesh_attribute_view(const hw_mesh *mesh,
                                 hw_element_kind kind,
                                 const char *name,
                                 hw_scalar_type scalar,
                                 const void **out_data,
                                 size_t *out_len);

/**
 * Writable access to attribute `name` of `kind` (layout as hw_mesh_attribute_view()): write
 * through `*out_data` (NULL when empty) until the next call that modifies the mesh.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh no other thread uses; `name` NULL or NUL-terminated;
 * `out_data`, `out_len` writable.
 * \ingroup attributes
 */
hw_status hw_mesh_attribute_data(hw_mesh *mesh,
                                 hw_element_kind kind,
                                 const char *name,
                                 hw_scalar_type scalar,
                                 void **out_data,
                                 size_t *out_len);

/**
 * Counts the attributes of `kind` (halfwing's own `hw:` ones included) into `*out_count`;
 * `HW_ERR_INVALID_INPUT` for an unknown kind.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh; `out_count` writable.
 * \ingroup attributes
 */
hw_status hw_mesh_count_attributes(const hw_mesh *mesh, hw_element_kind kind, size_t *out_count);

/**
 * Copies the name of attribute number `index` (`0 .. count`, in the order they were added) of
 * `kind` NUL-terminated into `out_text` of `capacity` bytes; `*out_needed` (when not NULL)
 * receives the size needed. `HW_ERR_BUFFER_TOO_SMALL` when it does not fit, `HW_ERR_NOT_FOUND`
 * when `index` is past the last.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh; `out_text` NULL or `capacity` writable bytes; `out_needed`
 * NULL or writable.
 * \ingroup attributes
 */
hw_status hw_mesh_attribute_name(const hw_mesh *mesh,
                                 hw_element_kind kind,
                                 size_t index,
                                 char *out_text,
                                 size_t capacity,
                                 size_t *out_needed);

/**
 * A read-only view of the corner normals: `*out_xyz` holds `3 * *out_n_halfedges` doubles (x,
 * y, z per half-edge slot, boundary ones included; NULL when empty). `HW_ERR_NOT_FOUND` when
 * the mesh has none (a mesh read from a file with normals, or given them with
 * hw_mesh_corner_normals_set(), has them). A zero normal means the corner has none: boundary
 * half-edges, and the corners an OBJ gives no normal while giving others one.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh; `out_xyz` and `out_n_halfedges` writable.
 * \ingroup attributes
 */
hw_status hw_mesh_corner_normals_view(const hw_mesh *mesh,
                                      const double **out_xyz,
                                      size_t *out_n_halfedges);

/**
 * Sets the corner normals (adding them when the mesh has none) from `3 * n_halfedges` finite
 * doubles; `n_halfedges` must be the half-edge slot count (hw_mesh_n_halfedge_slots()). Writing
 * single values in place: hw_mesh_attribute_data() on `"hw:corner_normal"`.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh no other thread uses; `xyz` NULL or `3 * n_halfedges`
 * doubles.
 * \ingroup attributes
 */
hw_status hw_mesh_corner_normals_set(hw_mesh *mesh, const double *xyz, size_t n_halfedges);

/**
 * A read-only view of the corner texture coordinates: `*out_uv` holds `2 * *out_n_halfedges`
 * doubles (u, v per half-edge slot; NULL when empty). `HW_ERR_NOT_FOUND` when the mesh has none.
 * Corners an OBJ gives no texture coordinate while giving others one hold (0, 0).
 *
 * # Safety
 * `mesh` must be NULL or a live mesh; `out_uv` and `out_n_halfedges` writable.
 * \ingroup attributes
 */
hw_status hw_mesh_corner_uvs_view(const hw_mesh *mesh,
                                  const double **out_uv,
                                  size_t *out_n_halfedges);

/**
 * Sets the corner texture coordinates (adding them when needed) from `2 * n_halfedges` finite
 * doubles, `n_halfedges` being the half-edge slot count.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh no other thread uses; `uv` NULL or `2 * n_halfedges`
 * doubles.
 * \ingroup attributes
 */
hw_status hw_mesh_corner_uvs_set(hw_mesh *mesh, const double *uv, size_t n_halfedges);

/* ----------------------------------------------------------------------------------------------
 * Half-edge normals
 * ---------------------------------------------------------------------------------------------- */

/**
 * How a vertex normal weighs the faces around it.
 * \ingroup normals
 */
typedef uint32_t hw_normal_weighting;

/**
 * Unit face normals summed: OpenMesh's default, the textbook average.
 * \ingroup normals
 */
#define HW_NORMAL_WEIGHTING_UNIFORM 0

/**
 * Face normals weighted by face area.
 * \ingroup normals
 */
#define HW_NORMAL_WEIGHTING_AREA 1

/**
 * Unit face normals weighted by the face's angle at the vertex: pmp's default.
 * \ingroup normals
 */
#define HW_NORMAL_WEIGHTING_ANGLE 2

/**
 * Unit normal of face `f` by Newell's method (outward for a counter-clockwise face; zero for a
 * degenerate face), written to `out_normal[0..3]` (required: NULL gives `HW_ERR_NULL_ARGUMENT`):
 * what hw_mesh_face_normals() gives `f`, bit for bit.
 *
 * # Safety
 * `mesh` must be NULL or live; `out_normal` must point to 3 writable doubles.
 * \ingroup normals
 */
hw_status hw_mesh_face_normal(const hw_mesh *mesh, hw_face f, double *out_normal);

/**
 * Unit normal of vertex `v` with the chosen weighting (the faces of every fan of a non-manifold
 * vertex count; zero when it has none), written to `out_normal[0..3]` (required: NULL gives
 * `HW_ERR_NULL_ARGUMENT`): what hw_mesh_vertex_normals() gives `v`, bit for bit.
 *
 * # Safety
 * `mesh` must be NULL or live; `out_normal` must point to 3 writable doubles.
 * \ingroup normals
 */
hw_status hw_mesh_vertex_normal(const hw_mesh *mesh,
                                hw_vertex v,
                                hw_normal_weighting weighting,
                                double *out_normal);

/**
 * Unit face normals by Newell's method (the best-fit plane of non-planar polygons).
 *
 * # Safety
 * `mesh` must be NULL or live; `out_normals` NULL or `3 * capacity` writable doubles; `out_needed`
 * NULL or writable.
 * \ingroup normals
 */
hw_status hw_mesh_face_normals(const hw_mesh *mesh,
                               double *out_normals,
                               size_t capacity,
                               size_t *out_needed);

/**
 * Unit vertex normals with the chosen weighting, in one pass over the faces. Every fan of a
 * non-manifold vertex counts.
 *
 * # Safety
 * `mesh` must be NULL or live; `out_normals` NULL or `3 * capacity` writable doubles; `out_needed`
 * NULL or writable.
 * \ingroup normals
 */
hw_status hw_mesh_vertex_normals(const hw_mesh *mesh,
                                 hw_normal_weighting weighting,
                                 double *out_normals,
                                 size_t capacity,
                                 size_t *out_needed);

/**
 * Face and vertex normals together, in one pass (what OpenMesh's `update_normals` computes):
 * `out_face_normals` needs one normal per face slot (hw_mesh_n_face_slots()),
 * `out_vertex_normals` one per vertex slot (hw_mesh_n_vertex_slots()). `*out_face_needed` and
 * `*out_vertex_needed` (each when not NULL) always receive those counts, both of them also when
 * either array is too small (then `HW_ERR_BUFFER_TOO_SMALL` and neither array is written).
 *
 * # Safety
 * `mesh` must be NULL or live; `out_face_normals` NULL or `3 * face_capacity` writable doubles;
 * `out_vertex_normals` NULL or `3 * vertex_capacity` writable doubles, not overlapping
 * `out_face_normals`; `out_face_needed` and `out_vertex_needed` NULL or writable.
 * \ingroup normals
 */
hw_status hw_mesh_normals(const hw_mesh *mesh,
                          hw_normal_weighting weighting,
                          double *out_face_normals,
                          size_t face_capacity,
                          size_t *out_face_needed,
                          double *out_vertex_normals,
                          size_t vertex_capacity,
                          size_t *out_vertex_needed);

/**
 * Per-corner normals, one per half-edge slot (the corner at the half-edge's origin inside its
 * face): angle-weighted over the faces around the vertex reachable without crossing a boundary or
 * an edge sharper than `crease_angle` radians. `crease_angle >= pi` gives smooth normals per fan,
 * 0 a faceted look.
 *
 * # Safety
 * `mesh` must be NULL or live; `out_normals` NULL or `3 * capacity` writable doubles; `out_needed`
 * NULL or writable.
 * \ingroup normals
 */
hw_status hw_mesh_corner_normals(const hw_mesh *mesh,
                                 double crease_angle,
                                 double *out_normals,
                                 size_t capacity,
                                 size_t *out_needed);

/* ----------------------------------------------------------------------------------------------
 * Files
 * ---------------------------------------------------------------------------------------------- */

/**
 * Reads a mesh file into an indexed face list. Malformed files give `HW_ERR_PARSE` with the
 * line (or binary PLY record) and the problem; unreadable ones `HW_ERR_IO`; an unknown extension
 * `HW_ERR_INVALID_INPUT`.
 *
 * # Safety
 * `path` must be NULL or NUL-terminated; `out_soup` writable.
 * \ingroup io
 */
hw_status hw_soup_read(const char *path, hw_soup **out_soup);

/**
 * Zero-copy views of a soup's arrays, in the form hw_mesh_from_indexed() takes: positions
 * (`3 * n_vertices` doubles), face sizes (`n_faces`) and corner indices (`n_indices`). They live
 * as long as the soup; an empty array's pointer is NULL. Any output pointer may be NULL when not
 * wanted.
 *
 * # Safety
 * `soup` must be NULL or live; each output NULL or writable.
 * \ingroup io
 */
hw_status hw_soup_view(const hw_soup *soup,
                       const double **out_positions,
                       size_t *out_n_vertices,
                       const uint32_t **out_face_sizes,
                       size_t *out_n_faces,
                       const uint32_t **out_indices,
                       size_t *out_n_indices);

/**
 * Releases a soup. NULL is a no-op; a second free is refused (within the limits the ownership
 * conventions at the top of the header state).
 *
 * # Safety
 * `soup` must be NULL or a soup from this library, not in use by another thread.
 * \ingroup io
 */
void hw_soup_free(hw_soup *soup);

/**
 * Reads a mesh file and builds a mesh from it, as hw_soup_read() then hw_mesh_from_indexed()
 * would (same policies, same diagnostic, also on a refusal; `out_diagnostic` may be NULL), keeping the file's
 * normals and texture coordinates per corner (hw_mesh_corner_normals_view(),
 * hw_mesh_corner_uvs_view()); hw_mesh_write() writes them back. When an OBJ gives them to some
 * corners only, the others get the zero normal (no direction: render buffers use their computed
 * normal there) and the texture coordinate (0, 0).
 *
 * # Safety
 * `path` must be NULL or NUL-terminated; `out_mesh` writable; `out_diagnostic` NULL or writable.
 * \ingroup io
 */
hw_status hw_mesh_read(const char *path,
                       hw_build_policy policy,
                       hw_mesh **out_mesh,
                       hw_diagnostic **out_diagnostic);

/**
 * Writes a mesh to a file (format by extension; PLY is written binary little-endian). Deleted
 * elements are left out.
 *
 * # Safety
 * `mesh` must be NULL or live; `path` NULL or NUL-terminated.
 * \ingroup io
 */
hw_status hw_mesh_write(const hw_mesh *mesh, const char *path);

/* ----------------------------------------------------------------------------------------------
 * Winged-edge meshes
 * ---------------------------------------------------------------------------------------------- */

/**
 * Creates an empty structure, to build with the Euler operators (hw_winged_mvfs() first).
 * Returns NULL only if the allocation fails.
 * \ingroup winged
 */
hw_winged *hw_winged_new(void);

/**
 * Builds a winged-edge structure from an indexed polygon list: each face's edges are found
 * or created through a bulk edge lookup, as in the classic construction from an indexed mesh.
 *
 * The arrays, `policy`, the statuses and the diagnostic are exactly those of
 * hw_mesh_from_indexed(): the same input is refused, skipped or repaired the same way by both
 * kernels. Edges are numbered in order of first appearance walking the faces in order and
 * point the way their first face walks them (that face is their left face); each face's loop
 * starts at its first corner; input vertex `i` is vertex `i`.
 *
 * On success `*out_winged` receives a new structure to release with hw_winged_free(), and, when
 * `out_diagnostic` is not NULL, `*out_diagnostic` a diagnostic to release with
 * hw_diagnostic_free(). A refused input writes its diagnostic as hw_mesh_from_indexed() does.
 *
 * # Safety
 * Array arguments must point to at least as many elements as their counts say (they may be NULL
 * when the count is 0); `out_winged` must be writable; `out_diagnostic` NULL or writable.
 * \ingroup winged
 */
hw_status hw_winged_from_indexed(const double *positions,
                                 size_t n_vertices,
                                 const uint32_t *face_sizes,
                                 size_t n_faces,
                                 const uint32_t *indices,
                                 size_t n_indices,
                                 hw_build_policy policy,
                                 hw_winged **out_winged,
                                 hw_diagnostic **out_diagnostic);

/**
 * Builds like hw_winged_from_indexed() (strict policy), but numbers and directs the edges as
 * `edge_order` lists them: edge `i` runs from `edge_order[2 i]` to `edge_order[2 i + 1]`, and
 * the face walking it that way is its left face. This reproduces tables whose edge numbering was
 * made by hand, as textbook examples are. `n_edges` must be the edge count of the faces and
 * every edge must be listed once, in either direction; otherwise `HW_ERR_INVALID_INPUT` with
 * the first mismatch in the message.
 *
 * # Safety
 * As for hw_winged_from_indexed(); `edge_order` must point to `2 * n_edges` indices (NULL
 * when `n_edges` is 0).
 * \ingroup winged
 */
hw_status hw_winged_from_indexed_ordered(const double *positions,
                                         size_t n_vertices,
                                         const uint32_t *face_sizes,
                                         size_t n_faces,
                                         const uint32_t *indices,
                                         size_t n_indices,
                                         const uint32_t *edge_order,
                                         size_t n_edges,
                                         hw_winged **out_winged);

/**
 * Builds the winged-edge structure of a half-edge mesh, record for record: winged edge `e` is
 * mesh edge `e`, directed as its half-edge `2e` (its left side; half-edge `2e + 1` is its right
 * side); vertices and faces keep their ids and their stored edge. Deleted mesh elements are left
 * out and the rest renumbered densely in order.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh; `out_winged` writable.
 * \ingroup winged
 */
hw_status hw_winged_from_mesh(const hw_mesh *mesh, hw_winged **out_winged);

/**
 * Converts to a half-edge mesh (the inverse of hw_winged_from_mesh()): edge `e`'s left side
 * becomes half-edge `2e`, its right side `2e + 1`; ids are kept, deleted elements included
 * (they stay deleted in the mesh until hw_mesh_garbage_collect()). Converting a structure built
 * by hw_winged_from_indexed() gives the mesh hw_mesh_from_indexed() builds from the same input,
 * under every policy (input vertices with a non-finite coordinate are deleted in both).
 *
 * Returns `HW_ERR_REFUSED` when a face has no edges (a point face made by hw_winged_mvfs():
 * a half-edge face needs a half-edge).
 *
 * # Safety
 * `winged` must be NULL or a live structure; `out_mesh` writable.
 * \ingroup winged
 */
hw_status hw_winged_to_mesh(const hw_winged *winged, hw_mesh **out_mesh);

/**
 * Releases a structure. NULL is a no-op; a structure freed already is refused, the last error
 * saying so (within the limits the ownership conventions at the top of the header state).
 *
 * # Safety
 * `winged` must be NULL or a structure from this library not in use by another thread.
 * \ingroup winged
 */
void hw_winged_free(hw_winged *winged);

/**
 * Number of vertices (deleted ones not counted); 0 for a NULL structure.
 *
 * # Safety
 * `winged` must be NULL or a live structure.
 * \ingroup winged
 */
size_t hw_winged_n_vertices(const hw_winged *winged);

/**
 * Number of edges (deleted ones not counted); 0 for a NULL structure.
 *
 * # Safety
 * `winged` must be NULL or a live structure.
 * \ingroup winged
 */
size_t hw_winged_n_edges(const hw_winged *winged);

/**
 * Number of faces (deleted ones not counted); 0 for a NULL structure.
 *
 * # Safety
 * `winged` must be NULL or a live structure.
 * \ingroup winged
 */
size_t hw_winged_n_faces(const hw_winged *winged);

/**
 * Size of the vertex id space: ids `0 .. capacity - 1`, deleted ones included until
 * hw_winged_garbage_collect(); 0 for a NULL structure.
 *
 * # Safety
 * `winged` must be NULL or a live structure.
 * \ingroup winged
 */
size_t hw_winged_n_vertex_slots(const hw_winged *winged);

/**
 * Size of the edge id space (see hw_winged_n_vertex_slots()); 0 for a NULL structure.
 *
 * # Safety
 * `winged` must be NULL or a live structure.
 * \ingroup winged
 */
size_t hw_winged_n_edge_slots(const hw_winged *winged);

/**
 * Size of the face id space (see hw_winged_n_vertex_slots()); 0 for a NULL structure.
 *
 * # Safety
 * `winged` must be NULL or a live structure.
 * \ingroup winged
 */
size_t hw_winged_n_face_slots(const hw_winged *winged);

/**
 * Checks every structural invariant (records in range, wings linking closed loops, stored
 * edges incident, counts). `HW_OK`, or `HW_ERR_INVALID_INPUT` with the first broken invariant
 * in the message. A structure made by this library always passes.
 *
 * # Safety
 * `winged` must be NULL or a live structure.
 * \ingroup winged
 */
hw_status hw_winged_check(const hw_winged *winged);

/* ----------------------------------------------------------------------------------------------
 * Winged-edge navigation
 * ---------------------------------------------------------------------------------------------- */

/**
 * A vertex id of an ::hw_winged.
 * \ingroup winged
 */
typedef struct {
  /**
   * The index; `HW_INVALID_INDEX` means none.
   */
  uint32_t idx;
} hw_wvertex;

/**
 * An edge id of an ::hw_winged (one record per undirected edge).
 * \ingroup winged
 */
typedef struct {
  /**
   * The index; `HW_INVALID_INDEX` means none.
   */
  uint32_t idx;
} hw_wedge;

/**
 * A face id of an ::hw_winged. On an edge side, `idx == HW_INVALID_INDEX` means a hole
 * (a boundary).
 * \ingroup winged
 */
typedef struct {
  /**
   * The index; `HW_INVALID_INDEX` means none.
   */
  uint32_t idx;
} hw_wface;

/**
 * Baumgart's edge record. An edge runs `start → end`; its **left** side is the loop that walks
 * it `start → end`, its **right** side the loop that walks it `end → start`; each side has the
 * previous and next edge of that loop (its wings). The same fields under three naming
 * conventions:
 *
 * | field        | Baumgart            | Granada            | Wikipedia            |
 * |--------------|---------------------|--------------------|----------------------|
 * | `start`      | VSTART              | Vi                 | vert_origin          |
 * | `end`        | VEND                | Vf                 | vert_destination     |
 * | `left_face`  | FCW                 | Cd                 | face_left            |
 * | `right_face` | FCCW                | Ci                 | face_right           |
 * | `left_prev`  | EPCW                | Ada                | edge_left_cw         |
 * | `left_next`  | ENCW                | Ads                | edge_left_ccw        |
 * | `right_prev` | EPCCW               | Aia                | edge_right_cw        |
 * | `right_next` | ENCCW               | Ais                | edge_right_ccw       |
 *
 * A face id of `HW_INVALID_INDEX` is a hole; its wings still link the boundary loop.
 * \ingroup winged
 */
typedef struct {
  /**
   * The vertex the edge starts at.
   */
  hw_wvertex start;
  /**
   * The vertex the edge ends at.
   */
  hw_wvertex end;
  /**
   * The face on its left (the loop that walks it `start → end`).
   */
  hw_wface left_face;
  /**
   * The face on its right (the loop that walks it `end → start`).
   */
  hw_wface right_face;
  /**
   * The edge before it in the left loop.
   */
  hw_wedge left_prev;
  /**
   * The edge after it in the left loop.
   */
  hw_wedge left_next;
  /**
   * The edge before it in the right loop.
   */
  hw_wedge right_prev;
  /**
   * The edge after it in the right loop.
   */
  hw_wedge right_next;
} hw_wedge_record;

/**
 * Whether `v` names a live vertex (false for a NULL structure, with the error recorded).
 *
 * # Safety
 * `winged` must be NULL or a live structure.
 * \ingroup winged_navigation
 */
bool hw_winged_is_vertex(const hw_winged *winged, hw_wvertex v);

/**
 * Whether `e` names a live edge (false for a NULL structure, with the error recorded).
 *
 * # Safety
 * `winged` must be NULL or a live structure.
 * \ingroup winged_navigation
 */
bool hw_winged_is_edge(const hw_winged *winged, hw_wedge e);

/**
 * Whether `f` names a live face (false for a NULL structure, with the error recorded).
 *
 * # Safety
 * `winged` must be NULL or a live structure.
 * \ingroup winged_navigation
 */
bool hw_winged_is_face(const hw_winged *winged, hw_wface f);

/**
 * Copies the record of edge `e` (its vertices, faces and wings) into `*out_record`.
 * `HW_ERR_INVALID_HANDLE` for an edge that does not exist or was deleted.
 *
 * # Safety
 * `winged` must be NULL or a live structure; `out_record` writable.
 * \ingroup winged_navigation
 */
hw_status hw_winged_edge(const hw_winged *winged, hw_wedge e, hw_wedge_record *out_record);

/**
 * A zero-copy, read-only view of all edge records, indexed by edge id: `*out_records` (NULL when
 * there are none) and `*out_len`. A deleted edge's record has `start.idx == HW_INVALID_INDEX`.
 * Valid until the next call that modifies the structure.
 *
 * # Safety
 * `winged` must be NULL or a live structure; `out_records` and `out_len` writable.
 * \ingroup winged_navigation
 */
hw_status hw_winged_edge_records(const hw_winged *winged,
                                 const hw_wedge_record **out_records,
                                 size_t *out_len);

/**
 * The edge vertex `v` stores: its ring starts there (for a boundary vertex, the edge whose side
 * leaving `v` is a hole). Invalid for an isolated vertex, and (with the error recorded) for a
 * vertex that does not exist.
 *
 * # Safety
 * `winged` must be NULL or a live structure.
 * \ingroup winged_navigation
 */
hw_wedge hw_winged_vertex_edge(const hw_winged *winged, hw_wvertex v);

/**
 * The edge face `f` stores: its loop starts there. Invalid for a point face (made by
 * hw_winged_mvfs()), and (with the error recorded) for a face that does not exist.
 *
 * # Safety
 * `winged` must be NULL or a live structure.
 * \ingroup winged_navigation
 */
hw_wedge hw_winged_face_edge(const hw_winged *winged, hw_wface f);

/* ----------------------------------------------------------------------------------------------
 * Winged-edge circulators
 * ---------------------------------------------------------------------------------------------- */

/**
 * What a winged circulator yields.
 * \ingroup winged_circulators
 */
typedef uint32_t hw_wcirculator_kind;

/**
 * Edges: the edges of a face's loop, or the edges at a vertex.
 * \ingroup winged_circulators
 */
#define HW_WCIRCULATOR_KIND_EDGES 0

/**
 * Vertices: a face's corners, or a vertex's neighbours (the other ends of its edges).
 * \ingroup winged_circulators
 */
#define HW_WCIRCULATOR_KIND_VERTICES 1

/**
 * Faces: the faces across a face's edges, or the faces around a vertex (holes skipped).
 * \ingroup winged_circulators
 */
#define HW_WCIRCULATOR_KIND_FACES 2

/**
 * A winged circulator's state, kept on the caller's stack. Fill it with
 * hw_wcirc_around_face() or hw_wcirc_around_vertex(); read it with the `hw_wcirc_next_*` call of
 * its kind. Treat the fields as private. It borrows the structure: do not modify the structure
 * while walking.
 * \ingroup winged_circulators
 */
typedef struct {
  /**
   * The structure walked.
   */
  const hw_winged *winged;
  /**
   * The edge of the use the walk started from; coming back to that use ends the walk.
   */
  uint32_t start_edge;
  /**
   * The side of that use: 0 left, 1 right.
   */
  uint32_t start_side;
  /**
   * The edge of the use the walk yields next, `HW_INVALID_INDEX` once it is over.
   */
  uint32_t current_edge;
  /**
   * The side of that use: 0 left, 1 right.
   */
  uint32_t current_side;
  /**
   * Steps left before the bound on a walk's length stops it (a corrupt cycle cannot hang).
   */
  uint32_t remaining;
  /**
   * What it walks around: a face or a vertex (internal code).
   */
  uint32_t center;
  /**
   * What it yields.
   */
  hw_wcirculator_kind kind;
} hw_wcirculator;

/**
 * Starts a walk around face `f`: its edges or corners in loop order, or the faces across its
 * edges (holes skipped). A point face (made by hw_winged_mvfs()) gives an empty walk.
 *
 * # Safety
 * `winged` must be NULL or a live structure; `out` writable.
 * \ingroup winged_circulators
 */
hw_status hw_wcirc_around_face(const hw_winged *winged,
                               hw_wface f,
                               hw_wcirculator_kind kind,
                               hw_wcirculator *out);

/**
 * Starts a walk around vertex `v`: its edges or neighbours counter-clockwise, or the faces
 * around it (holes skipped). An isolated vertex gives an empty walk.
 *
 * # Safety
 * `winged` must be NULL or a live structure; `out` writable.
 * \ingroup winged_circulators
 */
hw_status hw_wcirc_around_vertex(const hw_winged *winged,
                                 hw_wvertex v,
                                 hw_wcirculator_kind kind,
                                 hw_wcirculator *out);

/**
 * Next edge of a ::HW_WCIRCULATOR_KIND_EDGES circulator.
 *
 * # Safety
 * `circulator` must be NULL or a circulator over a live, unmodified structure; `out` writable.
 * \ingroup winged_circulators
 */
bool hw_wcirc_next_edge(hw_wcirculator *circulator, hw_wedge *out);

/**
 * Next vertex of a ::HW_WCIRCULATOR_KIND_VERTICES circulator.
 *
 * # Safety
 * `circulator` must be NULL or a circulator over a live, unmodified structure; `out` writable.
 * \ingroup winged_circulators
 */
bool hw_wcirc_next_vertex(hw_wcirculator *circulator, hw_wvertex *out);

/**
 * Next face of a ::HW_WCIRCULATOR_KIND_FACES circulator.
 *
 * # Safety
 * `circulator` must be NULL or a circulator over a live, unmodified structure; `out` writable.
 * \ingroup winged_circulators
 */
bool hw_wcirc_next_face(hw_wcirculator *circulator, hw_wface *out);

/* ----------------------------------------------------------------------------------------------
 * Euler operators
 * ---------------------------------------------------------------------------------------------- */

/**
 * **Make vertex, face, solid**: a new solid of one vertex at `position[0..3]` and one face
 * without edges (a point face). Writes the vertex and the face.
 *
 * # Safety
 * `winged` must be NULL or a live structure used by no one else during the call; `position`
 * must point to 3 readable doubles (NULL gives `HW_ERR_NULL_ARGUMENT`); `out_vertex` and
 * `out_face` writable.
 * \ingroup winged_edit
 */
hw_status hw_winged_mvfs(hw_winged *winged,
                         const double *position,
                         hw_wvertex *out_vertex,
                         hw_wface *out_face);

/**
 * **Make edge, vertex**: a new vertex at `position[0..3]` joined to `vertex` by a new edge
 * `vertex → new vertex` lying inside `face` (both its sides are `face`). `vertex` must occur
 * exactly once on `face`'s loop, or be the vertex of a point face. Writes the edge and vertex.
 *
 * # Safety
 * `winged` must be NULL or a live structure used by no one else during the call; `position`
 * must point to 3 readable doubles (NULL gives `HW_ERR_NULL_ARGUMENT`); `out_edge` and
 * `out_vertex` writable.
 * \ingroup winged_edit
 */
hw_status hw_winged_mev(hw_winged *winged,
                        hw_wface face,
                        hw_wvertex vertex,
                        const double *position,
                        hw_wedge *out_edge,
                        hw_wvertex *out_vertex);

/**
 * **Make edge, face**: splits `face` with a new edge `v1 → v2`. The new face is the new edge's
 * left side (the part of the loop from `v2` back to `v1`); `face` keeps the part from `v1` to
 * `v2`. `v1` and `v2` must differ and each occur exactly once on `face`'s loop. Writes the edge
 * and the new face.
 *
 * # Safety
 * `winged` must be NULL or a live structure used by no one else during the call; `out_edge`
 * and `out_face` writable.
 * \ingroup winged_edit
 */
hw_status hw_winged_mef(hw_winged *winged,
                        hw_wface face,
                        hw_wvertex v1,
                        hw_wvertex v2,
                        hw_wedge *out_edge,
                        hw_wface *out_face);

/**
 * **Kill edge, vertex** (inverse of MEV): removes `vertex` and `edge`, which must be its only
 * edge. When `edge` was its solid's last edge, the face becomes a point face on the other vertex.
 * Refused (`HW_ERR_REFUSED`, nothing changed) when `vertex` has other edges, also in another fan
 * of a pinched vertex, and when the last edge's other vertex has edges in another fan (a point
 * face's vertex has none).
 *
 * # Safety
 * `winged` must be NULL or a live structure used by no one else during the call.
 * \ingroup winged_edit
 */
hw_status hw_winged_kev(hw_winged *winged, hw_wedge edge, hw_wvertex vertex);

/**
 * **Kill edge, face** (inverse of MEF): removes `edge` and the face `kill` on one of its sides,
 * merging `kill` into the face on the other side. The two sides must be two different faces.
 *
 * # Safety
 * `winged` must be NULL or a live structure used by no one else during the call.
 * \ingroup winged_edit
 */
hw_status hw_winged_kef(hw_winged *winged, hw_wedge edge, hw_wface kill);

/**
 * **Kill vertex, face, solid** (inverse of MVFS): removes a point face and its vertex.
 *
 * # Safety
 * `winged` must be NULL or a live structure used by no one else during the call.
 * \ingroup winged_edit
 */
hw_status hw_winged_kvfs(hw_winged *winged, hw_wface face);

/**
 * Drops the elements the kill operators deleted and renumbers the live ones densely, keeping
 * their order. Every id held from before (and every view) is invalidated. When `out_maps` is not
 * NULL it receives the old-to-new maps (read with hw_index_maps_view(): vertices, edges and
 * faces; the half-edge map is empty; deleted → `HW_INVALID_INDEX`).
 *
 * # Safety
 * `winged` must be NULL or a live structure used by no one else during the call; `out_maps`
 * NULL or writable.
 * \ingroup winged_edit
 */
hw_status hw_winged_garbage_collect(hw_winged *winged, hw_index_maps **out_maps);

/* ----------------------------------------------------------------------------------------------
 * Winged-edge positions
 * ---------------------------------------------------------------------------------------------- */

/**
 * Writes the position of `v` to `out_xyz[0..3]` (required: NULL gives `HW_ERR_NULL_ARGUMENT`).
 *
 * # Safety
 * `winged` must be NULL or a live structure; `out_xyz` must point to 3 writable doubles.
 * \ingroup winged_attributes
 */
hw_status hw_winged_vertex_position(const hw_winged *winged, hw_wvertex v, double *out_xyz);

/**
 * Moves vertex `v` to `xyz[0..3]` (finite).
 *
 * # Safety
 * `winged` must be NULL or a live structure used by no one else during the call; `xyz` 3
 * doubles.
 * \ingroup winged_attributes
 */
hw_status hw_winged_set_vertex_position(hw_winged *winged, hw_wvertex v, const double *xyz);

/* ----------------------------------------------------------------------------------------------
 * Winged-edge normals
 * ---------------------------------------------------------------------------------------------- */

/**
 * Unit normal of face `f` by Newell's method (outward for a counter-clockwise face; zero for a
 * degenerate or point face), written to `out_normal[0..3]` (required: NULL gives
 * `HW_ERR_NULL_ARGUMENT`): what hw_winged_face_normals() gives `f`, bit for bit, and
 * hw_mesh_face_normal() the same face of a mesh.
 *
 * # Safety
 * `winged` must be NULL or a live structure; `out_normal` must point to 3 writable doubles.
 * \ingroup winged_normals
 */
hw_status hw_winged_face_normal(const hw_winged *winged, hw_wface f, double *out_normal);

/**
 * Unit normal of vertex `v` with the chosen weighting, as hw_mesh_vertex_normal() computes a
 * mesh's: the normalised sum of the weighted normals of the faces around it (every fan of a
 * non-manifold vertex; holes left out; zero if none), written to `out_normal[0..3]` (required:
 * NULL gives `HW_ERR_NULL_ARGUMENT`). Baumgart's vertex normal, the unit face normals summed, is
 * ::HW_NORMAL_WEIGHTING_UNIFORM.
 *
 * # Safety
 * `winged` must be NULL or a live structure; `out_normal` must point to 3 writable doubles.
 * \ingroup winged_normals
 */
hw_status hw_winged_vertex_normal(const hw_winged *winged,
                                  hw_wvertex v,
                                  hw_normal_weighting weighting,
                                  double *out_normal);

/**
 * The unit normals of all faces by Newell's method, indexed by face id, copied into
 * `out_normals` as x, y, z per face slot (zero for deleted and degenerate faces), as
 * hw_mesh_face_normals() copies a mesh's: `capacity` and `*out_needed` count normals (3 doubles
 * each), `*out_needed` (when not NULL) always receiving the number of face slots;
 * `HW_ERR_BUFFER_TOO_SMALL` when `out_normals` is NULL or too short.
 *
 * # Safety
 * `winged` must be NULL or a live structure; `out_normals` NULL or `3 * capacity` writable
 * doubles; `out_needed` NULL or writable.
 * \ingroup winged_normals
 */
hw_status hw_winged_face_normals(const hw_winged *winged,
                                 double *out_normals,
                                 size_t capacity,
                                 size_t *out_needed);

/**
 * The unit normals of all vertices with the chosen weighting, as hw_winged_vertex_normal()
 * computes them, in one pass over the faces, indexed by vertex id (zero for deleted vertices
 * and those without faces), copied as hw_winged_face_normals() copies the faces'.
 *
 * # Safety
 * As for hw_winged_face_normals().
 * \ingroup winged_normals
 */
hw_status hw_winged_vertex_normals(const hw_winged *winged,
                                   hw_normal_weighting weighting,
                                   double *out_normals,
                                   size_t capacity,
                                   size_t *out_needed);

/* ----------------------------------------------------------------------------------------------
 * Winged-edge tables
 * ---------------------------------------------------------------------------------------------- */

/**
 * Which table hw_winged_table() prints.
 * \ingroup winged_io
 */
typedef uint32_t hw_wtable;

/**
 * The vertex table: id, coordinates, stored edge (Baumgart's "Vertex-Edge" table).
 * \ingroup winged_io
 */
#define HW_WTABLE_VERTICES 0

/**
 * The face table: id, stored edge ("Face-Edge").
 * \ingroup winged_io
 */
#define HW_WTABLE_FACES 1

/**
 * The edge table: id, vertices, faces and wings ("Edge-Edge relation").
 * \ingroup winged_io
 */
#define HW_WTABLE_EDGES 2

/**
 * The three tables, vertex, face and edge, separated by a blank line.
 * \ingroup winged_io
 */
#define HW_WTABLE_ALL 3

/**
 * Which naming scheme a table's columns use.
 * \ingroup winged_io
 */
typedef uint32_t hw_wnaming;

/**
 * Baumgart's (his cube example): VSTART VEND EPCW ENCW EPCCW ENCCW FCW FCCW; elements labelled
 * from 1 with a letter (V1, E1, F1).
 * \ingroup winged_io
 */
#define HW_WNAMING_CW_CCW 0

/**
 * The University of Granada notes': Vi Vf Cd Ci Ada Ads Aia Ais; elements numbered from 0.
 * \ingroup winged_io
 */
#define HW_WNAMING_DIRECT_INVERSE 1

/**
 * Wikipedia's winged-edge article: vert_origin ... edge_right_ccw; elements numbered from 0.
 * \ingroup winged_io
 */
#define HW_WNAMING_LEFT_RIGHT 2

/**
 * How a table is written.
 * \ingroup winged_io
 */
typedef uint32_t hw_table_format;

/**
 * Columns aligned with spaces; a hole is `∅` (UTF-8).
 * \ingroup winged_io
 */
#define HW_TABLE_FORMAT_TEXT 0

/**
 * A Markdown table; a hole is `∅`.
 * \ingroup winged_io
 */
#define HW_TABLE_FORMAT_MARKDOWN 1

/**
 * Comma-separated values with a header row; a hole is an empty field.
 * \ingroup winged_io
 */
#define HW_TABLE_FORMAT_CSV 2

/**
 * Prints a table of the structure in a textbook layout (`which`: ::HW_WTABLE_VERTICES, ...;
 * `naming`: ::HW_WNAMING_CW_CCW, ...; `format`: ::HW_TABLE_FORMAT_TEXT, ...) into `out_text`
 * (`capacity` bytes), NUL-terminated, every line ending with a newline. `*out_needed` (when not
 * NULL) always receives the size needed, terminator included; `HW_ERR_BUFFER_TOO_SMALL` when
 * `out_text` is NULL or shorter (call with `out_text = NULL` to learn the size). Unknown enum
 * values give `HW_ERR_INVALID_INPUT`.
 *
 * # Safety
 * `winged` must be NULL or a live structure; `out_text` NULL or `capacity` writable bytes;
 * `out_needed` NULL or writable.
 * \ingroup winged_io
 */
hw_status hw_winged_table(const hw_winged *winged,
                          hw_wtable which,
                          hw_wnaming naming,
                          hw_table_format format,
                          char *out_text,
                          size_t capacity,
                          size_t *out_needed);

/* ----------------------------------------------------------------------------------------------
 * Voronoi diagrams
 * ---------------------------------------------------------------------------------------------- */

/**
 * The dimension of the site set, as hw_voronoi_dimension() reports it.
 * \ingroup voronoi
 */
typedef uint32_t hw_site_dimension;

/**
 * No sites.
 * \ingroup voronoi
 */
#define HW_SITE_DIMENSION_EMPTY 0

/**
 * One distinct site (possibly repeated): one cell, the whole plane.
 * \ingroup voronoi
 */
#define HW_SITE_DIMENSION_POINT 1

/**
 * Two or more distinct sites, all collinear: no triangles; cells are slabs between parallel
 * bisectors, and the hull lists the sites in order along their line.
 * \ingroup voronoi
 */
#define HW_SITE_DIMENSION_LINE 2

/**
 * The sites span the plane: at least one triangle.
 * \ingroup voronoi
 */
#define HW_SITE_DIMENSION_PLANE 3

/**
 * Which index array hw_voronoi_view() shows.
 * \ingroup voronoi
 */
typedef uint32_t hw_voronoi_array;

/**
 * Per site: the site representing it (itself unless it duplicates a smaller index).
 * \ingroup voronoi
 */
#define HW_VORONOI_ARRAY_REPRESENTATIVE 0

/**
 * Per Delaunay triangle: its three sites, counter-clockwise (`3 * n_triangles` entries).
 * Delaunay half-edge `e` (= corner `e`) runs from site `triangles[e]` to the next corner's site.
 * \ingroup voronoi
 */
#define HW_VORONOI_ARRAY_TRIANGLES 1

/**
 * Per Delaunay half-edge: the opposite half-edge, `HW_INVALID_INDEX` on the convex hull.
 * \ingroup voronoi
 */
#define HW_VORONOI_ARRAY_TRIANGLE_TWINS 2

/**
 * The convex hull's sites, counter-clockwise (for collinear input: the sites in order along the
 * line; for one distinct site: that site).
 * \ingroup voronoi
 */
#define HW_VORONOI_ARRAY_HULL 3

/**
 * Per Delaunay triangle: its Voronoi vertex (cocircular triangles share one).
 * \ingroup voronoi
 */
#define HW_VORONOI_ARRAY_TRIANGLE_VERTEX 4

/**
 * Per Voronoi half-edge: its start vertex, `HW_INVALID_INDEX` when it comes from infinity.
 * \ingroup voronoi
 */
#define HW_VORONOI_ARRAY_HALFEDGE_ORIGIN 5

/**
 * Per Voronoi half-edge: the next half-edge counter-clockwise around its cell (an edge running
 * out to infinity is followed by the one coming back).
 * \ingroup voronoi
 */
#define HW_VORONOI_ARRAY_HALFEDGE_NEXT 6

/**
 * Per Voronoi half-edge: the previous half-edge around its cell.
 * \ingroup voronoi
 */
#define HW_VORONOI_ARRAY_HALFEDGE_PREV 7

/**
 * Per Voronoi half-edge: the site whose cell it bounds (on its left).
 * \ingroup voronoi
 */
#define HW_VORONOI_ARRAY_HALFEDGE_SITE 8

/**
 * Per site: one half-edge of its cell (the edge from infinity for an unbounded cell),
 * `HW_INVALID_INDEX` for duplicates and when the diagram has no edges.
 * \ingroup voronoi
 */
#define HW_VORONOI_ARRAY_CELL_HALFEDGE 9

/**
 * Per Voronoi vertex: one outgoing half-edge.
 * \ingroup voronoi
 */
#define HW_VORONOI_ARRAY_VERTEX_HALFEDGE 10

/**
 * A half-edge of an ::hw_voronoi. Half-edges come in pairs: the twin of `h` is `h.idx ^ 1`.
 * \ingroup voronoi
 */
typedef struct {
  /**
   * The index; `HW_INVALID_INDEX` means none.
   */
  uint32_t idx;
} hw_voronoi_halfedge;

/**
 * The shape of a Voronoi edge (see ::hw_voronoi_edge).
 * \ingroup voronoi
 */
typedef uint32_t hw_voronoi_edge_kind;

/**
 * Both ends are Voronoi vertices: from `point` to `end`.
 * \ingroup voronoi
 */
#define HW_VORONOI_EDGE_KIND_SEGMENT 0

/**
 * One end at infinity: the points `point + t * direction`, `t >= 0`.
 * \ingroup voronoi
 */
#define HW_VORONOI_EDGE_KIND_RAY 1

/**
 * Both ends at infinity (collinear sites): the points `point + t * direction` for every `t`.
 * \ingroup voronoi
 */
#define HW_VORONOI_EDGE_KIND_LINE 2

/**
 * A site of an ::hw_voronoi: its input index, which is also its Delaunay vertex and the index of
 * its cell.
 * \ingroup voronoi
 */
typedef struct {
  /**
   * The index; `HW_INVALID_INDEX` means none.
   */
  uint32_t idx;
} hw_site;

/**
 * A vertex of an ::hw_voronoi (a circumcentre of Delaunay triangles).
 * \ingroup voronoi
 */
typedef struct {
  /**
   * The index; `HW_INVALID_INDEX` means none (an end at infinity).
   */
  uint32_t idx;
} hw_voronoi_vertex;

/**
 * One Voronoi edge seen from one of its half-edges: the two sites it separates and its geometry.
 * \ingroup voronoi
 */
typedef struct {
  /**
   * ::HW_VORONOI_EDGE_KIND_SEGMENT, ::HW_VORONOI_EDGE_KIND_RAY or ::HW_VORONOI_EDGE_KIND_LINE.
   */
  hw_voronoi_edge_kind kind;
  /**
   * The site on the half-edge's left (whose cell it bounds).
   */
  hw_site site;
  /**
   * The site on its right.
   */
  hw_site opposite_site;
  /**
   * Start vertex (`HW_INVALID_INDEX` when it comes from infinity).
   */
  hw_voronoi_vertex origin;
  /**
   * End vertex (`HW_INVALID_INDEX` when it runs to infinity).
   */
  hw_voronoi_vertex target;
  /**
   * Segment: the start. Ray: its finite end (for a half-edge coming from infinity, that is
   * where it ends). Line: the midpoint of the two sites.
   */
  double point[2];
  /**
   * Segment: the end. Otherwise equal to `point`.
   */
  double end[2];
  /**
   * Ray and line: the direction away from `point` (not normalised; for a half-edge coming
   * from infinity it points back towards infinity, i.e. against the half-edge). Segment:
   * `end - point`.
   */
  double direction[2];
} hw_voronoi_edge;

/**
 * A distance function for hw_voronoi_label_image().
 * \ingroup voronoi
 */
typedef uint32_t hw_metric;

/**
 * Euclidean distance (the diagram's own metric).
 * \ingroup voronoi
 */
#define HW_METRIC_EUCLIDEAN 0

/**
 * Manhattan (L1, taxicab) distance `|dx| + |dy|`.
 * \ingroup voronoi
 */
#define HW_METRIC_MANHATTAN 1

/**
 * Chebyshev (L∞) distance `max(|dx|, |dy|)`.
 * \ingroup voronoi
 */
#define HW_METRIC_CHEBYSHEV 2

/**
 * What hw_voronoi_svg() draws. hw_svg_options_default() gives the defaults.
 * \ingroup voronoi
 */
typedef struct {
  /**
   * Picture width in pixels (> 0); the height follows the clip region's aspect ratio.
   */
  double width_px;
  /**
   * Fill cells with distinct pastel colours (otherwise outlines only).
   */
  bool fill_cells;
  /**
   * Draw the sites as dots.
   */
  bool sites;
  /**
   * Draw the Delaunay edges.
   */
  bool delaunay_edges;
} hw_svg_options;

/**
 * Reads a 2D point file, the format by the path's extension: `.xy` and `.cin` (a point per line),
 * `.node` and `.poly` (Triangle's format: a header `count 2 ...`, then `index x y ...` lines),
 * `.txt` (a count line, then a point per line), `.json` (a flat or nested array of
 * coordinates). A malformed file gives `HW_ERR_PARSE`, the message naming the file, the line and
 * the problem; an unreadable one `HW_ERR_IO`; an unknown extension `HW_ERR_INVALID_INPUT`.
 * Non-finite coordinates are read as values (hw_voronoi_build() refuses them).
 *
 * # Safety
 * `path` must be NULL or NUL-terminated; `out_points` writable.
 * \ingroup voronoi
 */
hw_status hw_points2d_read(const char *path, hw_points2d **out_points);

/**
 * A zero-copy view of the points: `*out_xy` (`2 * *out_n_points` doubles, x then y of each
 * point, in the form hw_voronoi_build() takes; NULL when there are none). Lives as long as the
 * points.
 *
 * # Safety
 * `points` must be NULL or live; `out_xy` and `out_n_points` writable.
 * \ingroup voronoi
 */
hw_status hw_points2d_view(const hw_points2d *points, const double **out_xy, size_t *out_n_points);

/**
 * Releases points. NULL is a no-op; a second free is refused (within the limits the ownership
 * conventions at the top of the header state).
 *
 * # Safety
 * `points` must be NULL or points from this library, not in use by another thread.
 * \ingroup voronoi
 */
void hw_points2d_free(hw_points2d *points);

/**
 * Builds the Delaunay triangulation and Voronoi diagram of `n_sites` sites given as `2 * n_sites`
 * doubles (x, y per site).
 *
 * Predicates are exact, so the result is correct for any finite input: duplicates are merged
 * (see ::HW_VORONOI_ARRAY_REPRESENTATIVE), collinear sites give parallel bisectors and no
 * triangles, cocircular sites one Voronoi vertex of degree > 3. Zero, one or two sites are valid
 * input. A NaN or infinite coordinate gives `HW_ERR_INVALID_INPUT` with a message naming the site.
 *
 * On success `*out_voronoi` receives a new diagram to release with hw_voronoi_free().
 *
 * # Safety
 * `xy` must point to `2 * n_sites` doubles (NULL only when `n_sites` is 0); `out_voronoi`
 * writable.
 * \ingroup voronoi
 */
hw_status hw_voronoi_build(const double *xy, size_t n_sites, hw_voronoi **out_voronoi);

/**
 * Releases a diagram. NULL is a no-op; a diagram freed already is refused, the last error saying
 * so (within the limits the ownership conventions at the top of the header state). Clipped
 * cells made from it (::hw_voronoi_cells) stay valid.
 *
 * # Safety
 * `voronoi` must be NULL or a diagram from this library not in use by another thread.
 * \ingroup voronoi
 */
void hw_voronoi_free(hw_voronoi *voronoi);

/**
 * Number of input sites, duplicates included; 0 for a NULL diagram.
 *
 * # Safety
 * `voronoi` must be NULL or a live diagram.
 * \ingroup voronoi
 */
size_t hw_voronoi_n_sites(const hw_voronoi *voronoi);

/**
 * Number of distinct sites (= number of cells); 0 for a NULL diagram.
 *
 * # Safety
 * `voronoi` must be NULL or a live diagram.
 * \ingroup voronoi
 */
size_t hw_voronoi_n_unique_sites(const hw_voronoi *voronoi);

/**
 * Number of Delaunay triangles (0 when all sites are collinear); 0 for a NULL diagram.
 *
 * # Safety
 * `voronoi` must be NULL or a live diagram.
 * \ingroup voronoi
 */
size_t hw_voronoi_n_triangles(const hw_voronoi *voronoi);

/**
 * Number of Voronoi vertices; 0 for a NULL diagram.
 *
 * # Safety
 * `voronoi` must be NULL or a live diagram.
 * \ingroup voronoi
 */
size_t hw_voronoi_n_vertices(const hw_voronoi *voronoi);

/**
 * Number of Voronoi half-edges (twice the number of edges); 0 for a NULL diagram.
 *
 * # Safety
 * `voronoi` must be NULL or a live diagram.
 * \ingroup voronoi
 */
size_t hw_voronoi_n_halfedges(const hw_voronoi *voronoi);

/**
 * The dimension of the site set (::HW_SITE_DIMENSION_EMPTY for a NULL diagram, with the error
 * recorded).
 *
 * # Safety
 * `voronoi` must be NULL or a live diagram.
 * \ingroup voronoi
 */
hw_site_dimension hw_voronoi_dimension(const hw_voronoi *voronoi);

/**
 * A read-only view of one index array of the diagram (see ::hw_voronoi_array): `*out_data`
 * (NULL when empty) and its length `*out_len`, valid as long as the diagram. The half-edge
 * arrays are built on first use (by this call or any half-edge query), once, safely even when
 * several threads ask at the same time.
 *
 * A cell walk in C:
 * ```c
 * uint32_t h = cell_halfedge[s], start = h;
 * if (h != HW_INVALID_INDEX) do { visit(h); h = next[h]; } while (h != start);
 * ```
 *
 * # Safety
 * `voronoi` must be NULL or a live diagram; `out_data` and `out_len` writable.
 * \ingroup voronoi
 */
hw_status hw_voronoi_view(const hw_voronoi *voronoi,
                          hw_voronoi_array which,
                          const uint32_t **out_data,
                          size_t *out_len);

/**
 * A read-only view of the sites as given: `*out_xy` (x, y per site, NULL when empty) and the
 * number of sites `*out_n_sites`, valid as long as the diagram.
 *
 * # Safety
 * `voronoi` must be NULL or a live diagram; `out_xy` and `out_n_sites` writable.
 * \ingroup voronoi
 */
hw_status hw_voronoi_sites(const hw_voronoi *voronoi, const double **out_xy, size_t *out_n_sites);

/**
 * A read-only view of the Voronoi vertices (circumcentres): `*out_xy` (x, y per vertex, NULL
 * when empty) and their number `*out_n_vertices`, valid as long as the diagram.
 *
 * # Safety
 * `voronoi` must be NULL or a live diagram; `out_xy` and `out_n_vertices` writable.
 * \ingroup voronoi
 */
hw_status hw_voronoi_vertices(const hw_voronoi *voronoi,
                              const double **out_xy,
                              size_t *out_n_vertices);

/**
 * Describes the Voronoi edge of half-edge `halfedge` (see ::hw_voronoi_edge). An index out of
 * range gives `HW_ERR_INVALID_HANDLE`.
 *
 * # Safety
 * `voronoi` must be NULL or a live diagram; `out_edge` writable.
 * \ingroup voronoi
 */
hw_status hw_voronoi_edge_describe(const hw_voronoi *voronoi,
                                   hw_voronoi_halfedge halfedge,
                                   hw_voronoi_edge *out_edge);

/**
 * The Delaunay triangulation as a new half-edge mesh (z = 0): vertex `i` is site `i` (duplicates
 * are isolated vertices), one triangle per Delaunay triangle, in the order of
 * ::HW_VORONOI_ARRAY_TRIANGLES. Collinear input gives a mesh without faces. Release it with
 * hw_mesh_free().
 *
 * # Safety
 * `voronoi` must be NULL or a live diagram; `out_mesh` writable.
 * \ingroup voronoi
 */
hw_status hw_voronoi_delaunay_mesh(const hw_voronoi *voronoi, hw_mesh **out_mesh);

/**
 * The site nearest to the point (`x`, `y`) — the site whose cell contains it — exactly, ties
 * going to the smallest index. `hint`, when it is a site, starts the search there (a nearby
 * site makes the query O(1)); pass `(hw_site){HW_INVALID_INDEX}` for none. A NaN or infinite
 * point gives `HW_ERR_INVALID_INPUT`; a diagram without sites `HW_ERR_NOT_FOUND`.
 *
 * # Safety
 * `voronoi` must be NULL or a live diagram; `out_site` writable.
 * \ingroup voronoi
 */
hw_status hw_voronoi_nearest_site(const hw_voronoi *voronoi,
                                  double x,
                                  double y,
                                  hw_site hint,
                                  hw_site *out_site);

/**
 * Copies the sites whose cells share an edge with the cell of `site` (its Delaunay neighbours,
 * less those cut off by cocircular merging), counter-clockwise, into `out_sites`; `*out_needed`
 * (when not NULL) receives their number. A duplicate site answers for its representative. Out of
 * range: `HW_ERR_INVALID_HANDLE`; `capacity` too small: `HW_ERR_BUFFER_TOO_SMALL`.
 *
 * # Safety
 * `voronoi` must be NULL or a live diagram; `out_sites` NULL or `capacity` writable elements;
 * `out_needed` NULL or writable.
 * \ingroup voronoi
 */
hw_status hw_voronoi_neighbours(const hw_voronoi *voronoi,
                                hw_site site,
                                hw_site *out_sites,
                                size_t capacity,
                                size_t *out_needed);

/**
 * The Voronoi half-edge separating the cells of sites `a` and `b`, on the side of `a` (its twin,
 * `h ^ 1`, is on the side of `b`). Duplicates answer for their representatives. Either site out
 * of range: `HW_ERR_INVALID_HANDLE`; cells not adjacent: `HW_ERR_NOT_FOUND`.
 *
 * # Safety
 * `voronoi` must be NULL or a live diagram; `out_halfedge` writable.
 * \ingroup voronoi
 */
hw_status hw_voronoi_edge_between(const hw_voronoi *voronoi,
                                  hw_site a,
                                  hw_site b,
                                  hw_voronoi_halfedge *out_halfedge);

/**
 * Builds the Delaunay triangulation of `n_sites` sites given as `2 * n_sites` doubles (x, y per
 * site), without the Voronoi diagram (hw_voronoi_build() builds both): for callers that need
 * only the triangles, it takes less time and memory.
 *
 * Input as for hw_voronoi_build(): any finite sites, duplicates merged (see
 * ::HW_VORONOI_ARRAY_REPRESENTATIVE), collinear sites give no triangles; a NaN or infinite
 * coordinate gives `HW_ERR_INVALID_INPUT` with a message naming the site.
 *
 * On success `*out_delaunay` receives a new triangulation to release with hw_delaunay_free().
 *
 * # Safety
 * `xy` must point to `2 * n_sites` doubles (NULL only when `n_sites` is 0); `out_delaunay`
 * writable.
 * \ingroup voronoi
 */
hw_status hw_delaunay_build(const double *xy, size_t n_sites, hw_delaunay **out_delaunay);

/**
 * Releases a triangulation. NULL is a no-op; a triangulation freed already is refused, the last
 * error saying so (within the limits the ownership conventions at the top of the header state).
 *
 * # Safety
 * `delaunay` must be NULL or a triangulation from this library not in use by another thread.
 * \ingroup voronoi
 */
void hw_delaunay_free(hw_delaunay *delaunay);

/**
 * Number of triangles (0 when all sites are collinear); 0 for a NULL triangulation.
 *
 * # Safety
 * `delaunay` must be NULL or a live triangulation.
 * \ingroup voronoi
 */
size_t hw_delaunay_n_triangles(const hw_delaunay *delaunay);

/**
 * The dimension of the site set (::HW_SITE_DIMENSION_EMPTY for a NULL triangulation, with the
 * error recorded).
 *
 * # Safety
 * `delaunay` must be NULL or a live triangulation.
 * \ingroup voronoi
 */
hw_site_dimension hw_delaunay_dimension(const hw_delaunay *delaunay);

/**
 * A read-only view of one index array of the triangulation: `which` is one of
 * ::HW_VORONOI_ARRAY_REPRESENTATIVE, ::HW_VORONOI_ARRAY_TRIANGLES,
 * ::HW_VORONOI_ARRAY_TRIANGLE_TWINS and ::HW_VORONOI_ARRAY_HULL (the other arrays belong to the
 * Voronoi diagram: `HW_ERR_INVALID_INPUT`). `*out_data` (NULL when empty) and its length
 * `*out_len` are valid as long as the triangulation.
 *
 * # Safety
 * `delaunay` must be NULL or a live triangulation; `out_data` and `out_len` writable.
 * \ingroup voronoi
 */
hw_status hw_delaunay_view(const hw_delaunay *delaunay,
                           hw_voronoi_array which,
                           const uint32_t **out_data,
                           size_t *out_len);

/**
 * Clips every cell to the rectangle `[xmin, xmax] × [ymin, ymax]`. A rectangle of zero or
 * negative extent, or with a non-finite bound, gives `HW_ERR_INVALID_INPUT`. On success
 * `*out_cells` receives new cells to release with hw_voronoi_cells_free().
 *
 * # Safety
 * `voronoi` must be NULL or a live diagram; `out_cells` writable.
 * \ingroup voronoi
 */
hw_status hw_voronoi_clip_rect(const hw_voronoi *voronoi,
                               double xmin,
                               double ymin,
                               double xmax,
                               double ymax,
                               hw_voronoi_cells **out_cells);

/**
 * Clips every cell to the convex polygon of `n_vertices` vertices given as `2 * n_vertices`
 * doubles (x, y per vertex), in either orientation; vertices on the segment between their
 * neighbours are dropped. Fewer than three distinct vertices, zero area or a non-finite vertex
 * give `HW_ERR_INVALID_INPUT`, and so does a polygon that is not convex (the message names a
 * vertex where it turns the wrong way). On success `*out_cells` receives new cells to release
 * with hw_voronoi_cells_free().
 *
 * # Safety
 * `voronoi` must be NULL or a live diagram; `clip_xy` must point to `2 * n_vertices` doubles;
 * `out_cells` writable.
 * \ingroup voronoi
 */
hw_status hw_voronoi_clip_convex(const hw_voronoi *voronoi,
                                 const double *clip_xy,
                                 size_t n_vertices,
                                 hw_voronoi_cells **out_cells);

/**
 * Releases clipped cells. NULL is a no-op; cells freed already are refused (within the limits
 * the ownership conventions at the top of the header state).
 *
 * # Safety
 * `cells` must be NULL or cells from this library not in use by another thread.
 * \ingroup voronoi
 */
void hw_voronoi_cells_free(hw_voronoi_cells *cells);

/**
 * Number of cells, one per input site (empty ones included); 0 for NULL.
 *
 * # Safety
 * `cells` must be NULL or live cells.
 * \ingroup voronoi
 */
size_t hw_voronoi_cells_n_cells(const hw_voronoi_cells *cells);

/**
 * A read-only view of all cell corners: `*out_xy` (x, y per position; the region's corners
 * first, then Voronoi vertices inside it, then boundary crossings, then the corners of cells
 * rebuilt from their exact polygons; NULL when empty) and their
 * number `*out_n_positions`, valid as long as the cells.
 *
 * # Safety
 * `cells` must be NULL or live cells; `out_xy` and `out_n_positions` writable.
 * \ingroup voronoi
 */
hw_status hw_voronoi_cells_positions(const hw_voronoi_cells *cells,
                                     const double **out_xy,
                                     size_t *out_n_positions);

/**
 * A read-only view of the cell of `site`: `*out_indices` (NULL when empty), indices into
 * hw_voronoi_cells_positions(), counter-clockwise, and their number `*out_len` (0 for a
 * duplicate site or a cell that misses the region). Out of range: `HW_ERR_INVALID_HANDLE`.
 *
 * # Safety
 * `cells` must be NULL or live cells; `out_indices` and `out_len` writable.
 * \ingroup voronoi
 */
hw_status hw_voronoi_cells_polygon(const hw_voronoi_cells *cells,
                                   hw_site site,
                                   const uint32_t **out_indices,
                                   size_t *out_len);

/**
 * Area and centroid of the cell of `site`. An empty cell has area 0 and gives
 * `HW_ERR_NOT_FOUND` when its centroid is asked for; pass NULL for an output not wanted. Out of
 * range: `HW_ERR_INVALID_HANDLE`.
 *
 * # Safety
 * `cells` must be NULL or live cells; `out_area` NULL or writable; `out_centroid` NULL or two
 * writable doubles.
 * \ingroup voronoi
 */
hw_status hw_voronoi_cells_area_centroid(const hw_voronoi_cells *cells,
                                         hw_site site,
                                         double *out_area,
                                         double *out_centroid);

/**
 * The cells as a new half-edge mesh (z = 0) whose vertices are hw_voronoi_cells_positions(), so
 * neighbouring cells share edges: face `k` is the `k`-th non-empty cell in site order (see
 * hw_voronoi_cells_face_sites()). The mesh kernel can edit it. Release it with hw_mesh_free().
 *
 * # Safety
 * `cells` must be NULL or live cells; `out_mesh` writable.
 * \ingroup voronoi
 */
hw_status hw_voronoi_cells_mesh(const hw_voronoi_cells *cells, hw_mesh **out_mesh);

/**
 * Copies the site of every face of hw_voronoi_cells_mesh() into `out_sites` (`*out_needed`, when
 * not NULL, receives the face count); `capacity` too small: `HW_ERR_BUFFER_TOO_SMALL`.
 *
 * # Safety
 * `cells` must be NULL or live cells; `out_sites` NULL or `capacity` writable elements;
 * `out_needed` NULL or writable.
 * \ingroup voronoi
 */
hw_status hw_voronoi_cells_face_sites(const hw_voronoi_cells *cells,
                                      hw_site *out_sites,
                                      size_t capacity,
                                      size_t *out_needed);

/**
 * Lloyd relaxation: moves every site to the centroid of its Voronoi cell clipped to the convex
 * polygon `clip_xy` (`2 * n_clip_vertices` doubles; a rectangle is four corners), repeatedly,
 * for at most `max_iterations` iterations or until no site moved farther than `tolerance` in
 * one iteration (0 runs them all).
 *
 * `xy` holds the `n_sites` sites (x, y each); the relaxed sites are written to `out_xy`, which
 * holds as many doubles and may be the same array as `xy`. Sites whose cell misses the region
 * stay where they are; a duplicate stays while its representative moves, so they separate.
 * `*out_iterations` and `*out_max_displacement` (each may be NULL) receive the iterations run
 * and the largest move of the last one. Bad sites, a bad clip polygon (see
 * hw_voronoi_clip_convex()) or a negative or non-finite tolerance give `HW_ERR_INVALID_INPUT`,
 * naming the site or the tolerance (sites are checked also when `max_iterations` is 0); so does
 * a misaligned `out_xy`.
 *
 * # Safety
 * `xy` and `out_xy` must point to `2 * n_sites` doubles (readable, resp. writable; NULL only
 * when `n_sites` is 0); `clip_xy` to `2 * n_clip_vertices` doubles; the other outputs NULL or
 * writable.
 * \ingroup voronoi
 */
hw_status hw_voronoi_lloyd(const double *xy,
                           size_t n_sites,
                           const double *clip_xy,
                           size_t n_clip_vertices,
                           uint32_t max_iterations,
                           double tolerance,
                           double *out_xy,
                           uint32_t *out_iterations,
                           double *out_max_displacement);

/**
 * Labels every pixel of a `width × height` image of the rectangle `[xmin, xmax] × [ymin, ymax]`
 * with the index of the site nearest to the pixel's centre under `metric` — decided exactly,
 * ties to the smallest index; duplicates never appear. Row-major, row 0 at the top (largest y).
 *
 * `out_labels` must hold `width * height` labels; `*out_needed` (when not NULL) always receives
 * that count, and a smaller `capacity` gives `HW_ERR_BUFFER_TOO_SMALL` before any work. A diagram
 * without sites labels every pixel `HW_INVALID_INDEX`. A zero size, an unknown metric, a
 * non-finite bound or a misaligned `out_labels` give `HW_ERR_INVALID_INPUT`.
 *
 * # Safety
 * `voronoi` must be NULL or a live diagram; `out_labels` NULL or `capacity` writable elements;
 * `out_needed` NULL or writable.
 * \ingroup voronoi
 */
hw_status hw_voronoi_label_image(const hw_voronoi *voronoi,
                                 hw_metric metric_kind,
                                 double xmin,
                                 double ymin,
                                 double xmax,
                                 double ymax,
                                 uint32_t width,
                                 uint32_t height,
                                 uint32_t *out_labels,
                                 size_t capacity,
                                 size_t *out_needed);

/**
 * The default SVG options: 800 pixels wide, filled cells, sites, no Delaunay edges.
 * \ingroup voronoi
 */
hw_svg_options hw_svg_options_default(void);

/**
 * Copies an SVG drawing of `cells` (clipped from `voronoi`) into `out_text`, NUL-terminated;
 * `options` NULL means hw_svg_options_default(). `*out_needed` (when not NULL) always receives the
 * size needed, terminator included; a smaller `capacity` gives `HW_ERR_BUFFER_TOO_SMALL`. Cells
 * from another diagram or a non-positive width give `HW_ERR_INVALID_INPUT`.
 *
 * # Safety
 * `voronoi` and `cells` must be NULL or live objects; `options` NULL or readable; `out_text` NULL
 * or `capacity` writable bytes; `out_needed` NULL or writable.
 * \ingroup voronoi
 */
hw_status hw_voronoi_svg(const hw_voronoi *voronoi,
                         const hw_voronoi_cells *cells,
                         const hw_svg_options *options,
                         char *out_text,
                         size_t capacity,
                         size_t *out_needed);

/**
 * Writes an SVG drawing of `cells` (clipped from `voronoi`) to the file `path`; `options` NULL
 * means hw_svg_options_default(). A file that cannot be written gives `HW_ERR_IO`.
 *
 * # Safety
 * `voronoi` and `cells` must be NULL or live objects; `options` NULL or readable; `path` NULL
 * or NUL-terminated.
 * \ingroup voronoi
 */
hw_status hw_voronoi_svg_write(const hw_voronoi *voronoi,
                               const hw_voronoi_cells *cells,
                               const hw_svg_options *options,
                               const char *path);

/* ----------------------------------------------------------------------------------------------
 * Mesh doctor
 * ---------------------------------------------------------------------------------------------- */

/**
 * The doctor's thresholds; hw_doctor_options_default() gives the documented defaults.
 * \ingroup doctor
 */
typedef struct {
  /**
   * Distance under which two vertices are near duplicates and a vertex lies on an edge,
   * relative to the diagonal of the bounding box of the vertices faces name. 0 to 1; default
   * 1e-9.
   */
  double relative_tolerance;
  /**
   * A triangle with an angle below this (degrees) is a needle. Default 5.
   */
  double needle_angle_degrees;
  /**
   * A triangle with an angle above this (degrees) is a cap. Default 175.
   */
  double cap_angle_degrees;
  /**
   * Two faces sharing an edge whose normals are more than this (degrees) apart are folded.
   * Default 175.
   */
  double fold_angle_degrees;
  /**
   * An edge longer than this many times the median edge is long. At least 1; default 10.
   */
  double long_edge_ratio;
  /**
   * A component is small when its face count or diameter is at most this fraction of the
   * largest's. 0 to 1; default 0.01.
   */
  double small_component_ratio;
} hw_doctor_options;

/**
 * One kind of finding that is a list of elements (see hw_doctor_report_finding()). The values
 * run from ::HW_DOCTOR_FINDING_FIRST to `HW_DOCTOR_FINDING_FIRST + HW_DOCTOR_FINDING_COUNT - 1`,
 * apart from the diagnostic's lists (::hw_diagnostic_list, ::hw_diagnostic_edges), so a value of
 * one family passed where another is expected is refused, never read as a different list.
 * \ingroup doctor
 */
typedef uint32_t hw_doctor_finding;

/**
 * The first finding kind.
 * \ingroup doctor
 */
#define HW_DOCTOR_FINDING_FIRST 64

/**
 * Indices of small components (into hw_doctor_report_component()); one id per item.
 * \ingroup doctor
 */
#define HW_DOCTOR_FINDING_SMALL_COMPONENTS 64

/**
 * Faces of a closed path along which the orientation flips (the surface is not orientable),
 * each sharing an edge with the next and the last with the first; one id per item.
 * \ingroup doctor
 */
#define HW_DOCTOR_FINDING_NON_ORIENTABLE_WITNESS 65

/**
 * Edges whose ends are at the same position: 2 ids per item (vertices, smaller first).
 * \ingroup doctor
 */
#define HW_DOCTOR_FINDING_ZERO_LENGTH_EDGES 66

/**
 * Triangles with an angle below the needle threshold; one id per item.
 * \ingroup doctor
 */
#define HW_DOCTOR_FINDING_NEEDLES 67

/**
 * Triangles with an angle above the cap threshold; one id per item.
 * \ingroup doctor
 */
#define HW_DOCTOR_FINDING_CAPS 68

/**
 * Edges whose two faces fold onto each other: 4 ids per item (the two vertices, smaller
 * first, then the two faces, ascending).
 * \ingroup doctor
 */
#define HW_DOCTOR_FINDING_FOLDED_EDGES 69

/**
 * Edges longer than the long-edge ratio times the median: 2 ids per item (vertices).
 * \ingroup doctor
 */
#define HW_DOCTOR_FINDING_LONG_EDGES 70

/**
 * Vertices at exactly the position of a lower vertex: 2 ids per item (the vertex, then the
 * lowest vertex at that position).
 * \ingroup doctor
 */
#define HW_DOCTOR_FINDING_DUPLICATE_POSITIONS 71

/**
 * Vertices within the tolerance of a lower vertex (not at its position): 2 ids per item (the
 * vertex, then the first vertex of its group).
 * \ingroup doctor
 */
#define HW_DOCTOR_FINDING_NEAR_DUPLICATE_VERTICES 72

/**
 * Faces on the vertex set of a lower face, in either orientation: 2 ids per item (the face,
 * then the lowest such face).
 * \ingroup doctor
 */
#define HW_DOCTOR_FINDING_DUPLICATE_FACES 73

/**
 * Vertices lying inside a boundary edge they are not an end of: 4 ids per item (the vertex,
 * the edge's two ends, smaller first, and the edge's face).
 * \ingroup doctor
 */
#define HW_DOCTOR_FINDING_T_VERTICES 74

/**
 * Pairs of faces that intersect other than along the vertices and edges they share, decided
 * exactly (polygons as their triangles; touching counts; triangles with exactly collinear
 * corners and faces on non-finite vertices are not tested): 2 ids per item (faces, smaller first),
 * sorted.
 * \ingroup doctor
 */
#define HW_DOCTOR_FINDING_SELF_INTERSECTIONS 75

/**
 * The number of finding kinds.
 * \ingroup doctor
 */
#define HW_DOCTOR_FINDING_COUNT 12

/**
 * The surface's verdicts. `manifold`: no non-manifold edge or vertex and no malformed face;
 * `closed`: no boundary; `oriented`: every component orientable and consistently oriented;
 * `closed_polyhedron`: all three, finite coordinates, every component enclosing a positive
 * volume, no self-intersection and no zero-area face.
 * \ingroup doctor
 */
typedef struct {
  /**
   * No non-manifold edge or vertex and no malformed face.
   */
  bool manifold;
  /**
   * No boundary.
   */
  bool closed;
  /**
   * Every component orientable and consistently oriented.
   */
  bool oriented;
  /**
   * All three, finite coordinates, every component enclosing a positive volume, no
   * self-intersection and no zero-area face.
   */
  bool closed_polyhedron;
  /**
   * Why it is not a closed polyhedron (the first reason, static text), NULL when it is one.
   */
  const char *reason;
} hw_doctor_verdict;

/**
 * One connected component (faces joined through shared edges).
 * \ingroup doctor
 */
typedef struct {
  /**
   * Its lowest face.
   */
  uint32_t first_face;
  /**
   * Its faces.
   */
  size_t n_faces;
  /**
   * Its distinct edges.
   */
  size_t n_edges;
  /**
   * Distinct vertices (one shared with another component through a non-manifold vertex
   * counts in both).
   */
  size_t n_vertices;
  /**
   * Its boundary loops (0 when it is closed).
   */
  size_t n_boundary_loops;
  /**
   * V − E + F.
   */
  int64_t euler_characteristic;
  /**
   * The genus of an orientable 2-manifold component; -1 for any other.
   */
  int64_t genus;
  /**
   * No boundary edge (every edge has two or more faces).
   */
  bool closed;
  /**
   * No non-manifold edge or vertex.
   */
  bool manifold;
  /**
   * Its faces can be oriented so that every two-face edge is walked both ways.
   */
  bool orientable;
  /**
   * Every two-face edge is walked both ways as given.
   */
  bool consistently_oriented;
  /**
   * 1 when a closed, manifold, consistently oriented component faces outward (encloses a
   * positive volume), -1 inward, 0 otherwise or when it encloses no volume.
   */
  int32_t outward;
  /**
   * The signed volume it encloses (when `outward` is not 0 or the volume is 0; NaN for a
   * component that is not closed, manifold and consistently oriented). May overflow to
   * infinity or underflow to 0 at extreme coordinates: `outward` keeps the sign.
   */
  double volume;
  /**
   * The sum of its faces' areas.
   */
  double area;
  /**
   * Its bounding box: lowest x, y, z, then highest x, y, z.
   */
  double bounding_box[6];
} hw_doctor_component;

/**
 * The doctor's default thresholds.
 * \ingroup doctor
 */
hw_doctor_options hw_doctor_options_default(void);

/**
 * Examines an indexed face list (same arrays as hw_mesh_from_indexed()) with `options` (NULL
 * for the defaults). Malformed faces and non-finite coordinates are findings, not errors;
 * `HW_ERR_INVALID_INPUT` means an option is out of range or the list as a whole is malformed
 * (sizes not adding up to `n_indices`), or its triangulation is too large for 32-bit indices.
 * On success `*out_report` receives a report to release
 * with hw_doctor_report_free(). The input is never changed.
 *
 * # Safety
 * As for hw_mesh_from_indexed(); `options` NULL or readable; `out_report` writable.
 * \ingroup doctor
 */
hw_status hw_doctor_examine_indexed(const double *positions,
                                    size_t n_vertices,
                                    const uint32_t *face_sizes,
                                    size_t n_faces,
                                    const uint32_t *indices,
                                    size_t n_indices,
                                    const hw_doctor_options *options,
                                    hw_doctor_report **out_report);

/**
 * Examines a mesh's live faces (see hw_doctor_examine_indexed()).
 *
 * # Safety
 * `mesh` must be NULL or live; `options` NULL or readable; `out_report` writable.
 * \ingroup doctor
 */
hw_status hw_doctor_examine_mesh(const hw_mesh *mesh,
                                 const hw_doctor_options *options,
                                 hw_doctor_report **out_report);

/**
 * Releases a report. NULL is a no-op; freeing twice is detected and refused.
 *
 * # Safety
 * `report` must be NULL or a report from this library, not in use by another thread.
 * \ingroup doctor
 */
void hw_doctor_report_free(hw_doctor_report *report);

/**
 * The report's diagnostic of the input (malformed faces, non-finite coordinates, non-manifold
 * and inconsistently oriented edges, non-manifold and unreferenced vertices, zero-area faces),
 * read with the hw_diagnostic_* calls; owned by the report (do not free it), valid as long as
 * the report. NULL for a NULL report.
 *
 * # Safety
 * `report` must be NULL or live.
 * \ingroup doctor
 */
const hw_diagnostic *hw_doctor_report_diagnostic(const hw_doctor_report *report);

/**
 * The name of a finding kind ("needles", "T-vertices", …) as static text; NULL for an unknown
 * kind.
 * \ingroup doctor
 */
const char *hw_doctor_finding_name(hw_doctor_finding kind);

/**
 * A zero-copy view of one finding: `*out_ids` holds `*out_n_items` items of
 * `*out_ids_per_item` ids each (see each ::hw_doctor_finding), NULL when there are none;
 * valid as long as the report.
 *
 * # Safety
 * `report` must be NULL or live; `out_ids`, `out_n_items` and `out_ids_per_item` writable.
 * \ingroup doctor
 */
hw_status hw_doctor_report_finding(const hw_doctor_report *report,
                                   hw_doctor_finding kind,
                                   const uint32_t **out_ids,
                                   size_t *out_n_items,
                                   size_t *out_ids_per_item);

/**
 * The report's verdicts.
 *
 * # Safety
 * `report` must be NULL or live; `out_verdict` writable.
 * \ingroup doctor
 */
hw_status hw_doctor_report_verdict(const hw_doctor_report *report, hw_doctor_verdict *out_verdict);

/**
 * The number of components; 0 for a NULL report.
 *
 * # Safety
 * `report` must be NULL or live.
 * \ingroup doctor
 */
size_t hw_doctor_report_n_components(const hw_doctor_report *report);

/**
 * Component `index` (components in order of their lowest face).
 *
 * # Safety
 * `report` must be NULL or live; `out_component` writable.
 * \ingroup doctor
 */
hw_status hw_doctor_report_component(const hw_doctor_report *report,
                                     size_t index,
                                     hw_doctor_component *out_component);

/**
 * The number of boundary loops; 0 for a NULL report.
 *
 * # Safety
 * `report` must be NULL or live.
 * \ingroup doctor
 */
size_t hw_doctor_report_n_boundary_loops(const hw_doctor_report *report);

/**
 * Boundary loop `index`: a zero-copy view of its vertices in order (each joined by a boundary
 * edge to the next, the last to the first), valid as long as the report; its perimeter; and a
 * face along it.
 *
 * # Safety
 * `report` must be NULL or live; every output writable.
 * \ingroup doctor
 */
hw_status hw_doctor_report_boundary_loop(const hw_doctor_report *report,
                                         size_t index,
                                         const uint32_t **out_vertices,
                                         size_t *out_n_vertices,
                                         double *out_perimeter,
                                         uint32_t *out_face);

/**
 * The number of non-manifold vertices whose fans the report lists: those of
 * ::HW_DIAGNOSTIC_LIST_NON_MANIFOLD_VERTICES, in the same order; 0 for a NULL report.
 *
 * # Safety
 * `report` must be NULL or live.
 * \ingroup doctor
 */
size_t hw_doctor_report_n_vertex_fans(const hw_doctor_report *report);

/**
 * Fan `fan` of non-manifold vertex `index` (see hw_doctor_report_n_vertex_fans()): the vertex,
 * its number of fans, and a zero-copy view of the fan's faces (ascending; fans in order of their
 * lowest face), valid as long as the report.
 *
 * # Safety
 * `report` must be NULL or live; every output writable.
 * \ingroup doctor
 */
hw_status hw_doctor_report_vertex_fan(const hw_doctor_report *report,
                                      size_t index,
                                      size_t fan,
                                      uint32_t *out_vertex,
                                      size_t *out_n_fans,
                                      const uint32_t **out_faces,
                                      size_t *out_n_faces);

/**
 * The report as text (a summary line, the diagnostic, a line per component and per non-empty
 * finding naming its first few elements), copied NUL-terminated into `out_text`; `*out_needed`
 * receives the size needed even when `out_text` is too small (then `HW_ERR_BUFFER_TOO_SMALL` and
 * nothing is written to `out_text`).
 *
 * # Safety
 * `report` must be NULL or live; `out_text` NULL or `capacity` writable bytes; `out_needed` NULL
 * or writable.
 * \ingroup doctor
 */
hw_status hw_doctor_report_text(const hw_doctor_report *report,
                                char *out_text,
                                size_t capacity,
                                size_t *out_needed);

/**
 * The whole report as one JSON object (every element of every finding), copied as
 * hw_doctor_report_text() copies its text.
 *
 * # Safety
 * As for hw_doctor_report_text().
 * \ingroup doctor
 */
hw_status hw_doctor_report_json(const hw_doctor_report *report,
                                char *out_text,
                                size_t capacity,
                                size_t *out_needed);

/**
 * The pairs of faces of an indexed face list (same arrays as hw_mesh_from_indexed()) that
 * intersect other than along the vertices and edges they share (by vertex index), with the
 * semantics of CGAL's `Polygon_mesh_processing::self_intersections`: faces sharing no vertex
 * that touch anywhere, faces sharing one vertex that meet elsewhere, faces sharing an edge that
 * overlap beyond it (coplanar, third corners on the same side). A face whose triangle has
 * exactly collinear corners is degenerate: it is reported once as the pair (f, f) and not
 * tested against the others. Polygons are tested as the triangles hw_render_buffers_build()
 * gives them; the triangles of one face are not tested against each other.
 *
 * Every decision is exact, at any magnitude of finite coordinates. O(n log n + k) for n
 * triangles and k pairs of overlapping bounding boxes; on hw_set_thread_count() threads. On
 * success `*out_pairs` receives the pairs, sorted, smaller face first; release them with
 * hw_face_pairs_free(). `HW_ERR_INVALID_INPUT`: the sizes do not add up to `n_indices`, an
 * index is out of range, or a corner of a face has a NaN or infinite coordinate (the
 * message names the face and the vertex). `HW_ERR_OUT_OF_MEMORY`: the search needs more
 * memory than the system gives (checked before it starts).
 *
 * # Safety
 * As for hw_mesh_from_indexed(); `out_pairs` writable.
 * \ingroup doctor
 */
hw_status hw_self_intersections_indexed(const double *positions,
                                        size_t n_vertices,
                                        const uint32_t *face_sizes,
                                        size_t n_faces,
                                        const uint32_t *indices,
                                        size_t n_indices,
                                        hw_face_pairs **out_pairs);

/**
 * A zero-copy view of the pairs: `*out_ids` holds `2 * *out_n_pairs` face ids (NULL when there
 * are none), valid as long as `pairs`.
 *
 * # Safety
 * `pairs` must be NULL or live; `out_ids` and `out_n_pairs` writable.
 * \ingroup doctor
 */
hw_status hw_face_pairs_view(const hw_face_pairs *pairs,
                             const uint32_t **out_ids,
                             size_t *out_n_pairs);

/**
 * Releases face pairs. NULL is a no-op; freeing twice is detected and refused.
 *
 * # Safety
 * `pairs` must be NULL or from this library, not in use by another thread.
 * \ingroup doctor
 */
void hw_face_pairs_free(hw_face_pairs *pairs);

/* ----------------------------------------------------------------------------------------------
 * Repairs
 * ---------------------------------------------------------------------------------------------- */

/**
 * Which components hw_soup_remove_small_components() removes.
 * \ingroup repair
 */
typedef uint32_t hw_small_components;

/**
 * Components of at most `value` faces.
 * \ingroup repair
 */
#define HW_SMALL_COMPONENTS_BY_FACE_COUNT 0

/**
 * Components whose bounding-box diagonal is at most `value` (0 to 1) times the largest one's.
 * \ingroup repair
 */
#define HW_SMALL_COMPONENTS_BY_RELATIVE_DIAMETER 1

/**
 * What hw_soup_repair_non_manifold_edges() does at an edge of three faces or more.
 * \ingroup repair
 */
typedef uint32_t hw_non_manifold_edges;

/**
 * Keep every face and cut the surface along the edge (copies of its ends).
 * \ingroup repair
 */
#define HW_NON_MANIFOLD_EDGES_CUT 0

/**
 * Keep faces in order while the edge has at most one face each way; remove the others.
 * \ingroup repair
 */
#define HW_NON_MANIFOLD_EDGES_REMOVE_FACES 1

/**
 * One list of a repair report, for hw_repair_report_list().
 * \ingroup repair
 */
typedef uint32_t hw_repair_list;

/**
 * Pairs `removed, kept` (2 values each) of vertices merged into another.
 * \ingroup repair
 */
#define HW_REPAIR_LIST_MERGED_VERTICES 0

/**
 * Vertices removed (merged ones included).
 * \ingroup repair
 */
#define HW_REPAIR_LIST_REMOVED_VERTICES 1

/**
 * Faces removed.
 * \ingroup repair
 */
#define HW_REPAIR_LIST_REMOVED_FACES 2

/**
 * Pairs `removed, kept` (2 values each) of duplicate faces.
 * \ingroup repair
 */
#define HW_REPAIR_LIST_DUPLICATE_FACES 3

/**
 * Pairs `a, b` (2 values each) of boundary half-edges stitched: `a`'s edge stays, `b`'s goes.
 * \ingroup repair
 */
#define HW_REPAIR_LIST_STITCHED_HALFEDGES 4

/**
 * The vertex each added vertex copies: the `i`-th added vertex (id `n + i`, `n` the vertex
 * count before the repair) copies vertex `ids[i]`.
 * \ingroup repair
 */
#define HW_REPAIR_LIST_VERTEX_COPIES 5

/**
 * Faces whose corner order was reversed.
 * \ingroup repair
 */
#define HW_REPAIR_LIST_REORIENTED_FACES 6

/**
 * Pairs `cap, across` (2 values each) of triangles whose shared edge
 * hw_mesh_remove_degenerate_faces() flipped (`cap` had a corner on the edge; both stay).
 * \ingroup repair
 */
#define HW_REPAIR_LIST_FLIPPED_FACES 7

/**
 * How hw_mesh_fill_holes() and hw_repair_mesh() close a hole.
 * \ingroup repair
 */
typedef uint32_t hw_fill_mode;

/**
 * Triangles on the hole's corners only; no vertex is added.
 * \ingroup repair
 */
#define HW_FILL_MODE_TRIANGULATE 0

/**
 * The triangulation refined (centroid splits and Delaunay-like flips) until its edges match
 * the lengths of the mesh's edges at the hole's rim; adds vertices inside the hole, whose
 * attributes are the mean of those of the triangle they split.
 * \ingroup repair
 */
#define HW_FILL_MODE_REFINE 1

/**
 * Refined, then the added vertices moved to minimise a thin-plate energy (squared cotangent
 * Laplacian) with the rim and the mesh around it fixed, so the fill continues the surface
 * (a sparse Cholesky solve, refined by up to 8 iterations); a hole whose solve does not
 * converge is refused.
 * \ingroup repair
 */
#define HW_FILL_MODE_FAIR 2

/**
 * Which holes hw_mesh_fill_holes() fills, and how; start from hw_fill_hole_options_default().
 * \ingroup repair
 */
typedef struct {
  /**
   * Holes with more boundary edges than this are left open.
   */
  size_t max_edges;
  /**
   * Holes whose perimeter exceeds this are left open; infinity for no bound.
   */
  double max_perimeter;
  /**
   * How each hole is closed. Default ::HW_FILL_MODE_TRIANGULATE.
   */
  hw_fill_mode mode;
} hw_fill_hole_options;

/**
 * Options of hw_repair_mesh(); hw_repair_options_default() merges and stitches exact
 * duplicates only, mends exactly degenerate triangles, splits boundary edges at vertices
 * exactly on them, fills no hole and keeps every component.
 * \ingroup repair
 */
typedef struct {
  /**
   * Vertices this close merge (absolute, or when `merge_relative` a fraction 0 to 1 of the
   * bounding-box diagonal). Default 0: identical positions.
   */
  double merge_tolerance;
  /**
   * Whether `merge_tolerance` is relative. Default false.
   */
  bool merge_relative;
  /**
   * Boundary edges whose ends are this close stitch (as `merge_tolerance`). Default 0.
   */
  double stitch_tolerance;
  /**
   * Whether `stitch_tolerance` is relative. Default false.
   */
  bool stitch_relative;
  /**
   * Whether small components are removed (by `small_rule` and `small_value`, as
   * hw_soup_remove_small_components() takes them). Default false.
   */
  bool remove_small_components;
  /**
   * ::HW_SMALL_COMPONENTS_BY_FACE_COUNT or ::HW_SMALL_COMPONENTS_BY_RELATIVE_DIAMETER.
   */
  hw_small_components small_rule;
  /**
   * The face count or the diameter ratio.
   */
  double small_value;
  /**
   * Whether degenerate triangles are mended (hw_mesh_remove_degenerate_faces(), after the
   * build). Default true.
   */
  bool remove_degenerate_faces;
  /**
   * Triangles this close to a line are degenerate (as `merge_tolerance`). Default 0: exactly
   * on one line.
   */
  double degenerate_tolerance;
  /**
   * Whether `degenerate_tolerance` is relative. Default false.
   */
  bool degenerate_relative;
  /**
   * Whether boundary edges are split at T-vertices (hw_mesh_remove_t_vertices(), before
   * stitching). Default true.
   */
  bool remove_t_vertices;
  /**
   * Boundary vertices this close to another boundary edge split it (as `merge_tolerance`).
   * Default 0: exactly on the edge.
   */
  double t_vertex_tolerance;
  /**
   * Whether `t_vertex_tolerance` is relative. Default false.
   */
  bool t_vertex_relative;
  /**
   * Whether holes are filled (after stitching, as hw_mesh_fill_holes() fills them; holes it
   * refuses stay open). Default false: an open surface is often open on purpose.
   */
  bool fill_holes;
  /**
   * Holes with more boundary edges than this are left open. Default `SIZE_MAX`.
   */
  size_t fill_max_edges;
  /**
   * How holes are closed. Default ::HW_FILL_MODE_TRIANGULATE.
   */
  hw_fill_mode fill_mode;
} hw_repair_options;

/**
 * One list of hw_repair_fates_list().
 * \ingroup repair
 */
typedef uint32_t hw_fates_list;

/**
 * The ::hw_fate of every input vertex.
 * \ingroup repair
 */
#define HW_FATES_LIST_VERTEX_KINDS 0

/**
 * The id that goes with every input vertex's fate.
 * \ingroup repair
 */
#define HW_FATES_LIST_VERTEX_IDS 1

/**
 * The ::hw_fate of every input face.
 * \ingroup repair
 */
#define HW_FATES_LIST_FACE_KINDS 2

/**
 * The id that goes with every input face's fate.
 * \ingroup repair
 */
#define HW_FATES_LIST_FACE_IDS 3

/**
 * Pairs `output vertex, input vertex` (2 values each) of the output vertices no input vertex
 * became, by output id: copies of an input vertex, and vertices a refined hole fill placed
 * (input vertex `UINT32_MAX`).
 * \ingroup repair
 */
#define HW_FATES_LIST_ADDED_VERTICES 4

/**
 * The output faces no input face became (the triangles filling holes), by output id.
 * \ingroup repair
 */
#define HW_FATES_LIST_ADDED_FACES 5

/**
 * The counts of hw_repair_fates_counts().
 * \ingroup repair
 */
typedef struct {
  /**
   * Input vertices in the output.
   */
  size_t kept_vertices;
  /**
   * Input vertices merged into another.
   */
  size_t merged_vertices;
  /**
   * Input vertices removed.
   */
  size_t removed_vertices;
  /**
   * Output vertices no input vertex became: copies of an input vertex, and vertices placed
   * by a refined hole fill (kept + added = output vertices).
   */
  size_t added_vertices;
  /**
   * Input faces in the output (kept + added = output faces).
   */
  size_t kept_faces;
  /**
   * Kept faces that run the other way round.
   */
  size_t reversed_faces;
  /**
   * Input faces removed.
   */
  size_t removed_faces;
  /**
   * Pairs of boundary edges stitched into one.
   */
  size_t stitched_edges;
  /**
   * Edges flipped to mend a degenerate triangle.
   */
  size_t flipped_edges;
  /**
   * Boundary edges split at a T-vertex.
   */
  size_t split_edges;
  /**
   * Output faces no input face became: the triangles filling holes.
   */
  size_t added_faces;
  /**
   * Holes filled.
   */
  size_t filled_holes;
  /**
   * Holes within the fill bounds that filling refused (left open).
   */
  size_t refused_holes;
} hw_repair_fate_counts;

/**
 * Makes a soup of an indexed face list (the arrays hw_mesh_from_indexed() takes), copied as
 * they are (nothing checked until a repair or a build looks at them), for the `hw_soup_*`
 * repairs; read it back with hw_soup_view(), release it with hw_soup_free().
 *
 * # Safety
 * As for hw_mesh_from_indexed(); `out_soup` writable.
 * \ingroup repair
 */
hw_status hw_soup_from_indexed(const double *positions,
                               size_t n_vertices,
                               const uint32_t *face_sizes,
                               size_t n_faces,
                               const uint32_t *indices,
                               size_t n_indices,
                               hw_soup **out_soup);

/**
 * Merges the soup's vertices at one position or within `tolerance` of each other (an absolute
 * distance, or when `relative` a fraction 0 to 1 of the bounding-box diagonal of the
 * vertices) into the lowest of each cluster, which keeps its position. Exact duplicates always
 * merge; near ones greedily, in index order, into the first lower kept vertex within the
 * tolerance (not transitively). Faces naming a merged vertex drop corners that repeat the one
 * before; one left with fewer than 3 distinct corners is removed (::HW_REPAIR_LIST_REMOVED_FACES).
 * Corner normals and texture coordinates follow their corners. `HW_ERR_INVALID_INPUT`, the
 * soup unchanged, for a tolerance negative, NaN, infinite, relative above 1 or positive below
 * 2^-48 of the positions' extent, and for a malformed soup (index out of range, sizes not
 * adding up). On success `*out_report` (when not NULL) receives the report.
 *
 * # Safety
 * `soup` must be NULL or a live soup no other thread uses; `out_report` NULL or writable.
 * \ingroup repair
 */
hw_status hw_soup_merge_vertices(hw_soup *soup,
                                 double tolerance,
                                 bool relative,
                                 hw_repair_report **out_report);

/**
 * Removes every face whose vertex set is that of a lower face (either orientation, any
 * starting corner), keeping the lowest (::HW_REPAIR_LIST_DUPLICATE_FACES pairs each removed face
 * with the one kept). Vertices are untouched. Refusals and report as for
 * hw_soup_merge_vertices().
 *
 * # Safety
 * `soup` must be NULL or a live soup no other thread uses; `out_report` NULL or writable.
 * \ingroup repair
 */
hw_status hw_soup_remove_duplicate_faces(hw_soup *soup, hw_repair_report **out_report);

/**
 * Removes the vertices no face names, renumbering the others in order (the report's vertex
 * map). Refusals and report as for hw_soup_merge_vertices().
 *
 * # Safety
 * `soup` must be NULL or a live soup no other thread uses; `out_report` NULL or writable.
 * \ingroup repair
 */
hw_status hw_soup_remove_unreferenced_vertices(hw_soup *soup, hw_repair_report **out_report);

/**
 * Removes the faces of the small components (faces joined through shared edges) and the
 * vertices only they named: by ::HW_SMALL_COMPONENTS_BY_FACE_COUNT (at most `value` faces, a whole
 * number) or ::HW_SMALL_COMPONENTS_BY_RELATIVE_DIAMETER (a diagonal at most `value` times the
 * largest). `HW_ERR_INVALID_INPUT`, the soup unchanged, for a bad rule or value; otherwise as
 * hw_soup_merge_vertices().
 *
 * # Safety
 * `soup` must be NULL or a live soup no other thread uses; `out_report` NULL or writable.
 * \ingroup repair
 */
hw_status hw_soup_remove_small_components(hw_soup *soup,
                                          hw_small_components rule,
                                          double value,
                                          hw_repair_report **out_report);

/**
 * Reverses faces so that neighbours agree in orientation (in each connected part the smaller
 * side turns) and every closed component faces outward, as a build's `HW_BUILD_POLICY_REPAIR`
 * does; a non-orientable part keeps an edge whose faces disagree. Reversed faces keep their
 * corners' normals and texture coordinates, in reverse order (::HW_REPAIR_LIST_REORIENTED_FACES);
 * vertices are untouched. Refusals and report as for hw_soup_merge_vertices().
 *
 * # Safety
 * `soup` must be NULL or a live soup no other thread uses; `out_report` NULL or writable.
 * \ingroup repair
 */
hw_status hw_soup_orient_faces(hw_soup *soup, hw_repair_report **out_report);

/**
 * Makes every edge shared by at most two faces: ::HW_NON_MANIFOLD_EDGES_CUT keeps every face
 * and gives the groups of faces around the edge's ends copies of them (appended,
 * ::HW_REPAIR_LIST_VERTEX_COPIES), ::HW_NON_MANIFOLD_EDGES_REMOVE_FACES keeps faces in order while
 * the edge has at most one face running each way and removes the others
 * (::HW_REPAIR_LIST_REMOVED_FACES). Run hw_soup_orient_faces() first. `HW_ERR_INVALID_INPUT`, the
 * soup unchanged, for an unknown `how`; otherwise as hw_soup_merge_vertices().
 *
 * # Safety
 * `soup` must be NULL or a live soup no other thread uses; `out_report` NULL or writable.
 * \ingroup repair
 */
hw_status hw_soup_repair_non_manifold_edges(hw_soup *soup,
                                            hw_non_manifold_edges how,
                                            hw_repair_report **out_report);

/**
 * Gives every fan of faces around a non-manifold vertex but the first a copy of the vertex
 * (appended, ::HW_REPAIR_LIST_VERTEX_COPIES), as builds do; corners keep their normals and texture
 * coordinates. Refusals and report as for hw_soup_merge_vertices().
 *
 * # Safety
 * `soup` must be NULL or a live soup no other thread uses; `out_report` NULL or writable.
 * \ingroup repair
 */
hw_status hw_soup_split_non_manifold_vertices(hw_soup *soup, hw_repair_report **out_report);

/**
 * Mends the mesh's degenerate triangles: those whose corners lie exactly on one line (decided
 * exactly), or within `tolerance` of it (absolute, or when `relative` a fraction of the live
 * vertices' bounding-box diagonal). A triangle with an edge at most the tolerance long (zero
 * when exact) has the edge collapsed into its lower end (::HW_REPAIR_LIST_MERGED_VERTICES), which
 * removes the two triangles beside it and keeps the surface closed; a cap (its corner opposite
 * its longest edge on that edge) has that edge flipped with the triangle across it
 * (::HW_REPAIR_LIST_FLIPPED_FACES) when the two new triangles are sound; any other is removed,
 * leaving a boundary. Every removed face is in ::HW_REPAIR_LIST_REMOVED_FACES. Faces of more than 3
 * corners are left as they are; vertices only removed faces named stay, isolated. Corners keep
 * their normals and texture coordinates (a corner at a merged vertex keeps its own). The mesh
 * is then compacted (the report's maps; the identity when nothing changed, the mesh then
 * unchanged). Afterwards no triangle is degenerate. `HW_ERR_INVALID_INPUT`, the mesh
 * unchanged, for a tolerance negative, NaN, infinite or relative above 1.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh no other thread uses; `out_report` NULL or writable.
 * \ingroup repair
 */
hw_status hw_mesh_remove_degenerate_faces(hw_mesh *mesh,
                                          double tolerance,
                                          bool relative,
                                          hw_repair_report **out_report);

/**
 * Splits every boundary edge on whose inside a boundary vertex lies (a T-vertex: exactly, or
 * within `tolerance` as for hw_mesh_remove_degenerate_faces()) with a new vertex at the
 * T-vertex's position, so that hw_mesh_stitch_borders() can then close the crack. The `i`-th
 * new vertex (id `n + i`, `n` the vertex count before) copies T-vertex `ids[i]` of
 * ::HW_REPAIR_LIST_VERTEX_COPIES; its attributes, and the new corner of the face beside the edge,
 * are interpolated along the edge. Edges whose face has a corner at the T-vertex's position
 * are left. Nothing is removed; the mesh is compacted (the report's maps cover the elements
 * there were before; the identity when nothing was split). Afterwards no boundary vertex lies
 * inside a boundary edge. Refusals as for hw_mesh_remove_degenerate_faces().
 *
 * # Safety
 * `mesh` must be NULL or a live mesh no other thread uses; `out_report` NULL or writable.
 * \ingroup repair
 */
hw_status hw_mesh_remove_t_vertices(hw_mesh *mesh,
                                    double tolerance,
                                    bool relative,
                                    hw_repair_report **out_report);

/**
 * Glues the mesh's boundary edges that lie on each other end on end (exactly, or within
 * `tolerance`, absolute or when `relative` a fraction of the live vertices' bounding-box
 * diagonal), like CGAL's `stitch_borders`: an edge is stitched when exactly one other boundary
 * edge joins the same positions the opposite way, and only where the mesh stays manifold with
 * distinct edges. Faces keep their corners' data; merged vertices go into the lowest, which
 * keeps its position and attributes. The mesh is then compacted: the report's maps give the
 * new ids (the identity when nothing was stitched, the mesh then unchanged). Refusals as for
 * hw_soup_merge_vertices(), the mesh unchanged.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh no other thread uses; `out_report` NULL or writable.
 * \ingroup repair
 */
hw_status hw_mesh_stitch_borders(hw_mesh *mesh,
                                 double tolerance,
                                 bool relative,
                                 hw_repair_report **out_report);

/**
 * A read-only view of one list of the report (`*out_ids`, NULL when empty, with `*out_len`
 * values; pair lists hold 2 values per pair). Lives as long as the report.
 *
 * # Safety
 * `report` must be NULL or live; `out_ids` and `out_len` writable.
 * \ingroup repair
 */
hw_status hw_repair_report_list(const hw_repair_report *report,
                                hw_repair_list list,
                                const uint32_t **out_ids,
                                size_t *out_len);

/**
 * The report's old-to-new maps, to read with hw_index_maps_view() (a soup's repairs fill the
 * vertex and face maps; the `hw_mesh_*` repairs all four). Owned by the report: do not free
 * it; it lives as long as the report. Also `*out_removed_corners` (when not NULL): corners
 * dropped from kept faces.
 *
 * # Safety
 * `report` must be NULL or live; `out_maps` writable; `out_removed_corners` NULL or writable.
 * \ingroup repair
 */
hw_status hw_repair_report_maps(const hw_repair_report *report,
                                const hw_index_maps **out_maps,
                                size_t *out_removed_corners);

/**
 * Releases a repair report. NULL is a no-op; a second free is refused (within the limits the
 * ownership conventions at the top of the header state).
 *
 * # Safety
 * `report` must be NULL or a report from this library, not in use by another thread.
 * \ingroup repair
 */
void hw_repair_report_free(hw_repair_report *report);

/**
 * Options that fill every hole, triangulated: no bound on edges or perimeter.
 * \ingroup repair
 */
hw_fill_hole_options hw_fill_hole_options_default(void);

/**
 * Fills the hole whose boundary loop holds half-edge `h` with triangles on its corners (no new
 * vertex): Liepa's minimum-weight triangulation up to 100 edges, beyond that a triangulation
 * on the hole's best-fit plane improved by edge flips. `*out_faces_added` (when not NULL)
 * receives the number of new triangles (edges − 2). New faces, edges and corners get zero
 * attributes. `HW_ERR_INVALID_HANDLE` for a bad `h`; `HW_ERR_REFUSED`, the mesh unchanged,
 * when `h` has a face, the loop passes twice through a vertex, every triangulation needs an
 * edge that exists already, a hole of more than 100 edges does not project onto a simple
 * polygon, or the fill would fold (a new triangle degenerate, or turned more than 150° from a
 * face beside it).
 *
 * # Safety
 * `mesh` must be NULL or a live mesh no other thread uses; `out_faces_added` NULL or writable.
 * \ingroup repair
 */
hw_status hw_mesh_fill_hole(hw_mesh *mesh, hw_halfedge h, size_t *out_faces_added);

/**
 * Fills every hole within `options`' bounds (NULL: every hole) as hw_mesh_fill_hole() does;
 * holes it refuses are left open. `*out_filled`, `*out_refused` and `*out_faces_added` (each
 * when not NULL) receive the holes filled, the holes refused and the triangles added.
 * `HW_ERR_INVALID_INPUT`, the mesh unchanged, for a NaN or negative `max_perimeter`.
 *
 * # Safety
 * `mesh` must be NULL or a live mesh no other thread uses; `options` NULL or readable; the
 * outputs NULL or writable.
 * \ingroup repair
 */
hw_status hw_mesh_fill_holes(hw_mesh *mesh,
                             const hw_fill_hole_options *options,
                             size_t *out_filled,
                             size_t *out_refused,
                             size_t *out_faces_added);

/**
 * The default options of hw_repair_mesh().
 * \ingroup repair
 */
hw_repair_options hw_repair_options_default(void);

/**
 * Repairs the soup into a new mesh: merges duplicate vertices (within the options' merge
 * tolerance), removes duplicate faces, builds under ::HW_BUILD_POLICY_REPAIR (non-manifold vertices
 * split, non-manifold edges cut, faces oriented consistently, closed components outward, faces
 * that cannot be kept left out), mends degenerate triangles and splits boundary edges at
 * T-vertices (each when the options ask, as by default), stitches borders, fills holes (when
 * asked), removes small components (when asked) and
 * unreferenced vertices. The soup is unchanged. `*out_mesh` passes hw_mesh_check() and its
 * faces build again under ::HW_BUILD_POLICY_STRICT. `*out_fates` (when not NULL) says what became of
 * every input vertex and face. `HW_ERR_INVALID_INPUT`, nothing written, for bad options and a
 * malformed soup; `HW_ERR_OUT_OF_MEMORY` when memory ran out.
 *
 * # Safety
 * `soup` NULL or live; `options` NULL or readable; `out_mesh` writable; `out_fates` NULL or
 * writable.
 * \ingroup repair
 */
hw_status hw_repair_mesh(const hw_soup *soup,
                         const hw_repair_options *options,
                         hw_mesh **out_mesh,
                         hw_repair_fates **out_fates);

/**
 * A read-only view of one list of the fates (`*out_ids`, NULL when empty, with `*out_len`
 * values). Lives as long as the fates.
 *
 * # Safety
 * `fates` NULL or live; `out_ids` and `out_len` writable.
 * \ingroup repair
 */
hw_status hw_repair_fates_list(const hw_repair_fates *fates,
                               hw_fates_list list,
                               const uint32_t **out_ids,
                               size_t *out_len);

/**
 * The number of elements of every fate, written to `*out_counts`.
 *
 * # Safety
 * `fates` NULL or live; `out_counts` writable.
 * \ingroup repair
 */
hw_status hw_repair_fates_counts(const hw_repair_fates *fates, hw_repair_fate_counts *out_counts);

/**
 * Releases the fates. NULL is a no-op; a second free is refused (within the limits the
 * ownership conventions at the top of the header state).
 *
 * # Safety
 * `fates` NULL or fates from this library, not in use by another thread.
 * \ingroup repair
 */
void hw_repair_fates_free(hw_repair_fates *fates);

/* ----------------------------------------------------------------------------------------------
 * Surfaces
 * ---------------------------------------------------------------------------------------------- */

/**
 * How the cells of a parametric surface become faces.
 * \ingroup surfaces
 */
typedef uint32_t hw_cell_faces;

/**
 * One quadrilateral per cell (a triangle where a pole collapses a side).
 * \ingroup surfaces
 */
#define HW_CELL_FACES_QUADS 0

/**
 * Two triangles per cell.
 * \ingroup surfaces
 */
#define HW_CELL_FACES_TRIANGLES 1

/**
 * How hw_surface_revolution() closes the profile's ends that are off the axis.
 * \ingroup surfaces
 */
typedef uint32_t hw_caps;

/**
 * Leave them open.
 * \ingroup surfaces
 */
#define HW_CAPS_NONE 0

/**
 * One planar polygon per end.
 * \ingroup surfaces
 */
#define HW_CAPS_POLYGON 1

/**
 * A fan of triangles from a new vertex on the axis.
 * \ingroup surfaces
 */
#define HW_CAPS_FAN 2

/**
 * The regular tetrahedron of the winged-edge literature's worked example, with its exact
 * coordinates and faces.
 *
 * # Safety
 * `out_mesh` must be writable.
 * \ingroup surfaces
 */
hw_status hw_surface_tetrahedron(hw_mesh **out_mesh);

/**
 * An axis-aligned cube of six quads centred at the origin, `side` long (positive, finite).
 *
 * # Safety
 * `out_mesh` must be writable.
 * \ingroup surfaces
 */
hw_status hw_surface_cube(double side, hw_mesh **out_mesh);

/**
 * A sphere of triangles centred at the origin: an icosahedron subdivided `level` times (each
 * level splits every triangle in four), projected onto the sphere of `radius`.
 *
 * # Safety
 * `out_mesh` must be writable.
 * \ingroup surfaces
 */
hw_status hw_surface_icosphere(double radius, uint32_t level, hw_mesh **out_mesh);

/**
 * A closed torus about the z axis: `major_steps` segments around the axis (≥ 3) and
 * `minor_steps` around the tube (≥ 3); `minor_radius` below `major_radius`.
 *
 * # Safety
 * `out_mesh` must be writable.
 * \ingroup surfaces
 */
hw_status hw_surface_torus(double major_radius,
                           double minor_radius,
                           uint32_t major_steps,
                           uint32_t minor_steps,
                           hw_cell_faces faces,
                           hw_mesh **out_mesh);

/**
 * A flat grid in the plane z = 0 centred at the origin, facing +z: `cells_x` by `cells_y` cells
 * (≥ 1 each) over `width` by `height`. Open, one boundary loop.
 *
 * # Safety
 * `out_mesh` must be writable.
 * \ingroup surfaces
 */
hw_status hw_surface_grid(double width,
                          double height,
                          uint32_t cells_x,
                          uint32_t cells_y,
                          hw_cell_faces faces,
                          hw_mesh **out_mesh);

/**
 * A cylindrical surface: the polyline `profile` (`n_points` points, x y z each; closed joins the
 * last point to the first) swept along the vector `direction` (3 doubles) in `steps` rows (≥ 1).
 * Faces follow `P'(u) × direction`.
 *
 * # Safety
 * `profile` must hold `3 * n_points` doubles; `direction` 3 doubles; `out_mesh` writable.
 * \ingroup surfaces
 */
hw_status hw_surface_sweep(const double *profile,
                           size_t n_points,
                           bool closed,
                           const double *direction,
                           uint32_t steps,
                           hw_cell_faces faces,
                           hw_mesh **out_mesh);

/**
 * A surface of revolution: `profile` (`n_points` points) turned about the axis through
 * `axis_origin` along `axis_direction` (3 doubles each), right-handed. `full_turn` welds the
 * last column to the first; otherwise the turn is `angle` radians, in (0, 2π). `steps` angular
 * steps (≥ 3 for a full turn, ≥ 1 otherwise). Profile points on the axis become poles; `caps`
 * closes the ends that are off it.
 *
 * # Safety
 * `profile` must hold `3 * n_points` doubles; `axis_origin` and `axis_direction` 3 doubles
 * each; `out_mesh` writable.
 * \ingroup surfaces
 */
hw_status hw_surface_revolution(const double *profile,
                                size_t n_points,
                                bool closed,
                                const double *axis_origin,
                                const double *axis_direction,
                                bool full_turn,
                                double angle,
                                uint32_t steps,
                                hw_caps caps,
                                hw_cell_faces faces,
                                hw_mesh **out_mesh);

/**
 * A ruled surface joining `first[i]` to `second[i]` (both `n_points` points, x y z each) with
 * straight rulings, `steps` rows (≥ 1) between them; `closed` joins the curves' ends.
 *
 * # Safety
 * `first` and `second` must hold `3 * n_points` doubles each; `out_mesh` writable.
 * \ingroup surfaces
 */
hw_status hw_surface_ruled(const double *first,
                           const double *second,
                           size_t n_points,
                           bool closed,
                           uint32_t steps,
                           hw_cell_faces faces,
                           hw_mesh **out_mesh);

/* ----------------------------------------------------------------------------------------------
 * Rendering buffers
 * ---------------------------------------------------------------------------------------------- */

/**
 * Where the normals of hw_render_buffers_build() come from.
 * \ingroup render
 */
typedef uint32_t hw_shading;

/**
 * Face normals: faceted; every vertex is split per face.
 * \ingroup render
 */
#define HW_SHADING_FLAT 0

/**
 * Vertex normals with the options' weighting: one render vertex per mesh vertex.
 * \ingroup render
 */
#define HW_SHADING_SMOOTH 1

/**
 * Smooth within regions bounded by edges sharper than the options' crease angle; vertices are
 * split along those edges only.
 * \ingroup render
 */
#define HW_SHADING_CREASE 2

/**
 * The default: the options' `corner_normals`, else the mesh's own corner normals (a file's `vn`,
 * hw_mesh_corner_normals_set()) when `mesh_corner_normals` is true, scaled to unit length. A
 * corner without one — none given, or a zero vector (how a mesh read from an OBJ stores the
 * corners its file gives no normal) or a NaN or infinite one — takes the smooth normal with the
 * options' weighting. ::HW_SHADING_FLAT, ::HW_SHADING_SMOOTH and ::HW_SHADING_CREASE ignore
 * those normals and compute every normal from the positions.
 * \ingroup render
 */
#define HW_SHADING_CORNER_NORMALS 3

/**
 * How hw_render_buffers_build() builds its arrays. Start from hw_render_options_default().
 * \ingroup render
 */
typedef struct {
  /**
   * ::HW_SHADING_CORNER_NORMALS (the default), ::HW_SHADING_FLAT, ::HW_SHADING_SMOOTH or
   * ::HW_SHADING_CREASE.
   */
  hw_shading shading;
  /**
   * Weighting of smooth shading (also where ::HW_SHADING_CORNER_NORMALS has no normal) and of
   * the vertex-normal glyphs (::HW_NORMAL_WEIGHTING_UNIFORM, ::HW_NORMAL_WEIGHTING_AREA,
   * ::HW_NORMAL_WEIGHTING_ANGLE).
   */
  hw_normal_weighting weighting;
  /**
   * For ::HW_SHADING_CREASE: the dihedral angle in radians (≥ 0) above which an edge is sharp.
   */
  double crease_angle;
  /**
   * `true`: one ::HW_RENDER_FLOATS_INTERLEAVED array (x y z nx ny nz [u v] per vertex); `false`:
   * separate ::HW_RENDER_FLOATS_POSITIONS, ::HW_RENDER_FLOATS_NORMALS and ::HW_RENDER_FLOATS_UVS
   * arrays.
   */
  bool interleaved;
  /**
   * Length of the normal glyphs; 0 takes the mesh's mean edge length.
   */
  double normal_length;
  /**
   * With ::HW_SHADING_CORNER_NORMALS: use the mesh's own corner normals (a file's `vn`,
   * hw_mesh_corner_normals_set()) when it has them and `corner_normals` is NULL. The other
   * shadings ignore them.
   */
  bool mesh_corner_normals;
  /**
   * Give the vertices the mesh's own corner texture coordinates, when it has them and
   * `corner_uvs` is NULL (a mesh read from an OBJ has (0, 0) at the corners its file gives
   * none).
   */
  bool mesh_corner_uvs;
  /**
   * NULL, or `3 * n_corners` doubles: a normal per half-edge slot (the corner at the
   * half-edge's origin), used by ::HW_SHADING_CORNER_NORMALS instead of the mesh's own; a
   * zero vector means the corner has none. The other shadings ignore it.
   */
  const double *corner_normals;
  /**
   * NULL, or `2 * n_corners` doubles: a texture coordinate per half-edge slot; the vertices
   * then carry uvs, as given.
   */
  const double *corner_uvs;
  /**
   * Half-edge slots in `corner_normals` and `corner_uvs`: must be
   * `hw_mesh_n_halfedge_slots(mesh)` when either is given.
   */
  size_t n_corners;
} hw_render_options;

/**
 * The `float` arrays of a render-buffer object (see hw_render_buffers_floats()). Lengths are in
 * floats.
 * \ingroup render
 */
typedef uint32_t hw_render_floats;

/**
 * x y z per vertex (separate layout; empty when interleaved).
 * \ingroup render
 */
#define HW_RENDER_FLOATS_POSITIONS 0

/**
 * Unit nx ny nz per vertex (separate layout; empty when interleaved).
 * \ingroup render
 */
#define HW_RENDER_FLOATS_NORMALS 1

/**
 * u v per vertex (separate layout with corner uvs; empty otherwise).
 * \ingroup render
 */
#define HW_RENDER_FLOATS_UVS 2

/**
 * hw_render_buffers_stride() floats per vertex: x y z nx ny nz [u v] (interleaved layout).
 * \ingroup render
 */
#define HW_RENDER_FLOATS_INTERLEAVED 3

/**
 * `GL_LINES` points, x y z, two per segment: every edge (a polygon list: every polygon side).
 * \ingroup render
 */
#define HW_RENDER_FLOATS_WIREFRAME 4

/**
 * `GL_LINES` points of the boundary edges (edges with a face on one side only).
 * \ingroup render
 */
#define HW_RENDER_FLOATS_BOUNDARY 5

/**
 * `GL_LINES` points of the non-manifold edges reported by the diagnostic given to the build.
 * \ingroup render
 */
#define HW_RENDER_FLOATS_NON_MANIFOLD 6

/**
 * `GL_LINES` glyphs of the vertex normals, from each vertex along its normal.
 * \ingroup render
 */
#define HW_RENDER_FLOATS_VERTEX_NORMALS 7

/**
 * `GL_LINES` glyphs of the face normals, from each face's centroid.
 * \ingroup render
 */
#define HW_RENDER_FLOATS_FACE_NORMALS 8

/**
 * `GL_POINTS` points, x y z: the vertices a doctor's finding names
 * (hw_render_buffers_from_finding(); empty otherwise).
 * \ingroup render
 */
#define HW_RENDER_FLOATS_POINTS 9

/**
 * The `uint32_t` arrays of a render-buffer object (see hw_render_buffers_indices()).
 * \ingroup render
 */
typedef uint32_t hw_render_indices;

/**
 * Three vertex indices per triangle, counter-clockwise from outside: the element buffer.
 * \ingroup render
 */
#define HW_RENDER_INDICES_TRIANGLES 0

/**
 * Per triangle, the mesh face (or polygon) it comes from.
 * \ingroup render
 */
#define HW_RENDER_INDICES_TRIANGLE_FACES 1

/**
 * Per vertex, the mesh vertex (or polygon) it shows.
 * \ingroup render
 */
#define HW_RENDER_INDICES_VERTEX_SOURCES 2

/**
 * Per ::HW_RENDER_FLOATS_WIREFRAME segment, its edge id (or polygon).
 * \ingroup render
 */
#define HW_RENDER_INDICES_WIREFRAME_SOURCES 3

/**
 * Per ::HW_RENDER_FLOATS_BOUNDARY segment, its edge id.
 * \ingroup render
 */
#define HW_RENDER_INDICES_BOUNDARY_SOURCES 4

/**
 * Per ::HW_RENDER_FLOATS_POINTS point, the item of the finding it shows.
 * \ingroup render
 */
#define HW_RENDER_INDICES_POINT_SOURCES 5

/**
 * The default options: ::HW_SHADING_CORNER_NORMALS (the mesh's own corner normals where it has
 * them, smooth angle-weighted normals elsewhere), a crease angle of 30°, separate arrays,
 * glyphs as long as the mean edge; the mesh's own corner uvs when it has them, no other
 * per-corner attributes.
 * \ingroup render
 */
hw_render_options hw_render_options_default(void);

/**
 * Builds the render buffers of a mesh: the triangulated surface (every polygon, non-convex ones
 * included, in O(n log n) for n corners), its vertex attributes as `float`, the wireframe, the
 * boundary, the non-manifold edges of `diagnostic` and the normal glyphs.
 *
 * `diagnostic` may be NULL (no non-manifold edges then); when given it must be the one the
 * mesh's build returned (load with ::HW_BUILD_POLICY_REPAIR or ::HW_BUILD_POLICY_SKIP to see the
 * non-manifold edges of a file). `options` may be NULL for hw_render_options_default(). Bad
 * options (an unknown shading or weighting, a negative or non-finite crease angle or glyph length,
 * corner arrays of the wrong size) give `HW_ERR_INVALID_INPUT`.
 *
 * Draw the surface with `glDrawElements(GL_TRIANGLES, n, GL_UNSIGNED_INT, 0)` after uploading
 * ::HW_RENDER_INDICES_TRIANGLES as the element buffer, and each line set with
 * `glDrawArrays(GL_LINES, 0, len / 3)`.
 *
 * # Safety
 * `mesh` must be NULL or live; `diagnostic` NULL or live; `options` NULL or readable, with its
 * corner arrays NULL or as long as it says; `out_buffers` writable.
 * \ingroup render
 */
hw_status hw_render_buffers_build(const hw_mesh *mesh,
                                  const hw_diagnostic *diagnostic,
                                  const hw_render_options *options,
                                  hw_render_buffers **out_buffers);

/**
 * Builds fill and outline buffers of a list of polygons — Voronoi cells, regions, any polygons:
 * ::HW_RENDER_FLOATS_POSITIONS and ::HW_RENDER_FLOATS_NORMALS (each polygon's own corners, so
 * polygons can be coloured apart; normals are the polygons' unit normals, +z for counter-clockwise
 * 2D input), ::HW_RENDER_INDICES_TRIANGLES (every polygon triangulated) with
 * ::HW_RENDER_INDICES_TRIANGLE_FACES and ::HW_RENDER_INDICES_VERTEX_SOURCES naming polygons, and
 * the outlines as ::HW_RENDER_FLOATS_WIREFRAME. The other arrays are empty, and the layout is
 * always separate.
 *
 * `corners` holds `dimension * n_corners` doubles (`dimension` 2: x y in the plane z = 0;
 * 3: x y z), polygon after polygon; polygon `i` has `sizes[i]` corners, and the sizes must add
 * up to `n_corners`. A polygon of fewer than 3 corners or a NaN or infinite coordinate is
 * refused too; each of these gives `HW_ERR_INVALID_INPUT` with a message naming the polygon
 * (and the corner within it).
 *
 * # Safety
 * `corners` must hold `dimension * n_corners` doubles and `sizes` `n_polygons` values (either
 * may be NULL when its count is 0); `out_buffers` writable.
 * \ingroup render
 */
hw_status hw_render_buffers_from_polygons(const double *corners,
                                          uint32_t dimension,
                                          size_t n_corners,
                                          const uint32_t *sizes,
                                          size_t n_polygons,
                                          hw_render_buffers **out_buffers);

/**
 * Builds fill and outline buffers of the clipped cells of a Voronoi diagram, as
 * hw_render_buffers_from_polygons() would from its cells: polygon `i` is the cell of site `i`,
 * so ::HW_RENDER_INDICES_TRIANGLE_FACES, ::HW_RENDER_INDICES_VERTEX_SOURCES and
 * ::HW_RENDER_INDICES_WIREFRAME_SOURCES name sites (colour a cell by its site). Each cell gets its
 * own copies of its corners (z = 0, normals +z); an empty cell (a duplicate site, or a cell
 * outside the clip region) has no triangle and no outline. The buffers do not depend on `cells`
 * afterwards.
 *
 * # Safety
 * `cells` must be NULL or a live `hw_voronoi_cells`; `out_buffers` writable.
 * \ingroup render
 */
hw_status hw_render_buffers_from_voronoi_cells(const hw_voronoi_cells *cells,
                                               hw_render_buffers **out_buffers);

/**
 * Builds the buffers that draw one kind of finding of a doctor's report over the face list it
 * examined (the same arrays as given to hw_doctor_examine_indexed()):
 * - the faces it names, each once with its own corners, as ::HW_RENDER_FLOATS_POSITIONS,
 *   ::HW_RENDER_FLOATS_NORMALS and ::HW_RENDER_INDICES_TRIANGLES, outlined by
 *   ::HW_RENDER_FLOATS_WIREFRAME; ::HW_RENDER_INDICES_TRIANGLE_FACES,
 *   ::HW_RENDER_INDICES_VERTEX_SOURCES and ::HW_RENDER_INDICES_WIREFRAME_SOURCES name faces of the
 *   list;
 * - the edges it names, and the 12 edges of the bounding box of each small component, as
 *   ::HW_RENDER_FLOATS_BOUNDARY segments, whose ::HW_RENDER_INDICES_BOUNDARY_SOURCES are item
 *   indices of the finding;
 * - the vertices it names as ::HW_RENDER_FLOATS_POINTS, with ::HW_RENDER_INDICES_POINT_SOURCES
 *   (items).
 *
 * What each kind names: faces for the orientation witness, needles, caps, duplicate faces and
 * intersecting face pairs; the edge and its two faces for folded edges; the edge for long
 * edges; the vertex for zero-length edges; the vertex and an edge to the vertex it repeats for
 * duplicate positions and near duplicates; the vertex and the edge it lies on for T-vertices.
 * Faces, edges and vertices on NaN or infinite positions cannot be drawn and are left out.
 * `HW_ERR_INVALID_INPUT` for an unknown kind, a report that names a face or vertex the list
 * does not have (it is another list's report) or sizes that do not add up to `n_indices`.
 *
 * # Safety
 * `report` must be NULL or live; the arrays as for hw_mesh_from_indexed(); `out_buffers`
 * writable.
 * \ingroup render
 */
hw_status hw_render_buffers_from_finding(const hw_doctor_report *report,
                                         hw_doctor_finding kind,
                                         const double *positions,
                                         size_t n_vertices,
                                         const uint32_t *face_sizes,
                                         size_t n_faces,
                                         const uint32_t *indices,
                                         size_t n_indices,
                                         hw_render_buffers **out_buffers);

/**
 * Releases render buffers (their views die with them). NULL is a no-op; a second free is
 * refused (within the limits the ownership conventions at the top of the header state).
 *
 * # Safety
 * `buffers` must be NULL or from this library, not in use by another thread.
 * \ingroup render
 */
void hw_render_buffers_free(hw_render_buffers *buffers);

/**
 * A zero-copy view of one `float` array: `*out_data` (NULL when empty) and its length in floats
 * `*out_len`, ready for `glBufferData(GL_ARRAY_BUFFER, *out_len * sizeof(float), *out_data, ...)`.
 *
 * # Safety
 * `buffers` must be NULL or live; `out_data` and `out_len` writable.
 * \ingroup render
 */
hw_status hw_render_buffers_floats(const hw_render_buffers *buffers,
                                   hw_render_floats which,
                                   const float **out_data,
                                   size_t *out_len);

/**
 * A zero-copy view of one `uint32_t` array: `*out_data` (NULL when empty) and its length
 * `*out_len` in elements (three per triangle for ::HW_RENDER_INDICES_TRIANGLES).
 *
 * # Safety
 * `buffers` must be NULL or live; `out_data` and `out_len` writable.
 * \ingroup render
 */
hw_status hw_render_buffers_indices(const hw_render_buffers *buffers,
                                    hw_render_indices which,
                                    const uint32_t **out_data,
                                    size_t *out_len);

/**
 * Number of render vertices (entries of the per-vertex arrays); 0 for NULL.
 *
 * # Safety
 * `buffers` must be NULL or live.
 * \ingroup render
 */
size_t hw_render_buffers_n_vertices(const hw_render_buffers *buffers);

/**
 * Floats per vertex of ::HW_RENDER_FLOATS_INTERLEAVED (6: x y z nx ny nz; 8 with uvs), 0 when the
 * arrays are separate; 0 for NULL. The byte stride of `glVertexAttribPointer` is this times
 * `sizeof(float)`; normals start at float 3 and uvs at float 6.
 *
 * # Safety
 * `buffers` must be NULL or live.
 * \ingroup render
 */
size_t hw_render_buffers_stride(const hw_render_buffers *buffers);

/**
 * The box around the vertices, to frame a camera: `out_min` and `out_max` receive x y z each.
 * With no vertex, min is +infinity and max -infinity. Both outputs are required: NULL for
 * either gives `HW_ERR_NULL_ARGUMENT` and writes neither.
 *
 * # Safety
 * `buffers` must be NULL or live; `out_min` and `out_max` must each point to 3 writable floats.
 * \ingroup render
 */
hw_status hw_render_buffers_bounds(const hw_render_buffers *buffers,
                                   float *out_min,
                                   float *out_max);

#ifdef __cplusplus
}  // extern "C"
#endif  // __cplusplus

#endif  /* HALFWING_H */

#include "halfwing_nav.h"
