// halfwing.hpp — header-only C++17 wrapper over the halfwing C API (include/halfwing.h).
//
// Owning classes are move-only and free their object in the destructor; failures throw
// hw::error, which carries the hw_status and the library's message.
//
// One vocabulary with C: every function of halfwing.h has a counterpart here with the C name
// minus the `hw_` and kernel prefix the class gives (hw_mesh_split_face() is
// hw::mesh::split_face(), hw_winged_set_vertex_position() is hw::winged::set_vertex_position()), the same
// argument order and the same defaults (C's `*_default()` option structs); outputs become return
// values. c_tests/every_function_wrapped.cmake checks it and lists the few exceptions.
//
// Element ids stay the C structs (hw_vertex, hw_halfedge, hw_edge, hw_face; hw_wvertex, hw_wedge,
// hw_wface for the winged-edge kernel; hw_site, hw_voronoi_vertex, hw_voronoi_halfedge for the
// Voronoi diagram), with `==`, `!=`, `<` and std::hash defined below so they work as keys of
// std::map, std::set and the unordered containers. Whole index arrays (views, label images,
// Delaunay triangles) stay plain `uint32_t`, as in C.
//
// Enumerations: every C enumeration has a scoped C++ counterpart with the same values
// (hw_normal_weighting is hw::NormalWeighting, HW_NORMAL_WEIGHTING_ANGLE is
// hw::NormalWeighting::Angle), and the wrapper's functions take and return only these. The C
// types are all plain `uint32_t`, so C++ could not overload on them or stop a value of one family
// from reaching a function of another; the enum classes can (an hw::DiagnosticList passed where
// an hw::DoctorFinding is wanted does not compile), and one spelling per call keeps the wrapper
// single. Crossing over is explicit: hw::to_c(hw::Shading::Flat) is HW_SHADING_FLAT (for the C
// option structs, which stay C), static_cast<hw::Shading>(HW_SHADING_FLAT) the other way.
// hw::name() gives the name of the values that have one in C (statuses, diagnostic lists,
// doctor findings).
#ifndef HALFWING_HPP
#define HALFWING_HPP

#include "halfwing.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <iterator>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

/// Defines `==`, `!=`, `<` (by index) and std::hash for a C element id. In the global namespace,
/// the ids' own, so that argument-dependent lookup finds them.
#define HALFWING_ID_OPERATORS(Id)                                                              \
  /** Same element: same index. */                                                              \
  inline bool operator==(Id a, Id b) noexcept { return a.idx == b.idx; }                      \
  /** Different elements. */                                                                    \
  inline bool operator!=(Id a, Id b) noexcept { return a.idx != b.idx; }                      \
  /** Index order (the order of hw_mesh_visit()). */                                            \
  inline bool operator<(Id a, Id b) noexcept { return a.idx < b.idx; }                        \
  namespace std {                                                                               \
  /** Hashes the index. */                                                                      \
  template <>                                                                                   \
  struct hash<Id> {                                                                             \
    /** The hash of the index. */                                                               \
    std::size_t operator()(Id id) const noexcept { return std::hash<uint32_t>()(id.idx); }      \
  };                                                                                            \
  }

HALFWING_ID_OPERATORS(hw_vertex)
HALFWING_ID_OPERATORS(hw_halfedge)
HALFWING_ID_OPERATORS(hw_edge)
HALFWING_ID_OPERATORS(hw_face)
HALFWING_ID_OPERATORS(hw_wvertex)
HALFWING_ID_OPERATORS(hw_wedge)
HALFWING_ID_OPERATORS(hw_wface)
HALFWING_ID_OPERATORS(hw_site)
HALFWING_ID_OPERATORS(hw_voronoi_vertex)
HALFWING_ID_OPERATORS(hw_voronoi_halfedge)
#undef HALFWING_ID_OPERATORS

/// The C++ wrapper: owning classes that throw hw::error, range-for walks, and a scoped
/// enumeration for each C one.
namespace hw {

/// ::hw_status, scoped: each value is the C constant it names.
enum class Status : uint32_t {
  Ok = HW_OK,                                ///< ::HW_OK
  NullArgument = HW_ERR_NULL_ARGUMENT,       ///< ::HW_ERR_NULL_ARGUMENT
  InvalidHandle = HW_ERR_INVALID_HANDLE,     ///< ::HW_ERR_INVALID_HANDLE
  InvalidInput = HW_ERR_INVALID_INPUT,       ///< ::HW_ERR_INVALID_INPUT
  NonManifold = HW_ERR_NON_MANIFOLD,         ///< ::HW_ERR_NON_MANIFOLD
  BufferTooSmall = HW_ERR_BUFFER_TOO_SMALL,  ///< ::HW_ERR_BUFFER_TOO_SMALL
  Io = HW_ERR_IO,                            ///< ::HW_ERR_IO
  Parse = HW_ERR_PARSE,                      ///< ::HW_ERR_PARSE
  Refused = HW_ERR_REFUSED,                  ///< ::HW_ERR_REFUSED
  Panic = HW_ERR_PANIC,                      ///< ::HW_ERR_PANIC
  NotFound = HW_ERR_NOT_FOUND,               ///< ::HW_ERR_NOT_FOUND
  OutOfMemory = HW_ERR_OUT_OF_MEMORY,        ///< ::HW_ERR_OUT_OF_MEMORY
};
/// ::hw_element_kind, scoped: each value is the C constant it names.
enum class ElementKind : uint32_t {
  Vertex = HW_ELEMENT_KIND_VERTEX,      ///< ::HW_ELEMENT_KIND_VERTEX
  Halfedge = HW_ELEMENT_KIND_HALFEDGE,  ///< ::HW_ELEMENT_KIND_HALFEDGE
  Edge = HW_ELEMENT_KIND_EDGE,          ///< ::HW_ELEMENT_KIND_EDGE
  Face = HW_ELEMENT_KIND_FACE,          ///< ::HW_ELEMENT_KIND_FACE
};
/// ::hw_scalar_type, scoped: each value is the C constant it names.
enum class ScalarType : uint32_t {
  F64 = HW_SCALAR_TYPE_F64,  ///< ::HW_SCALAR_TYPE_F64
  F32 = HW_SCALAR_TYPE_F32,  ///< ::HW_SCALAR_TYPE_F32
  I32 = HW_SCALAR_TYPE_I32,  ///< ::HW_SCALAR_TYPE_I32
  U32 = HW_SCALAR_TYPE_U32,  ///< ::HW_SCALAR_TYPE_U32
};
/// ::hw_build_policy, scoped: each value is the C constant it names.
enum class BuildPolicy : uint32_t {
  Strict = HW_BUILD_POLICY_STRICT,  ///< ::HW_BUILD_POLICY_STRICT
  Skip = HW_BUILD_POLICY_SKIP,      ///< ::HW_BUILD_POLICY_SKIP
  Repair = HW_BUILD_POLICY_REPAIR,  ///< ::HW_BUILD_POLICY_REPAIR
};
/// ::hw_diagnostic_list, scoped: each value is the C constant it names.
enum class DiagnosticList : uint32_t {
  FacesTooSmall = HW_DIAGNOSTIC_LIST_FACES_TOO_SMALL,  ///< ::HW_DIAGNOSTIC_LIST_FACES_TOO_SMALL
  /// ::HW_DIAGNOSTIC_LIST_FACES_OUT_OF_RANGE
  FacesOutOfRange = HW_DIAGNOSTIC_LIST_FACES_OUT_OF_RANGE,
  /// ::HW_DIAGNOSTIC_LIST_FACES_REPEATED_VERTEX
  FacesRepeatedVertex = HW_DIAGNOSTIC_LIST_FACES_REPEATED_VERTEX,
  /// ::HW_DIAGNOSTIC_LIST_NON_FINITE_VERTICES
  NonFiniteVertices = HW_DIAGNOSTIC_LIST_NON_FINITE_VERTICES,
  /// ::HW_DIAGNOSTIC_LIST_NON_MANIFOLD_VERTICES
  NonManifoldVertices = HW_DIAGNOSTIC_LIST_NON_MANIFOLD_VERTICES,
  /// ::HW_DIAGNOSTIC_LIST_ISOLATED_VERTICES
  IsolatedVertices = HW_DIAGNOSTIC_LIST_ISOLATED_VERTICES,
  DegenerateFaces = HW_DIAGNOSTIC_LIST_DEGENERATE_FACES,  ///< ::HW_DIAGNOSTIC_LIST_DEGENERATE_FACES
  SkippedFaces = HW_DIAGNOSTIC_LIST_SKIPPED_FACES,        ///< ::HW_DIAGNOSTIC_LIST_SKIPPED_FACES
  VertexCopies = HW_DIAGNOSTIC_LIST_VERTEX_COPIES,        ///< ::HW_DIAGNOSTIC_LIST_VERTEX_COPIES
  ReorientedFaces = HW_DIAGNOSTIC_LIST_REORIENTED_FACES,  ///< ::HW_DIAGNOSTIC_LIST_REORIENTED_FACES
};
/// ::hw_diagnostic_edges, scoped: each value is the C constant it names.
enum class DiagnosticEdges : uint32_t {
  NonManifold = HW_DIAGNOSTIC_EDGES_NON_MANIFOLD,   ///< ::HW_DIAGNOSTIC_EDGES_NON_MANIFOLD
  Inconsistent = HW_DIAGNOSTIC_EDGES_INCONSISTENT,  ///< ::HW_DIAGNOSTIC_EDGES_INCONSISTENT
};
/// ::hw_circulator_kind, scoped: each value is the C constant it names.
enum class CirculatorKind : uint32_t {
  Halfedges = HW_CIRCULATOR_KIND_HALFEDGES,  ///< ::HW_CIRCULATOR_KIND_HALFEDGES
  Incoming = HW_CIRCULATOR_KIND_INCOMING,    ///< ::HW_CIRCULATOR_KIND_INCOMING
  Vertices = HW_CIRCULATOR_KIND_VERTICES,    ///< ::HW_CIRCULATOR_KIND_VERTICES
  Edges = HW_CIRCULATOR_KIND_EDGES,          ///< ::HW_CIRCULATOR_KIND_EDGES
  Faces = HW_CIRCULATOR_KIND_FACES,          ///< ::HW_CIRCULATOR_KIND_FACES
};
/// ::hw_mesh_array, scoped: each value is the C constant it names.
enum class MeshArray : uint32_t {
  HalfedgeOrigin = HW_MESH_ARRAY_HALFEDGE_ORIGIN,  ///< ::HW_MESH_ARRAY_HALFEDGE_ORIGIN
  HalfedgeNext = HW_MESH_ARRAY_HALFEDGE_NEXT,      ///< ::HW_MESH_ARRAY_HALFEDGE_NEXT
  HalfedgePrev = HW_MESH_ARRAY_HALFEDGE_PREV,      ///< ::HW_MESH_ARRAY_HALFEDGE_PREV
  HalfedgeFace = HW_MESH_ARRAY_HALFEDGE_FACE,      ///< ::HW_MESH_ARRAY_HALFEDGE_FACE
  VertexHalfedge = HW_MESH_ARRAY_VERTEX_HALFEDGE,  ///< ::HW_MESH_ARRAY_VERTEX_HALFEDGE
  FaceHalfedge = HW_MESH_ARRAY_FACE_HALFEDGE,      ///< ::HW_MESH_ARRAY_FACE_HALFEDGE
};
/// ::hw_normal_weighting, scoped: each value is the C constant it names.
enum class NormalWeighting : uint32_t {
  Uniform = HW_NORMAL_WEIGHTING_UNIFORM,  ///< ::HW_NORMAL_WEIGHTING_UNIFORM
  Area = HW_NORMAL_WEIGHTING_AREA,        ///< ::HW_NORMAL_WEIGHTING_AREA
  Angle = HW_NORMAL_WEIGHTING_ANGLE,      ///< ::HW_NORMAL_WEIGHTING_ANGLE
};
/// ::hw_doctor_finding, scoped: each value is the C constant it names.
enum class DoctorFinding : uint32_t {
  SmallComponents = HW_DOCTOR_FINDING_SMALL_COMPONENTS,  ///< ::HW_DOCTOR_FINDING_SMALL_COMPONENTS
  /// ::HW_DOCTOR_FINDING_NON_ORIENTABLE_WITNESS
  NonOrientableWitness = HW_DOCTOR_FINDING_NON_ORIENTABLE_WITNESS,
  ZeroLengthEdges = HW_DOCTOR_FINDING_ZERO_LENGTH_EDGES,  ///< ::HW_DOCTOR_FINDING_ZERO_LENGTH_EDGES
  Needles = HW_DOCTOR_FINDING_NEEDLES,                    ///< ::HW_DOCTOR_FINDING_NEEDLES
  Caps = HW_DOCTOR_FINDING_CAPS,                          ///< ::HW_DOCTOR_FINDING_CAPS
  FoldedEdges = HW_DOCTOR_FINDING_FOLDED_EDGES,           ///< ::HW_DOCTOR_FINDING_FOLDED_EDGES
  LongEdges = HW_DOCTOR_FINDING_LONG_EDGES,               ///< ::HW_DOCTOR_FINDING_LONG_EDGES
  /// ::HW_DOCTOR_FINDING_DUPLICATE_POSITIONS
  DuplicatePositions = HW_DOCTOR_FINDING_DUPLICATE_POSITIONS,
  /// ::HW_DOCTOR_FINDING_NEAR_DUPLICATE_VERTICES
  NearDuplicateVertices = HW_DOCTOR_FINDING_NEAR_DUPLICATE_VERTICES,
  DuplicateFaces = HW_DOCTOR_FINDING_DUPLICATE_FACES,  ///< ::HW_DOCTOR_FINDING_DUPLICATE_FACES
  TVertices = HW_DOCTOR_FINDING_T_VERTICES,            ///< ::HW_DOCTOR_FINDING_T_VERTICES
  /// ::HW_DOCTOR_FINDING_SELF_INTERSECTIONS
  SelfIntersections = HW_DOCTOR_FINDING_SELF_INTERSECTIONS,
};
/// ::hw_repair_list, scoped: each value is the C constant it names.
enum class RepairList : uint32_t {
  MergedVertices = HW_REPAIR_LIST_MERGED_VERTICES,        ///< ::HW_REPAIR_LIST_MERGED_VERTICES
  RemovedVertices = HW_REPAIR_LIST_REMOVED_VERTICES,      ///< ::HW_REPAIR_LIST_REMOVED_VERTICES
  RemovedFaces = HW_REPAIR_LIST_REMOVED_FACES,            ///< ::HW_REPAIR_LIST_REMOVED_FACES
  DuplicateFaces = HW_REPAIR_LIST_DUPLICATE_FACES,        ///< ::HW_REPAIR_LIST_DUPLICATE_FACES
  StitchedHalfedges = HW_REPAIR_LIST_STITCHED_HALFEDGES,  ///< ::HW_REPAIR_LIST_STITCHED_HALFEDGES
  VertexCopies = HW_REPAIR_LIST_VERTEX_COPIES,            ///< ::HW_REPAIR_LIST_VERTEX_COPIES
  ReorientedFaces = HW_REPAIR_LIST_REORIENTED_FACES,      ///< ::HW_REPAIR_LIST_REORIENTED_FACES
  FlippedFaces = HW_REPAIR_LIST_FLIPPED_FACES,            ///< ::HW_REPAIR_LIST_FLIPPED_FACES
};
/// ::hw_small_components, scoped: each value is the C constant it names.
enum class SmallComponents : uint32_t {
  ByFaceCount = HW_SMALL_COMPONENTS_BY_FACE_COUNT,  ///< ::HW_SMALL_COMPONENTS_BY_FACE_COUNT
  /// ::HW_SMALL_COMPONENTS_BY_RELATIVE_DIAMETER
  ByRelativeDiameter = HW_SMALL_COMPONENTS_BY_RELATIVE_DIAMETER,
};
/// ::hw_non_manifold_edges, scoped: each value is the C constant it names.
enum class NonManifoldEdges : uint32_t {
  Cut = HW_NON_MANIFOLD_EDGES_CUT,                   ///< ::HW_NON_MANIFOLD_EDGES_CUT
  RemoveFaces = HW_NON_MANIFOLD_EDGES_REMOVE_FACES,  ///< ::HW_NON_MANIFOLD_EDGES_REMOVE_FACES
};
/// ::hw_fate, scoped: each value is the C constant it names.
enum class Fate : uint32_t {
  Kept = HW_FATE_KEPT,                       ///< ::HW_FATE_KEPT
  Merged = HW_FATE_MERGED,                   ///< ::HW_FATE_MERGED
  Reversed = HW_FATE_REVERSED,               ///< ::HW_FATE_REVERSED
  Collapsed = HW_FATE_COLLAPSED,             ///< ::HW_FATE_COLLAPSED
  Duplicate = HW_FATE_DUPLICATE,             ///< ::HW_FATE_DUPLICATE
  Unbuildable = HW_FATE_UNBUILDABLE,         ///< ::HW_FATE_UNBUILDABLE
  SmallComponent = HW_FATE_SMALL_COMPONENT,  ///< ::HW_FATE_SMALL_COMPONENT
  Unreferenced = HW_FATE_UNREFERENCED,       ///< ::HW_FATE_UNREFERENCED
  Degenerate = HW_FATE_DEGENERATE,           ///< ::HW_FATE_DEGENERATE
};
/// ::hw_fates_list, scoped: each value is the C constant it names.
enum class FatesList : uint32_t {
  VertexKinds = HW_FATES_LIST_VERTEX_KINDS,      ///< ::HW_FATES_LIST_VERTEX_KINDS
  VertexIds = HW_FATES_LIST_VERTEX_IDS,          ///< ::HW_FATES_LIST_VERTEX_IDS
  FaceKinds = HW_FATES_LIST_FACE_KINDS,          ///< ::HW_FATES_LIST_FACE_KINDS
  FaceIds = HW_FATES_LIST_FACE_IDS,              ///< ::HW_FATES_LIST_FACE_IDS
  AddedVertices = HW_FATES_LIST_ADDED_VERTICES,  ///< ::HW_FATES_LIST_ADDED_VERTICES
  AddedFaces = HW_FATES_LIST_ADDED_FACES,        ///< ::HW_FATES_LIST_ADDED_FACES
};
/// ::hw_fill_mode, scoped: each value is the C constant it names.
enum class FillMode : uint32_t {
  Triangulate = HW_FILL_MODE_TRIANGULATE,  ///< ::HW_FILL_MODE_TRIANGULATE
  Refine = HW_FILL_MODE_REFINE,            ///< ::HW_FILL_MODE_REFINE
  Fair = HW_FILL_MODE_FAIR,                ///< ::HW_FILL_MODE_FAIR
};
/// ::hw_cell_faces, scoped: each value is the C constant it names.
enum class CellFaces : uint32_t {
  Quads = HW_CELL_FACES_QUADS,          ///< ::HW_CELL_FACES_QUADS
  Triangles = HW_CELL_FACES_TRIANGLES,  ///< ::HW_CELL_FACES_TRIANGLES
};
/// ::hw_caps, scoped: each value is the C constant it names.
enum class Caps : uint32_t {
  None = HW_CAPS_NONE,        ///< ::HW_CAPS_NONE
  Polygon = HW_CAPS_POLYGON,  ///< ::HW_CAPS_POLYGON
  Fan = HW_CAPS_FAN,          ///< ::HW_CAPS_FAN
};
/// ::hw_shading, scoped: each value is the C constant it names.
enum class Shading : uint32_t {
  Flat = HW_SHADING_FLAT,                     ///< ::HW_SHADING_FLAT
  Smooth = HW_SHADING_SMOOTH,                 ///< ::HW_SHADING_SMOOTH
  Crease = HW_SHADING_CREASE,                 ///< ::HW_SHADING_CREASE
  CornerNormals = HW_SHADING_CORNER_NORMALS,  ///< ::HW_SHADING_CORNER_NORMALS
};
/// ::hw_render_floats, scoped: each value is the C constant it names.
enum class RenderFloats : uint32_t {
  Positions = HW_RENDER_FLOATS_POSITIONS,           ///< ::HW_RENDER_FLOATS_POSITIONS
  Normals = HW_RENDER_FLOATS_NORMALS,               ///< ::HW_RENDER_FLOATS_NORMALS
  Uvs = HW_RENDER_FLOATS_UVS,                       ///< ::HW_RENDER_FLOATS_UVS
  Interleaved = HW_RENDER_FLOATS_INTERLEAVED,       ///< ::HW_RENDER_FLOATS_INTERLEAVED
  Wireframe = HW_RENDER_FLOATS_WIREFRAME,           ///< ::HW_RENDER_FLOATS_WIREFRAME
  Boundary = HW_RENDER_FLOATS_BOUNDARY,             ///< ::HW_RENDER_FLOATS_BOUNDARY
  NonManifold = HW_RENDER_FLOATS_NON_MANIFOLD,      ///< ::HW_RENDER_FLOATS_NON_MANIFOLD
  VertexNormals = HW_RENDER_FLOATS_VERTEX_NORMALS,  ///< ::HW_RENDER_FLOATS_VERTEX_NORMALS
  FaceNormals = HW_RENDER_FLOATS_FACE_NORMALS,      ///< ::HW_RENDER_FLOATS_FACE_NORMALS
  Points = HW_RENDER_FLOATS_POINTS,                 ///< ::HW_RENDER_FLOATS_POINTS
};
/// ::hw_render_indices, scoped: each value is the C constant it names.
enum class RenderIndices : uint32_t {
  Triangles = HW_RENDER_INDICES_TRIANGLES,           ///< ::HW_RENDER_INDICES_TRIANGLES
  TriangleFaces = HW_RENDER_INDICES_TRIANGLE_FACES,  ///< ::HW_RENDER_INDICES_TRIANGLE_FACES
  VertexSources = HW_RENDER_INDICES_VERTEX_SOURCES,  ///< ::HW_RENDER_INDICES_VERTEX_SOURCES
  /// ::HW_RENDER_INDICES_WIREFRAME_SOURCES
  WireframeSources = HW_RENDER_INDICES_WIREFRAME_SOURCES,
  BoundarySources = HW_RENDER_INDICES_BOUNDARY_SOURCES,  ///< ::HW_RENDER_INDICES_BOUNDARY_SOURCES
  PointSources = HW_RENDER_INDICES_POINT_SOURCES,        ///< ::HW_RENDER_INDICES_POINT_SOURCES
};
/// ::hw_wtable, scoped: each value is the C constant it names.
enum class WTable : uint32_t {
  Vertices = HW_WTABLE_VERTICES,  ///< ::HW_WTABLE_VERTICES
  Faces = HW_WTABLE_FACES,        ///< ::HW_WTABLE_FACES
  Edges = HW_WTABLE_EDGES,        ///< ::HW_WTABLE_EDGES
  All = HW_WTABLE_ALL,            ///< ::HW_WTABLE_ALL
};
/// ::hw_wnaming, scoped: each value is the C constant it names.
enum class WNaming : uint32_t {
  CwCcw = HW_WNAMING_CW_CCW,                  ///< ::HW_WNAMING_CW_CCW
  DirectInverse = HW_WNAMING_DIRECT_INVERSE,  ///< ::HW_WNAMING_DIRECT_INVERSE
  LeftRight = HW_WNAMING_LEFT_RIGHT,          ///< ::HW_WNAMING_LEFT_RIGHT
};
/// ::hw_table_format, scoped: each value is the C constant it names.
enum class TableFormat : uint32_t {
  Text = HW_TABLE_FORMAT_TEXT,          ///< ::HW_TABLE_FORMAT_TEXT
  Markdown = HW_TABLE_FORMAT_MARKDOWN,  ///< ::HW_TABLE_FORMAT_MARKDOWN
  Csv = HW_TABLE_FORMAT_CSV,            ///< ::HW_TABLE_FORMAT_CSV
};
/// ::hw_wcirculator_kind, scoped: each value is the C constant it names.
enum class WCirculatorKind : uint32_t {
  Edges = HW_WCIRCULATOR_KIND_EDGES,        ///< ::HW_WCIRCULATOR_KIND_EDGES
  Vertices = HW_WCIRCULATOR_KIND_VERTICES,  ///< ::HW_WCIRCULATOR_KIND_VERTICES
  Faces = HW_WCIRCULATOR_KIND_FACES,        ///< ::HW_WCIRCULATOR_KIND_FACES
};
/// ::hw_site_dimension, scoped: each value is the C constant it names.
enum class SiteDimension : uint32_t {
  Empty = HW_SITE_DIMENSION_EMPTY,  ///< ::HW_SITE_DIMENSION_EMPTY
  Point = HW_SITE_DIMENSION_POINT,  ///< ::HW_SITE_DIMENSION_POINT
  Line = HW_SITE_DIMENSION_LINE,    ///< ::HW_SITE_DIMENSION_LINE
  Plane = HW_SITE_DIMENSION_PLANE,  ///< ::HW_SITE_DIMENSION_PLANE
};
/// ::hw_voronoi_array, scoped: each value is the C constant it names.
enum class VoronoiArray : uint32_t {
  Representative = HW_VORONOI_ARRAY_REPRESENTATIVE,   ///< ::HW_VORONOI_ARRAY_REPRESENTATIVE
  Triangles = HW_VORONOI_ARRAY_TRIANGLES,             ///< ::HW_VORONOI_ARRAY_TRIANGLES
  TriangleTwins = HW_VORONOI_ARRAY_TRIANGLE_TWINS,    ///< ::HW_VORONOI_ARRAY_TRIANGLE_TWINS
  Hull = HW_VORONOI_ARRAY_HULL,                       ///< ::HW_VORONOI_ARRAY_HULL
  TriangleVertex = HW_VORONOI_ARRAY_TRIANGLE_VERTEX,  ///< ::HW_VORONOI_ARRAY_TRIANGLE_VERTEX
  HalfedgeOrigin = HW_VORONOI_ARRAY_HALFEDGE_ORIGIN,  ///< ::HW_VORONOI_ARRAY_HALFEDGE_ORIGIN
  HalfedgeNext = HW_VORONOI_ARRAY_HALFEDGE_NEXT,      ///< ::HW_VORONOI_ARRAY_HALFEDGE_NEXT
  HalfedgePrev = HW_VORONOI_ARRAY_HALFEDGE_PREV,      ///< ::HW_VORONOI_ARRAY_HALFEDGE_PREV
  HalfedgeSite = HW_VORONOI_ARRAY_HALFEDGE_SITE,      ///< ::HW_VORONOI_ARRAY_HALFEDGE_SITE
  CellHalfedge = HW_VORONOI_ARRAY_CELL_HALFEDGE,      ///< ::HW_VORONOI_ARRAY_CELL_HALFEDGE
  VertexHalfedge = HW_VORONOI_ARRAY_VERTEX_HALFEDGE,  ///< ::HW_VORONOI_ARRAY_VERTEX_HALFEDGE
};
/// ::hw_voronoi_edge_kind, scoped: each value is the C constant it names.
enum class VoronoiEdgeKind : uint32_t {
  Segment = HW_VORONOI_EDGE_KIND_SEGMENT,  ///< ::HW_VORONOI_EDGE_KIND_SEGMENT
  Ray = HW_VORONOI_EDGE_KIND_RAY,          ///< ::HW_VORONOI_EDGE_KIND_RAY
  Line = HW_VORONOI_EDGE_KIND_LINE,        ///< ::HW_VORONOI_EDGE_KIND_LINE
};
/// ::hw_metric, scoped: each value is the C constant it names.
enum class Metric : uint32_t {
  Euclidean = HW_METRIC_EUCLIDEAN,  ///< ::HW_METRIC_EUCLIDEAN
  Manhattan = HW_METRIC_MANHATTAN,  ///< ::HW_METRIC_MANHATTAN
  Chebyshev = HW_METRIC_CHEBYSHEV,  ///< ::HW_METRIC_CHEBYSHEV
};

/// The C value of a scoped enumeration value, for the C API and its option structs:
/// `hw::to_c(hw::Shading::Flat) == HW_SHADING_FLAT`.
template <class Enum, class = std::enable_if_t<std::is_enum_v<Enum>>>
constexpr std::underlying_type_t<Enum> to_c(Enum value) noexcept {
  return static_cast<std::underlying_type_t<Enum>>(value);
}

/// A failed halfwing call: the status code and the detailed message of the failure. Every
/// status is thrown as this class, HW_ERR_OUT_OF_MEMORY included (memory the library could not
/// get for an input's count, the size in the message): it leaves the library and the objects
/// passed in usable, unlike the std::bad_alloc of the wrapper's own containers.
class error : public std::runtime_error {
 public:
  /// An error with its status and message.
  error(Status status, const std::string& message) : std::runtime_error(message), status_(status) {}
  /// The status (never Status::Ok).
  Status status() const noexcept { return status_; }

 private:
  Status status_;
};

/// The message of the last failed call on this thread (empty if none failed).
inline std::string last_error_message() {
  std::size_t needed = 0;
  hw_last_error_message(nullptr, 0, &needed);
  std::string message(needed, '\0');
  if (hw_last_error_message(&message[0], message.size(), &needed) != HW_OK) return {};
  message.resize(needed - 1);
  return message;
}

/// Throws hw::error when `status` (a C status) is not HW_OK.
inline void check(hw_status status) {
  if (status != HW_OK) {
    std::string message = last_error_message();
    if (message.empty()) message = hw_status_str(status);
    throw error(static_cast<Status>(status), message);
  }
}

/// The version of the linked library, e.g. "0.2.0".
inline std::string version() { return hw_version_string(); }
/// The version of the linked library as one number (see hw_version_number()).
inline uint32_t version_number() { return hw_version_number(); }

/// Sets the number of threads the parallel operations use; 0 restores the default (see
/// hw_set_thread_count()).
inline void set_thread_count(std::size_t count) { check(hw_set_thread_count(count)); }

/// The description of a status ("null argument", ...); see hw_status_str().
inline std::string name(Status status) { return hw_status_str(to_c(status)); }
/// The name of a diagnostic id list ("isolated vertices", ...); see hw_diagnostic_list_name().
inline std::string name(DiagnosticList list) {
  const char* name = hw_diagnostic_list_name(to_c(list));
  if (!name)
    throw error(Status::InvalidInput, "unknown diagnostic list " + std::to_string(to_c(list)));
  return name;
}
/// The name of a diagnostic edge list; see hw_diagnostic_edges_name().
inline std::string name(DiagnosticEdges edges) {
  const char* name = hw_diagnostic_edges_name(to_c(edges));
  if (!name)
    throw error(Status::InvalidInput,
                "unknown diagnostic edge list " + std::to_string(to_c(edges)));
  return name;
}
/// The name of a doctor finding kind ("needles", ...); see hw_doctor_finding_name().
inline std::string name(DoctorFinding kind) {
  const char* name = hw_doctor_finding_name(to_c(kind));
  if (!name)
    throw error(Status::InvalidInput, "unknown doctor finding " + std::to_string(to_c(kind)));
  return name;
}

namespace detail {

/// A move-only owner of a C object released by `Free`.
template <class T, void (*Free)(T*)>
class owned {
 public:
  owned() noexcept = default;
  explicit owned(T* raw) noexcept : raw_(raw) {}
  owned(const owned&) = delete;
  owned& operator=(const owned&) = delete;
  owned(owned&& other) noexcept : raw_(std::exchange(other.raw_, nullptr)) {}
  owned& operator=(owned&& other) noexcept {
    if (this != &other) {
      Free(raw_);
      raw_ = std::exchange(other.raw_, nullptr);
    }
    return *this;
  }
  ~owned() { Free(raw_); }

  /// The C object, still owned by this wrapper.
  T* get() const noexcept { return raw_; }
  /// Gives up ownership: the caller must free the object.
  T* release() noexcept { return std::exchange(raw_, nullptr); }
  explicit operator bool() const noexcept { return raw_ != nullptr; }

 private:
  T* raw_ = nullptr;
};

/// The text of a copy-into-buffer call: `copy(out_text, capacity, &out_needed)` is asked for the
/// size, then for the text.
template <class Copy>
std::string copied_text(Copy copy) {
  std::size_t needed = 0;
  const hw_status sized = copy(nullptr, 0, &needed);
  // The size query answers HW_ERR_BUFFER_TOO_SMALL with the size; no size means another failure.
  if (needed == 0) {
    check(sized);
    return std::string();
  }
  std::string text(needed, '\0');
  check(copy(&text[0], text.size(), &needed));
  text.resize(needed - 1);
  return text;
}

/// The hw_scalar_type of each C++ type an attribute column can hold.
template <class T>
struct scalar_type;
template <>
struct scalar_type<double> : std::integral_constant<hw_scalar_type, HW_SCALAR_TYPE_F64> {};
template <>
struct scalar_type<float> : std::integral_constant<hw_scalar_type, HW_SCALAR_TYPE_F32> {};
template <>
struct scalar_type<int32_t> : std::integral_constant<hw_scalar_type, HW_SCALAR_TYPE_I32> {};
template <>
struct scalar_type<uint32_t> : std::integral_constant<hw_scalar_type, HW_SCALAR_TYPE_U32> {};

}  // namespace detail

/// A borrowed run of values inside a mesh (an attribute column: valid until the next call that
/// modifies the mesh) or a render-buffer object (valid while it lives). `T` is const for
/// read-only views.
template <class T>
class values_view {
 public:
  /// A view of `size` values at `data`.
  values_view(T* data, std::size_t size) noexcept : data_(data), size_(size) {}
  ///@{
  /// The standard container accessors over the viewed values (no bounds checks).
  T* begin() const noexcept { return data_; }
  T* end() const noexcept { return data_ + size_; }
  T& operator[](std::size_t i) const noexcept { return data_[i]; }
  T* data() const noexcept { return data_; }
  std::size_t size() const noexcept { return size_; }
  bool empty() const noexcept { return size_ == 0; }
  ///@}
  /// Bytes, for glBufferData.
  std::size_t size_bytes() const noexcept { return size_ * sizeof(T); }

 private:
  T* data_;
  std::size_t size_;
};


/// A range over a C circulator (of either kernel), for range-for loops:
/// `for (hw_vertex w : m.vertices_around(v))`. It borrows the mesh: do not modify the mesh while
/// iterating.
template <class Circulator, class Id, bool (*Next)(Circulator*, Id*)>
class circulation_of {
 public:
  /// A range over the walk `start` begins.
  explicit circulation_of(const Circulator& start) : start_(start) {}

  /// The range's input iterator: each increment is one step of the circulator.
  class iterator {
   public:
    ///@{
    /// The standard iterator types.
    using value_type = Id;
    using difference_type = std::ptrdiff_t;
    using iterator_category = std::input_iterator_tag;
    using pointer = const Id*;
    using reference = const Id&;
    ///@}
    iterator() = default;
    /// An iterator at the next element of circulator `c`.
    explicit iterator(const Circulator& c) : c_(c), live_(true) { ++*this; }
    ///@{
    /// The input iterator's operations; two iterators compare equal once both are past the end.
    const Id& operator*() const { return current_; }
    iterator& operator++() {
      live_ = live_ && Next(&c_, &current_);
      return *this;
    }
    void operator++(int) { ++*this; }
    bool operator==(const iterator& other) const { return live_ == other.live_ && !live_; }
    bool operator!=(const iterator& other) const { return !(*this == other); }
    ///@}

   private:
    Circulator c_{};
    Id current_{};
    bool live_ = false;
  };

  ///@{
  /// The range's ends, for range-for.
  iterator begin() const { return iterator(start_); }
  iterator end() const { return iterator(); }
  ///@}

 private:
  Circulator start_;
};

/// A range over an inline circulator of halfwing_nav.h (see circulation_of): every step is a few
/// array reads the compiler inlines.
template <class Id, bool (*Next)(hw_nav_circ*, Id*)>
using circulation = circulation_of<hw_nav_circ, Id, Next>;

/// Half-edges, by hw_nav_circ_next_halfedge().
using halfedge_circulation = circulation<hw_halfedge, hw_nav_circ_next_halfedge>;
/// Incoming half-edges of a vertex, by hw_nav_circ_next_incoming().
using incoming_circulation = circulation<hw_halfedge, hw_nav_circ_next_incoming>;
/// Vertices, by hw_nav_circ_next_vertex().
using vertex_circulation = circulation<hw_vertex, hw_nav_circ_next_vertex>;
/// Edges, by hw_nav_circ_next_edge().
using edge_circulation = circulation<hw_edge, hw_nav_circ_next_edge>;
/// Faces, by hw_nav_circ_next_face().
using face_circulation = circulation<hw_face, hw_nav_circ_next_face>;

/// The inline navigation of a mesh (hw_nav, see halfwing.h / halfwing_nav.h), from
/// hw::mesh::nav(): navigation and range-for walks that compile to array reads. Valid until the
/// next call that modifies the mesh. Ids are trusted, not checked: pass ids the mesh gave since
/// its last modification, and use hw::mesh's checked methods for any other. Orders, boundary
/// vertices and deleted elements as documented in halfwing_nav.h (the same orders as the checked
/// circulators).
class nav_view {
 public:
  /// The navigation view of `mesh` (throws hw::error for a NULL mesh).
  explicit nav_view(const hw_mesh* mesh) { check(hw_mesh_nav(mesh, &raw_)); }

  /// The C view, for the `hw_nav_*` functions.
  const hw_nav& raw() const noexcept { return raw_; }
  ///@{
  /// Slots of each kind, deleted ones included: valid ids are below these.
  std::size_t n_vertex_slots() const noexcept { return raw_.n_vertex_slots; }
  std::size_t n_halfedge_slots() const noexcept { return raw_.n_halfedge_slots; }
  std::size_t n_face_slots() const noexcept { return raw_.n_face_slots; }
  ///@}

  ///@{
  /// The step of the same name in halfwing_nav.h (hw_nav_origin(), hw_nav_vertex_halfedge(), hw_nav_vertex_is_deleted(), ...), over trusted ids.
  hw_vertex origin(hw_halfedge h) const noexcept { return hw_nav_origin(&raw_, h); }
  hw_vertex target(hw_halfedge h) const noexcept { return hw_nav_target(&raw_, h); }
  hw_halfedge twin(hw_halfedge h) const noexcept { return hw_nav_twin(&raw_, h); }
  hw_halfedge next(hw_halfedge h) const noexcept { return hw_nav_next(&raw_, h); }
  hw_halfedge prev(hw_halfedge h) const noexcept { return hw_nav_prev(&raw_, h); }
  hw_face face(hw_halfedge h) const noexcept { return hw_nav_face(&raw_, h); }
  hw_edge edge(hw_halfedge h) const noexcept { return hw_nav_edge(&raw_, h); }
  hw_halfedge halfedge(hw_vertex v) const noexcept { return hw_nav_vertex_halfedge(&raw_, v); }
  hw_halfedge halfedge(hw_face f) const noexcept { return hw_nav_face_halfedge(&raw_, f); }
  bool is_boundary(hw_halfedge h) const noexcept { return hw_nav_is_boundary(&raw_, h); }
  bool is_deleted(hw_vertex v) const noexcept { return hw_nav_vertex_is_deleted(&raw_, v); }
  bool is_deleted(hw_edge e) const noexcept { return hw_nav_edge_is_deleted(&raw_, e); }
  bool is_deleted(hw_face f) const noexcept { return hw_nav_face_is_deleted(&raw_, f); }
  ///@}

  ///@{
  /// A range-for walk around a vertex (outgoing or incoming half-edges, vertices, edges, faces) or a face (its half-edges, vertices, edges, the faces across its edges), in the orders of halfwing_nav.h.
  halfedge_circulation outgoing(hw_vertex v) const noexcept { return halfedge_circulation(hw_nav_around_vertex(&raw_, v)); }
  incoming_circulation incoming(hw_vertex v) const noexcept { return incoming_circulation(hw_nav_around_vertex(&raw_, v)); }
  vertex_circulation vertices_around(hw_vertex v) const noexcept { return vertex_circulation(hw_nav_around_vertex(&raw_, v)); }
  edge_circulation edges_around(hw_vertex v) const noexcept { return edge_circulation(hw_nav_around_vertex(&raw_, v)); }
  face_circulation faces_around(hw_vertex v) const noexcept { return face_circulation(hw_nav_around_vertex(&raw_, v)); }
  halfedge_circulation halfedges_of(hw_face f) const noexcept { return halfedge_circulation(hw_nav_around_face(&raw_, f)); }
  vertex_circulation vertices_of(hw_face f) const noexcept { return vertex_circulation(hw_nav_around_face(&raw_, f)); }
  edge_circulation edges_of(hw_face f) const noexcept { return edge_circulation(hw_nav_around_face(&raw_, f)); }
  face_circulation faces_across(hw_face f) const noexcept { return face_circulation(hw_nav_around_face(&raw_, f)); }
  ///@}
  /// The loop through `h` by next: a face's sides or a boundary loop.
  halfedge_circulation loop(hw_halfedge h) const noexcept { return halfedge_circulation(hw_nav_along_loop(&raw_, h)); }
  /// The outgoing half-edges around the origin of `h`, counter-clockwise from `h`.
  halfedge_circulation around_origin(hw_halfedge h) const noexcept { return halfedge_circulation(hw_nav_around_origin(&raw_, h)); }

 private:
  hw_nav raw_{};
};

/// What a build found wrong with its input (owns an hw_diagnostic).
class diagnostic {
 public:
  diagnostic() = default;
  /// Takes ownership of `raw`.
  explicit diagnostic(hw_diagnostic* raw) : raw_(raw) {}

  /// Analyses an indexed face list without building (see hw_diagnose_indexed()).
  static diagnostic of(const std::vector<double>& positions,
                       const std::vector<uint32_t>& face_sizes,
                       const std::vector<uint32_t>& indices) {
    hw_diagnostic* raw = nullptr;
    check(hw_diagnose_indexed(positions.data(), positions.size() / 3, face_sizes.data(),
                              face_sizes.size(), indices.data(), indices.size(), &raw));
    return diagnostic(raw);
  }

  /// True when nothing is wrong; an empty (default-constructed) diagnostic is clean.
  bool is_clean() const { return !raw_ || hw_diagnostic_is_clean(raw_.get()); }
  /// One id list (faces or vertices, per `list`); empty for an empty diagnostic.
  std::vector<uint32_t> ids(DiagnosticList list) const {
    if (!raw_) return {};
    const uint32_t* data = nullptr;
    std::size_t n = 0;
    check(hw_diagnostic_ids(raw_.get(), to_c(list), &data, &n));
    return std::vector<uint32_t>(data, data + n);
  }
  /// An edge of an edge list: its two input vertices (smaller first) and the input faces using
  /// it (ascending).
  struct edge_report {
    std::array<uint32_t, 2> vertices{};  ///< The two input vertices, smaller first.
    std::vector<uint32_t> faces;         ///< The input faces using the edge, ascending.
  };
  /// The number of edges in one edge list; 0 for an empty diagnostic.
  std::size_t count_edges(DiagnosticEdges edges) const {
    if (!raw_) return 0;
    std::size_t n = 0;
    check(hw_diagnostic_count_edges(raw_.get(), to_c(edges), &n));
    return n;
  }
  /// Edge `index` of an edge list (see hw_diagnostic_edge()).
  edge_report edge(DiagnosticEdges edges, std::size_t index) const {
    edge_report report;
    const uint32_t* faces = nullptr;
    std::size_t n_faces = 0;
    check(hw_diagnostic_edge(raw_.get(), to_c(edges), index, report.vertices.data(), &faces,
                             &n_faces));
    report.faces.assign(faces, faces + n_faces);
    return report;
  }
  /// The human-readable account; empty for an empty diagnostic.
  std::string summary() const {
    if (!raw_) return std::string();
    return detail::copied_text([this](char* out_text, std::size_t capacity,
                                      std::size_t* out_needed) {
      return hw_diagnostic_summary(raw_.get(), out_text, capacity, out_needed);
    });
  }
  ///@{
  /// The C object (still owned by this object), and whether there is one.
  hw_diagnostic* get() const noexcept { return raw_.get(); }
  explicit operator bool() const noexcept { return static_cast<bool>(raw_); }
  ///@}

 private:
  detail::owned<hw_diagnostic, hw_diagnostic_free> raw_;
};

/// The mesh doctor's findings on a face list or a mesh (see hw_doctor_examine_indexed()).
class doctor_report {
 public:
  /// One finding's elements: `n_items` items of `ids_per_item` ids each (see
  /// ::hw_doctor_finding), valid as long as the report.
  struct finding_view {
    /// The ids, `n_items * ids_per_item` of them.
    const uint32_t* ids = nullptr;
    /// The number of items.
    std::size_t n_items = 0;
    /// Ids per item.
    std::size_t ids_per_item = 1;
  };
  /// A boundary loop: its vertices in order, its perimeter, a face along it.
  struct boundary_loop {
    /// Its vertices in order.
    std::vector<uint32_t> vertices;
    /// Its length.
    double perimeter = 0;
    /// A face along it.
    uint32_t face = 0;
  };

  doctor_report() = default;
  /// Takes ownership of `raw`.
  explicit doctor_report(hw_doctor_report* raw) : raw_(raw) {}

  /// Examines an indexed face list (see hw_doctor_examine_indexed()).
  static doctor_report of(const std::vector<double>& positions,
                          const std::vector<uint32_t>& face_sizes,
                          const std::vector<uint32_t>& indices,
                          const hw_doctor_options& options = hw_doctor_options_default()) {
    if (positions.size() % 3 != 0)
      throw error(Status::InvalidInput, "positions: size is not a multiple of 3 (x, y, z)");
    hw_doctor_report* raw = nullptr;
    check(hw_doctor_examine_indexed(positions.data(), positions.size() / 3, face_sizes.data(),
                                    face_sizes.size(), indices.data(), indices.size(), &options,
                                    &raw));
    return doctor_report(raw);
  }

  /// The verdicts (see hw_doctor_report_verdict()).
  hw_doctor_verdict verdict() const {
    hw_doctor_verdict verdict{};
    check(hw_doctor_report_verdict(raw_.get(), &verdict));
    return verdict;
  }
  /// One finding's elements (see hw_doctor_report_finding()).
  finding_view finding(DoctorFinding kind) const {
    finding_view view;
    check(hw_doctor_report_finding(raw_.get(), to_c(kind), &view.ids, &view.n_items,
                                   &view.ids_per_item));
    return view;
  }
  /// Every connected component.
  std::vector<hw_doctor_component> components() const {
    const std::size_t n = hw_doctor_report_n_components(raw_.get());
    std::vector<hw_doctor_component> components(n);
    for (std::size_t i = 0; i < n; ++i)
      check(hw_doctor_report_component(raw_.get(), i, &components[i]));
    return components;
  }
  /// Every boundary loop.
  std::vector<boundary_loop> boundary_loops() const {
    const std::size_t n = hw_doctor_report_n_boundary_loops(raw_.get());
    std::vector<boundary_loop> loops(n);
    for (std::size_t i = 0; i < n; ++i) {
      const uint32_t* vertices = nullptr;
      std::size_t n_vertices = 0;
      check(hw_doctor_report_boundary_loop(raw_.get(), i, &vertices, &n_vertices,
                                           &loops[i].perimeter, &loops[i].face));
      loops[i].vertices.assign(vertices, vertices + n_vertices);
    }
    return loops;
  }
  /// One fan of a non-manifold vertex: the vertex, its number of fans and the fan's faces.
  struct vertex_fan_view {
    uint32_t vertex = 0;          ///< The non-manifold vertex.
    std::size_t n_fans = 0;       ///< Its number of fans.
    std::vector<uint32_t> faces;  ///< The faces of this fan, ascending.
  };
  /// The number of non-manifold vertices whose fans the report lists.
  std::size_t n_vertex_fans() const { return hw_doctor_report_n_vertex_fans(raw_.get()); }
  /// Fan `fan` of non-manifold vertex `index` (see hw_doctor_report_vertex_fan()).
  vertex_fan_view vertex_fan(std::size_t index, std::size_t fan) const {
    vertex_fan_view view;
    const uint32_t* faces = nullptr;
    std::size_t n_faces = 0;
    check(hw_doctor_report_vertex_fan(raw_.get(), index, fan, &view.vertex, &view.n_fans, &faces,
                                      &n_faces));
    view.faces.assign(faces, faces + n_faces);
    return view;
  }
  /// The input's diagnostic, owned by the report.
  const hw_diagnostic* input_diagnostic() const { return hw_doctor_report_diagnostic(raw_.get()); }
  /// The report as text.
  std::string text() const {
    return detail::copied_text([this](char* out_text, std::size_t capacity,
                                      std::size_t* out_needed) {
      return hw_doctor_report_text(raw_.get(), out_text, capacity, out_needed);
    });
  }
  /// The report as JSON.
  std::string json() const {
    return detail::copied_text([this](char* out_text, std::size_t capacity,
                                      std::size_t* out_needed) {
      return hw_doctor_report_json(raw_.get(), out_text, capacity, out_needed);
    });
  }
  ///@{
  /// The C object (still owned by this object), and whether there is one.
  hw_doctor_report* get() const noexcept { return raw_.get(); }
  explicit operator bool() const noexcept { return static_cast<bool>(raw_); }
  ///@}

 private:
  detail::owned<hw_doctor_report, hw_doctor_report_free> raw_;
};

/// The pairs of faces of an indexed face list that intersect other than along the vertices and
/// edges they share, sorted, smaller face first; (f, f) for a degenerate face f (see
/// hw_self_intersections_indexed()).
inline std::vector<std::array<uint32_t, 2>> self_intersections(
    const std::vector<double>& positions, const std::vector<uint32_t>& face_sizes,
    const std::vector<uint32_t>& indices) {
  if (positions.size() % 3 != 0)
    throw error(Status::InvalidInput, "positions: size is not a multiple of 3 (x, y, z)");
  hw_face_pairs* raw = nullptr;
  check(hw_self_intersections_indexed(positions.data(), positions.size() / 3, face_sizes.data(),
                                      face_sizes.size(), indices.data(), indices.size(), &raw));
  const detail::owned<hw_face_pairs, hw_face_pairs_free> pairs(raw);
  const uint32_t* ids = nullptr;
  std::size_t n = 0;
  check(hw_face_pairs_view(pairs.get(), &ids, &n));
  std::vector<std::array<uint32_t, 2>> found(n);
  for (std::size_t i = 0; i < n; ++i) found[i] = {ids[2 * i], ids[2 * i + 1]};
  return found;
}

/// The old-to-new id maps of a compaction (owns an hw_index_maps; see
/// hw_mesh_garbage_collect()).
class index_maps {
 public:
  /// No maps.
  index_maps() = default;
  /// Takes ownership of maps a C call gave.
  explicit index_maps(hw_index_maps* raw) : raw_(raw) {}
  /// The old-to-new map of one element kind (HW_INVALID_INDEX for removed elements), valid as
  /// long as the maps.
  values_view<const uint32_t> view(ElementKind kind) const {
    const uint32_t* ids = nullptr;
    std::size_t n = 0;
    check(hw_index_maps_view(raw_.get(), to_c(kind), &ids, &n));
    return values_view<const uint32_t>(ids, n);
  }
  /// The C object, still owned by these maps.
  hw_index_maps* get() const noexcept { return raw_.get(); }

 private:
  detail::owned<hw_index_maps, hw_index_maps_free> raw_;
};

/// What a repair changed (owns an hw_repair_report; see hw_soup_merge_vertices()).
class repair_report {
 public:
  repair_report() = default;
  /// Takes ownership of `raw`.
  explicit repair_report(hw_repair_report* raw) : raw_(raw) {}

  /// One list (pair lists hold 2 ids per pair; see ::hw_repair_list).
  std::vector<uint32_t> list(RepairList which) const {
    const uint32_t* ids = nullptr;
    std::size_t n = 0;
    check(hw_repair_report_list(raw_.get(), to_c(which), &ids, &n));
    return std::vector<uint32_t>(ids, ids + n);
  }
  /// The old-to-new map of one element kind (HW_INVALID_INDEX for removed elements).
  std::vector<uint32_t> map(ElementKind kind) const {
    const hw_index_maps* maps = nullptr;
    check(hw_repair_report_maps(raw_.get(), &maps, nullptr));
    const uint32_t* ids = nullptr;
    std::size_t n = 0;
    check(hw_index_maps_view(maps, to_c(kind), &ids, &n));
    return std::vector<uint32_t>(ids, ids + n);
  }
  /// Corners dropped from kept faces.
  std::size_t removed_corners() const {
    const hw_index_maps* maps = nullptr;
    std::size_t n = 0;
    check(hw_repair_report_maps(raw_.get(), &maps, &n));
    return n;
  }
  ///@{
  /// The C object (still owned by this object), and whether there is one.
  hw_repair_report* get() const noexcept { return raw_.get(); }
  explicit operator bool() const noexcept { return static_cast<bool>(raw_); }
  ///@}

 private:
  detail::owned<hw_repair_report, hw_repair_report_free> raw_;
};

/// What hw::repair_mesh() did to every input element (owns an hw_repair_fates).
class repair_fates {
 public:
  /// An empty object (owns nothing).
  repair_fates() = default;
  /// Takes ownership of `raw` (from hw_repair_mesh()).
  explicit repair_fates(hw_repair_fates* raw) : raw_(raw) {}

  /// One list (see ::hw_fates_list): fates (::hw_fate) and ids of the input vertices and
  /// faces, the added vertices' pairs, or the added faces.
  std::vector<uint32_t> list(FatesList which) const {
    const uint32_t* ids = nullptr;
    std::size_t n = 0;
    check(hw_repair_fates_list(raw_.get(), to_c(which), &ids, &n));
    return std::vector<uint32_t>(ids, ids + n);
  }
  /// How many elements met each fate.
  hw_repair_fate_counts counts() const {
    hw_repair_fate_counts c{};
    check(hw_repair_fates_counts(raw_.get(), &c));
    return c;
  }
  /// The C object, for calls the wrapper does not cover. Still owned by this object.
  hw_repair_fates* get() const noexcept { return raw_.get(); }
  /// Whether this object owns fates (false once moved from).
  explicit operator bool() const noexcept { return static_cast<bool>(raw_); }

 private:
  detail::owned<hw_repair_fates, hw_repair_fates_free> raw_;
};

class soup;
class mesh;
/// The repair pipeline (see hw_repair_mesh()): a new mesh from `input` and the fate of every
/// input element; `input` is unchanged.
std::pair<mesh, repair_fates> repair_mesh(const soup& input,
                                          const hw_repair_options& options = hw_repair_options_default());

/// An indexed face list, read from a file or copied from arrays, that the repairs change in
/// place (owns an hw_soup).
class soup {
 public:
  /// Copies positions (x, y, z per vertex), corners per face and corner indices; see
  /// hw_soup_from_indexed().
  static soup from_indexed(const std::vector<double>& positions,
                           const std::vector<uint32_t>& face_sizes,
                           const std::vector<uint32_t>& indices) {
    if (positions.size() % 3 != 0)
      throw error(Status::InvalidInput, "positions: size is not a multiple of 3 (x, y, z)");
    hw_soup* raw = nullptr;
    check(hw_soup_from_indexed(positions.data(), positions.size() / 3, face_sizes.data(),
                               face_sizes.size(), indices.data(), indices.size(), &raw));
    return soup(raw);
  }
  /// Reads an OBJ, OFF or PLY file as it is; see hw_soup_read().
  static soup read(const std::string& path) {
    hw_soup* raw = nullptr;
    check(hw_soup_read(path.c_str(), &raw));
    return soup(raw);
  }

  /// The positions, x y z per vertex.
  std::vector<double> positions() const {
    const double* xyz = nullptr;
    std::size_t n = 0;
    check(hw_soup_view(get(), &xyz, &n, nullptr, nullptr, nullptr, nullptr));
    return std::vector<double>(xyz, xyz + 3 * n);
  }
  /// The number of corners of each face.
  std::vector<uint32_t> face_sizes() const {
    const uint32_t* sizes = nullptr;
    std::size_t n = 0;
    check(hw_soup_view(get(), nullptr, nullptr, &sizes, &n, nullptr, nullptr));
    return std::vector<uint32_t>(sizes, sizes + n);
  }
  /// The corners' vertex indices, face after face.
  std::vector<uint32_t> indices() const {
    const uint32_t* ids = nullptr;
    std::size_t n = 0;
    check(hw_soup_view(get(), nullptr, nullptr, nullptr, nullptr, &ids, &n));
    return std::vector<uint32_t>(ids, ids + n);
  }

  /// See hw_soup_merge_vertices(): `tolerance` absolute, or a fraction of the bounding-box
  /// diagonal when `relative`; 0 merges exact duplicates only.
  repair_report merge_vertices(double tolerance = 0, bool relative = false) {
    return run([&](hw_repair_report** out) {
      return hw_soup_merge_vertices(get(), tolerance, relative, out);
    });
  }
  /// See hw_soup_remove_duplicate_faces().
  repair_report remove_duplicate_faces() {
    return run([&](hw_repair_report** out) { return hw_soup_remove_duplicate_faces(get(), out); });
  }
  /// See hw_soup_remove_unreferenced_vertices().
  repair_report remove_unreferenced_vertices() {
    return run(
        [&](hw_repair_report** out) { return hw_soup_remove_unreferenced_vertices(get(), out); });
  }
  /// See hw_soup_remove_small_components().
  repair_report remove_small_components(SmallComponents rule, double value) {
    return run([&](hw_repair_report** out) {
      return hw_soup_remove_small_components(get(), to_c(rule), value, out);
    });
  }
  /// See hw_soup_orient_faces().
  repair_report orient_faces() {
    return run([&](hw_repair_report** out) { return hw_soup_orient_faces(get(), out); });
  }
  /// See hw_soup_repair_non_manifold_edges().
  repair_report repair_non_manifold_edges(NonManifoldEdges how = NonManifoldEdges::Cut) {
    return run([&](hw_repair_report** out) {
      return hw_soup_repair_non_manifold_edges(get(), to_c(how), out);
    });
  }
  /// See hw_soup_split_non_manifold_vertices().
  repair_report split_non_manifold_vertices() {
    return run(
        [&](hw_repair_report** out) { return hw_soup_split_non_manifold_vertices(get(), out); });
  }

  /// The C object, still owned by this face list.
  hw_soup* get() const noexcept { return raw_.get(); }

 private:
  explicit soup(hw_soup* raw) : raw_(raw) {}
  template <class Call>
  static repair_report run(Call call) {
    hw_repair_report* raw = nullptr;
    check(call(&raw));
    return repair_report(raw);
  }
  detail::owned<hw_soup, hw_soup_free> raw_;
};

class winged;
class voronoi;
class voronoi_cells;

namespace detail {

/// Calls a C builder of the hw_mesh_from_indexed() form with the three arrays and returns the new
/// object; `report`, when given, receives the build's diagnostic.
template <class T, class Builder>
T* build_indexed(Builder build, const std::vector<double>& positions,
                 const std::vector<uint32_t>& face_sizes, const std::vector<uint32_t>& indices,
                 BuildPolicy policy, diagnostic* report) {
  if (positions.size() % 3 != 0)
    throw error(Status::InvalidInput, "positions: size is not a multiple of 3 (x, y, z)");
  T* raw = nullptr;
  hw_diagnostic* found = nullptr;
  const hw_status status =
      build(positions.data(), positions.size() / 3, face_sizes.data(), face_sizes.size(),
            indices.data(), indices.size(), to_c(policy), &raw, report ? &found : nullptr);
  // A refused build gives its diagnostic too: take it before throwing.
  if (report) *report = diagnostic(found);
  check(status);
  return raw;
}

/// Adapts a C++ callable to hw_visit_fn. An exception thrown by the callable must not unwind
/// through the library: it is caught here, stops the visit, and is rethrown by the caller.
template <class F>
struct visitor {
  F& f;
  std::exception_ptr thrown;

  static bool call(uint32_t idx, void* self) noexcept {
    visitor& v = *static_cast<visitor*>(self);
    try {
      if constexpr (std::is_same_v<std::invoke_result_t<F&, uint32_t>, bool>) {
        return v.f(idx);
      } else {
        v.f(idx);
        return true;
      }
    } catch (...) {
      v.thrown = std::current_exception();
      return false;
    }
  }
};

}  // namespace detail

/// A half-edge polygon mesh (owns an hw_mesh). Const methods may run concurrently; the others
/// need exclusive access. Failures throw hw::error.
class mesh {
 public:
  /// An empty mesh.
  mesh() : raw_(hw_mesh_new()) {
    if (!raw_) check(HW_ERR_PANIC);
  }

  /// Builds a mesh from positions (x, y, z per vertex), corners per face and the vertex index of
  /// every corner; see hw_mesh_from_indexed(). `report`, when given, receives the diagnostic.
  static mesh from_indexed(const std::vector<double>& positions,
                           const std::vector<uint32_t>& face_sizes,
                           const std::vector<uint32_t>& indices,
                           BuildPolicy policy = BuildPolicy::Strict, diagnostic* report = nullptr) {
    return mesh(detail::build_indexed<hw_mesh>(hw_mesh_from_indexed, positions, face_sizes,
                                               indices, policy, report));
  }

  /// Reads an OBJ, OFF or PLY file; see hw_mesh_read(). `report`, when given, receives the
  /// diagnostic, also of a refused file.
  static mesh read(const std::string& path, BuildPolicy policy = BuildPolicy::Strict,
                   diagnostic* report = nullptr) {
    hw_mesh* raw = nullptr;
    hw_diagnostic* found = nullptr;
    const hw_status status =
        hw_mesh_read(path.c_str(), to_c(policy), &raw, report ? &found : nullptr);
    if (report) *report = diagnostic(found);
    check(status);
    return mesh(raw);
  }

  /// The doctor's report on this mesh; see hw_doctor_examine_mesh().
  doctor_report examine(const hw_doctor_options& options = hw_doctor_options_default()) const {
    hw_doctor_report* raw = nullptr;
    check(hw_doctor_examine_mesh(get(), &options, &raw));
    return doctor_report(raw);
  }

  /// Writes the mesh (format by extension); see hw_mesh_write().
  void write(const std::string& path) const { check(hw_mesh_write(get(), path.c_str())); }

  ///@{
  /// Element counts, deleted ones not counted.
  std::size_t n_vertices() const { return hw_mesh_n_vertices(get()); }
  std::size_t n_edges() const { return hw_mesh_n_edges(get()); }
  std::size_t n_halfedges() const { return hw_mesh_n_halfedges(get()); }
  std::size_t n_faces() const { return hw_mesh_n_faces(get()); }
  ///@}
  ///@{
  /// Slots of each kind, deleted ones included: valid ids are below these, and arrays indexed by
  /// id (normals, components) have these lengths.
  std::size_t n_vertex_slots() const { return hw_mesh_n_vertex_slots(get()); }
  std::size_t n_halfedge_slots() const { return hw_mesh_n_halfedge_slots(get()); }
  std::size_t n_edge_slots() const { return hw_mesh_n_edge_slots(get()); }
  std::size_t n_face_slots() const { return hw_mesh_n_face_slots(get()); }
  ///@}

  // Navigation (invalid ids give HW_INVALID_INDEX, as in C).
  ///@{
  /// The checked navigation of the same name in C (hw_mesh_he_origin(), hw_mesh_vertex_halfedge(), hw_mesh_vertex_valence(), hw_mesh_vertex_position(), ...): an invalid or deleted id gives an invalid id, false or 0, as in C (position() throws hw::error).
  hw_vertex origin(hw_halfedge h) const { return hw_mesh_he_origin(get(), h); }
  hw_vertex target(hw_halfedge h) const { return hw_mesh_he_target(get(), h); }
  hw_halfedge twin(hw_halfedge h) const { return hw_mesh_he_twin(get(), h); }
  hw_halfedge next(hw_halfedge h) const { return hw_mesh_he_next(get(), h); }
  hw_halfedge prev(hw_halfedge h) const { return hw_mesh_he_prev(get(), h); }
  hw_face face(hw_halfedge h) const { return hw_mesh_he_face(get(), h); }
  hw_edge edge(hw_halfedge h) const { return hw_mesh_he_edge(get(), h); }
  hw_halfedge halfedge(hw_vertex v) const { return hw_mesh_vertex_halfedge(get(), v); }
  hw_halfedge halfedge(hw_face f) const { return hw_mesh_face_halfedge(get(), f); }
  bool is_boundary(hw_halfedge h) const { return hw_mesh_he_is_boundary(get(), h); }
  bool is_boundary(hw_vertex v) const { return hw_mesh_vertex_is_boundary(get(), v); }
  bool is_boundary(hw_edge e) const { return hw_mesh_edge_is_boundary(get(), e); }
  bool is_boundary(hw_face f) const { return hw_mesh_face_is_boundary(get(), f); }
  uint32_t valence(hw_vertex v) const { return hw_mesh_vertex_valence(get(), v); }
  uint32_t degree(hw_face f) const { return hw_mesh_face_degree(get(), f); }
  std::array<double, 3> position(hw_vertex v) const {
    std::array<double, 3> p{};
    check(hw_mesh_vertex_position(get(), v, p.data()));
    return p;
  }
  ///@}

  /// The inline navigation (see hw::nav_view), valid until the next call that modifies the
  /// mesh: the fastest walks, over trusted ids.
  nav_view nav() const { return nav_view(get()); }

  // Circulation, in the orders documented in halfwing_nav.h (counter-clockwise from outside).
  // The id is checked once (hw::error for an invalid or deleted one); the steps are inline. A
  // range is valid until the next call that modifies the mesh.
  ///@{
  /// A range-for walk around a vertex (outgoing or incoming half-edges, vertices, edges, faces) or a face (its half-edges, vertices, edges, the faces across its edges), in the orders of halfwing_nav.h; the id is checked once (hw::error for an invalid or deleted one).
  halfedge_circulation outgoing(hw_vertex v) const { return checked_nav(v).outgoing(v); }
  incoming_circulation incoming(hw_vertex v) const { return checked_nav(v).incoming(v); }
  vertex_circulation vertices_around(hw_vertex v) const { return checked_nav(v).vertices_around(v); }
  edge_circulation edges_around(hw_vertex v) const { return checked_nav(v).edges_around(v); }
  face_circulation faces_around(hw_vertex v) const { return checked_nav(v).faces_around(v); }
  halfedge_circulation halfedges_of(hw_face f) const { return checked_nav(f).halfedges_of(f); }
  vertex_circulation vertices_of(hw_face f) const { return checked_nav(f).vertices_of(f); }
  edge_circulation edges_of(hw_face f) const { return checked_nav(f).edges_of(f); }
  face_circulation faces_across(hw_face f) const { return checked_nav(f).faces_across(f); }
  ///@}
  /// The loop through `h` by next: a face's sides or a boundary loop.
  halfedge_circulation loop(hw_halfedge h) const {
    hw_circulator c;
    check(hw_circ_along_loop(get(), h, &c));
    return nav().loop(h);
  }

  /// Calls `f(id)` (a `uint32_t`) for every live element of `kind` in increasing id order; an
  /// `f` that returns bool stops the visit by returning false. Returns the number of calls. An
  /// exception thrown by `f` ends the visit and is rethrown here. See hw_mesh_visit().
  template <class F>
  std::size_t visit(ElementKind kind, F&& f) const {
    detail::visitor<std::remove_reference_t<F>> v{f, nullptr};
    std::size_t visited = 0;
    check(hw_mesh_visit(get(), to_c(kind), &decltype(v)::call, &v, &visited));
    if (v.thrown) std::rethrow_exception(v.thrown);
    return visited;
  }

  // Topology.
  /// Throws hw::error naming the first broken invariant (see hw_mesh_check()).
  void check_invariants() const { check(hw_mesh_check(get())); }
  /// One half-edge of every boundary loop (see hw_mesh_boundary_loops()).
  std::vector<hw_halfedge> boundary_loops() const {
    std::size_t n = 0;
    hw_mesh_boundary_loops(get(), nullptr, 0, &n);
    std::vector<hw_halfedge> loops(n);
    check(hw_mesh_boundary_loops(get(), loops.data(), loops.size(), &n));
    return loops;
  }
  /// Counts the boundary loops (see hw_mesh_count_boundary_loops()).
  std::size_t count_boundary_loops() const {
    std::size_t n = 0;
    check(hw_mesh_count_boundary_loops(get(), &n));
    return n;
  }
  /// Counts the connected components (see hw_mesh_count_components()).
  std::size_t count_components() const {
    std::size_t n = 0;
    check(hw_mesh_count_components(get(), &n));
    return n;
  }
  /// The component of every face slot (see hw_mesh_face_components()).
  std::vector<uint32_t> face_components() const {
    std::vector<uint32_t> out(n_face_slots());
    std::size_t n = 0;
    check(hw_mesh_face_components(get(), out.data(), out.size(), &n));
    out.resize(n);
    return out;
  }
  /// Half-edge `side` (0 or 1) of edge `e`.
  hw_halfedge edge_halfedge(hw_edge e, uint32_t side) const {
    return hw_mesh_edge_halfedge(get(), e, side);
  }

  /// A zero-copy view of one connectivity array (see hw_mesh_view()), valid until the next call
  /// that modifies the mesh.
  values_view<const uint32_t> view(MeshArray which) const {
    const uint32_t* data = nullptr;
    std::size_t n = 0;
    check(hw_mesh_view(get(), to_c(which), &data, &n));
    return values_view<const uint32_t>(data, n);
  }
  /// A zero-copy view of the positions, x y z per vertex slot (see hw_mesh_view_positions()).
  values_view<const double> view_positions() const {
    const double* xyz = nullptr;
    std::size_t n = 0;
    check(hw_mesh_view_positions(get(), &xyz, &n));
    return values_view<const double>(xyz, 3 * n);
  }

  // Normals, x y z per element slot.
  /// The unit normal of face `f` (see hw_mesh_face_normal()).
  std::array<double, 3> face_normal(hw_face f) const {
    std::array<double, 3> n{};
    check(hw_mesh_face_normal(get(), f, n.data()));
    return n;
  }
  /// The unit normal of vertex `v` with this weighting (see hw_mesh_vertex_normal()).
  std::array<double, 3> vertex_normal(hw_vertex v,
                                      NormalWeighting weighting = NormalWeighting::Uniform) const {
    std::array<double, 3> n{};
    check(hw_mesh_vertex_normal(get(), v, to_c(weighting), n.data()));
    return n;
  }
  /// Face normals, x y z per face slot.
  std::vector<double> face_normals() const {
    std::vector<double> out(3 * n_face_slots());
    check(hw_mesh_face_normals(get(), out.data(), out.size() / 3, nullptr));
    return out;
  }
  /// Vertex normals with this weighting, x y z per vertex slot.
  std::vector<double> vertex_normals(NormalWeighting weighting = NormalWeighting::Uniform) const {
    std::vector<double> out(3 * n_vertex_slots());
    check(hw_mesh_vertex_normals(get(), to_c(weighting), out.data(), out.size() / 3, nullptr));
    return out;
  }
  /// Normals per corner (x y z per half-edge slot), split at edges sharper than `crease_angle` radians (see hw_mesh_corner_normals()).
  std::vector<double> corner_normals(double crease_angle) const {
    std::vector<double> out(3 * n_halfedge_slots());
    check(hw_mesh_corner_normals(get(), crease_angle, out.data(), out.size() / 3, nullptr));
    return out;
  }
  /// Face and vertex normals in one pass (see hw_mesh_normals()).
  struct face_and_vertex_normals {
    std::vector<double> faces;     ///< x y z per face slot
    std::vector<double> vertices;  ///< x y z per vertex slot
  };
  /// Face and vertex normals in one pass (see hw_mesh_normals()).
  face_and_vertex_normals normals(NormalWeighting weighting = NormalWeighting::Uniform) const {
    face_and_vertex_normals out;
    out.faces.resize(3 * n_face_slots());
    out.vertices.resize(3 * n_vertex_slots());
    check(hw_mesh_normals(get(), to_c(weighting), out.faces.data(), out.faces.size() / 3,
                          nullptr, out.vertices.data(), out.vertices.size() / 3, nullptr));
    return out;
  }

  // Editing; a refused operation throws hw::error (Status::Refused) and changes nothing.
  /// Adds an isolated vertex at `p`.
  hw_vertex add_vertex(const std::array<double, 3>& p) {
    hw_vertex v;
    check(hw_mesh_add_vertex(get(), p.data(), &v));
    return v;
  }
  /// Moves vertex `v` to `p` (finite).
  void set_vertex_position(hw_vertex v, const std::array<double, 3>& p) {
    check(hw_mesh_set_vertex_position(get(), v, p.data()));
  }
  /// Flips interior edge `e` between two triangles (see hw_mesh_flip_edge()).
  void flip_edge(hw_edge e) { check(hw_mesh_flip_edge(get(), e)); }
  /// Splits edge `e` at `p`; returns the new vertex (see hw_mesh_split_edge()).
  hw_vertex split_edge(hw_edge e, const std::array<double, 3>& p) {
    hw_vertex v;
    check(hw_mesh_split_edge(get(), e, p.data(), &v));
    return v;
  }
  /// Splits the face of `h0` and `h1` with a new edge from `h0`'s target to `h1`'s target;
  /// returns the new half-edge (see hw_mesh_split_face()).
  hw_halfedge split_face(hw_halfedge h0, hw_halfedge h1) {
    hw_halfedge h;
    check(hw_mesh_split_face(get(), h0, h1, &h));
    return h;
  }
  /// Triangulates face `f`; returns the number of faces it became (see
  /// hw_mesh_triangulate_face()).
  std::size_t triangulate_face(hw_face f) {
    std::size_t n = 0;
    check(hw_mesh_triangulate_face(get(), f, &n));
    return n;
  }
  /// Collapses `h`, moving its origin onto its target; returns the vertex kept (see
  /// hw_mesh_collapse_halfedge()).
  hw_vertex collapse_halfedge(hw_halfedge h) {
    hw_vertex v;
    check(hw_mesh_collapse_halfedge(get(), h, &v));
    return v;
  }
  /// Deletes face `f`, and the vertices it leaves isolated when asked (see
  /// hw_mesh_delete_face()).
  void delete_face(hw_face f, bool delete_isolated_vertices) {
    check(hw_mesh_delete_face(get(), f, delete_isolated_vertices));
  }
  /// Deletes edge `e` with the faces beside it (see hw_mesh_delete_edge()).
  void delete_edge(hw_edge e, bool delete_isolated_vertices) {
    check(hw_mesh_delete_edge(get(), e, delete_isolated_vertices));
  }
  /// Deletes vertex `v` with every face around it.
  void delete_vertex(hw_vertex v) { check(hw_mesh_delete_vertex(get(), v)); }
  /// Removes deleted elements for good; returns the old-to-new maps.
  index_maps garbage_collect() {
    hw_index_maps* maps = nullptr;
    check(hw_mesh_garbage_collect(get(), &maps));
    return index_maps(maps);
  }
  /// Mends degenerate triangles (see hw_mesh_remove_degenerate_faces()): short edges collapse,
  /// caps flip with the triangle across, the rest are removed; the mesh is compacted, the
  /// report's maps giving the new ids.
  repair_report remove_degenerate_faces(double tolerance = 0, bool relative = false) {
    hw_repair_report* raw = nullptr;
    check(hw_mesh_remove_degenerate_faces(get(), tolerance, relative, &raw));
    return repair_report(raw);
  }
  /// Splits boundary edges at the T-vertices on them (see hw_mesh_remove_t_vertices()), so
  /// that stitch_borders() can close the cracks; the report's vertex copies name the
  /// T-vertices.
  repair_report remove_t_vertices(double tolerance = 0, bool relative = false) {
    hw_repair_report* raw = nullptr;
    check(hw_mesh_remove_t_vertices(get(), tolerance, relative, &raw));
    return repair_report(raw);
  }
  /// Glues coincident boundary edges (see hw_mesh_stitch_borders()); the mesh is compacted,
  /// the report's maps giving the new ids.
  repair_report stitch_borders(double tolerance = 0, bool relative = false) {
    hw_repair_report* raw = nullptr;
    check(hw_mesh_stitch_borders(get(), tolerance, relative, &raw));
    return repair_report(raw);
  }
  /// Fills the hole whose boundary loop holds `h` (see hw_mesh_fill_hole()); returns the
  /// triangles added. Throws hw::error (Status::Refused, mesh unchanged) when it cannot.
  size_t fill_hole(hw_halfedge h) {
    size_t faces = 0;
    check(hw_mesh_fill_hole(get(), h, &faces));
    return faces;
  }
  /// What fill_holes() did: holes filled and refused (left open), triangles added.
  struct fill_holes_result {
    size_t filled = 0;       ///< Holes closed.
    size_t refused = 0;      ///< Holes within the bounds left open (see hw_mesh_fill_holes()).
    size_t faces_added = 0;  ///< Triangles added in all.
  };
  /// Fills every hole within `options`' bounds (see hw_mesh_fill_holes()).
  fill_holes_result fill_holes(const hw_fill_hole_options& options = hw_fill_hole_options_default()) {
    fill_holes_result result;
    check(hw_mesh_fill_holes(get(), &options, &result.filled, &result.refused,
                             &result.faces_added));
    return result;
  }
  /// Fills every hole of at most `max_edges` boundary edges in `mode` (see
  /// hw_mesh_fill_holes()); a refined fill also adds vertices (n_vertices() grows).
  fill_holes_result fill_holes(size_t max_edges, FillMode mode) {
    hw_fill_hole_options options = hw_fill_hole_options_default();
    options.max_edges = max_edges;
    options.mode = to_c(mode);
    return fill_holes(options);
  }

  /// Adds an isolated vertex.
  hw_vertex add_vertex(double x, double y, double z) { return add_vertex({x, y, z}); }

  /// Adds the face with these corners (counter-clockwise); throws hw::error (Status::Refused,
  /// mesh unchanged) for a complex edge or vertex, repeated or too few corners.
  hw_face add_face(const std::vector<hw_vertex>& corners) {
    hw_face f;
    check(hw_mesh_add_face(get(), corners.data(), corners.size(), &f));
    return f;
  }

  /// Adds a zero-filled attribute of `components` values of type `T` (double, float, int32_t,
  /// uint32_t) per element of `kind`.
  template <class T>
  void add_attribute(ElementKind kind, const std::string& name, std::size_t components = 1) {
    check(hw_mesh_attribute_add(get(), to_c(kind), name.c_str(), detail::scalar_type<T>::value,
                                components));
  }

  /// The values of attribute `name` (element `i` owns `components` values from `i *
  /// components`); throws when it does not exist or holds another type.
  template <class T>
  values_view<const T> attribute(ElementKind kind, const std::string& name) const {
    const void* data = nullptr;
    std::size_t size = 0;
    check(hw_mesh_attribute_view(get(), to_c(kind), name.c_str(), detail::scalar_type<T>::value, &data,
                                 &size));
    return values_view<const T>(static_cast<const T*>(data), size);
  }

  /// The values of attribute `name`, writable.
  template <class T>
  values_view<T> attribute_data(ElementKind kind, const std::string& name) {
    void* data = nullptr;
    std::size_t size = 0;
    check(hw_mesh_attribute_data(get(), to_c(kind), name.c_str(), detail::scalar_type<T>::value, &data,
                                 &size));
    return values_view<T>(static_cast<T*>(data), size);
  }

  /// The scalar type and the components per element of attribute `name` (see
  /// hw_mesh_attribute_info()).
  std::pair<ScalarType, std::size_t> attribute_info(ElementKind kind,
                                                    const std::string& name) const {
    hw_scalar_type type = 0;
    std::size_t components = 0;
    check(hw_mesh_attribute_info(get(), to_c(kind), name.c_str(), &type, &components));
    return {static_cast<ScalarType>(type), components};
  }

  /// Removes attribute `name` of `kind`.
  void remove_attribute(ElementKind kind, const std::string& name) {
    check(hw_mesh_attribute_remove(get(), to_c(kind), name.c_str()));
  }

  /// Names of the attributes of `kind`, in the order they were added.
  std::vector<std::string> attribute_names(ElementKind kind) const {
    std::size_t count = 0;
    check(hw_mesh_count_attributes(get(), to_c(kind), &count));
    std::vector<std::string> names;
    for (std::size_t i = 0; i < count; ++i) {
      names.push_back(detail::copied_text([&](char* out_text, std::size_t capacity,
                                              std::size_t* out_needed) {
        return hw_mesh_attribute_name(get(), to_c(kind), i, out_text, capacity, out_needed);
      }));
    }
    return names;
  }

  /// Corner normals, x y z per half-edge slot; throws Status::NotFound when there are none.
  values_view<const double> corner_normals() const {
    const double* xyz = nullptr;
    std::size_t n = 0;
    check(hw_mesh_corner_normals_view(get(), &xyz, &n));
    return values_view<const double>(xyz, 3 * n);
  }

  /// Sets the corner normals from x y z per half-edge slot.
  void set_corner_normals(const std::vector<double>& xyz) {
    if (xyz.size() % 3 != 0)
      throw error(Status::InvalidInput, "corner normals: size is not a multiple of 3 (x, y, z)");
    check(hw_mesh_corner_normals_set(get(), xyz.data(), xyz.size() / 3));
  }

  /// Corner texture coordinates, u v per half-edge slot; throws Status::NotFound when none.
  values_view<const double> corner_uvs() const {
    const double* uv = nullptr;
    std::size_t n = 0;
    check(hw_mesh_corner_uvs_view(get(), &uv, &n));
    return values_view<const double>(uv, 2 * n);
  }

  /// Sets the corner texture coordinates from u v per half-edge slot.
  void set_corner_uvs(const std::vector<double>& uv) {
    if (uv.size() % 2 != 0)
      throw error(Status::InvalidInput, "corner uvs: size is not a multiple of 2 (u, v)");
    check(hw_mesh_corner_uvs_set(get(), uv.data(), uv.size() / 2));
  }

  /// Takes ownership of a mesh made by a C call (a generator, a builder).
  static mesh adopt(hw_mesh* raw) { return mesh(raw); }

  /// The C object, for calls the wrapper does not cover. Still owned by this mesh.
  hw_mesh* get() const noexcept { return raw_.get(); }
  /// Whether this object owns a mesh (false once moved from).
  explicit operator bool() const noexcept { return static_cast<bool>(raw_); }

 private:
  friend class winged;  // hw::winged::to_mesh() hands over a new hw_mesh
  // The Voronoi classes hand out meshes they build.
  friend class voronoi;
  friend class voronoi_cells;
  friend std::pair<mesh, repair_fates> repair_mesh(const soup&, const hw_repair_options&);
  explicit mesh(hw_mesh* raw) : raw_(raw) {}
  // The navigation view once `v` (or `f`) is known to be live: the checked circulator start
  // throws hw::error with the library's message otherwise.
  nav_view checked_nav(hw_vertex v) const {
    hw_circulator c;
    check(hw_circ_around_vertex(get(), v, HW_CIRCULATOR_KIND_HALFEDGES, &c));
    return nav();
  }
  nav_view checked_nav(hw_face f) const {
    hw_circulator c;
    check(hw_circ_around_face(get(), f, HW_CIRCULATOR_KIND_HALFEDGES, &c));
    return nav();
  }
  detail::owned<hw_mesh, hw_mesh_free> raw_;
};

inline std::pair<mesh, repair_fates> repair_mesh(const soup& input,
                                                 const hw_repair_options& options) {
  hw_mesh* raw_mesh = nullptr;
  hw_repair_fates* raw_fates = nullptr;
  check(hw_repair_mesh(input.get(), &options, &raw_mesh, &raw_fates));
  return {mesh(raw_mesh), repair_fates(raw_fates)};
}

// ---------------------------------------------------------------------------------------------
// Winged-edge kernel

/// A winged-edge (Baumgart) polygon mesh (owns an hw_winged). Ids are hw_wvertex, hw_wedge and
/// hw_wface; the walks are ranges (`for (hw_wedge e : w.face_edges(f))`); the Euler operators
/// throw hw::error (Status::Refused when a precondition does not hold) and leave the
/// structure unchanged when they refuse.
class winged {
 public:
  ///@{
  /// A range-for walk (of edges, vertices or faces) around a face or a vertex.
  using edge_range = circulation_of<hw_wcirculator, hw_wedge, hw_wcirc_next_edge>;
  using vertex_range = circulation_of<hw_wcirculator, hw_wvertex, hw_wcirc_next_vertex>;
  using face_range = circulation_of<hw_wcirculator, hw_wface, hw_wcirc_next_face>;
  ///@}
  /// A position, x y z.
  using point = std::array<double, 3>;

  /// An empty structure, to build with the Euler operators (mvfs() first).
  winged() : raw_(hw_winged_new()) {
    if (!raw_) check(HW_ERR_PANIC);
  }

  /// Builds from positions (x, y, z per vertex), corners per face and the vertex index of every
  /// corner; see hw_winged_from_indexed(). `report`, when given, receives the diagnostic.
  static winged from_indexed(const std::vector<double>& positions,
                             const std::vector<uint32_t>& face_sizes,
                             const std::vector<uint32_t>& indices,
                             BuildPolicy policy = BuildPolicy::Strict,
                             diagnostic* report = nullptr) {
    return winged(detail::build_indexed<hw_winged>(hw_winged_from_indexed, positions, face_sizes,
                                                   indices, policy, report));
  }

  /// Builds like from_indexed() (strict policy), numbering and directing the edges as
  /// `edge_order` lists them (two vertex indices per edge); see hw_winged_from_indexed_ordered().
  static winged from_indexed_ordered(const std::vector<double>& positions,
                                     const std::vector<uint32_t>& face_sizes,
                                     const std::vector<uint32_t>& indices,
                                     const std::vector<uint32_t>& edge_order) {
    if (positions.size() % 3 != 0)
      throw error(Status::InvalidInput, "positions: size is not a multiple of 3 (x, y, z)");
    if (edge_order.size() % 2 != 0)
      throw error(Status::InvalidInput, "edge_order: size is not a multiple of 2 (from, to)");
    hw_winged* raw = nullptr;
    check(hw_winged_from_indexed_ordered(positions.data(), positions.size() / 3,
                                         face_sizes.data(), face_sizes.size(), indices.data(),
                                         indices.size(), edge_order.data(),
                                         edge_order.size() / 2, &raw));
    return winged(raw);
  }

  /// The winged-edge structure of a half-edge mesh (same ids); see hw_winged_from_mesh().
  static winged from_mesh(const hw::mesh& m) {
    hw_winged* raw = nullptr;
    check(hw_winged_from_mesh(m.get(), &raw));
    return winged(raw);
  }

  /// The half-edge mesh of this structure (same ids); see hw_winged_to_mesh().
  hw::mesh to_mesh() const {
    hw_mesh* raw = nullptr;
    check(hw_winged_to_mesh(get(), &raw));
    return hw::mesh(raw);
  }

  ///@{
  /// Element counts, deleted ones not counted.
  std::size_t n_vertices() const { return hw_winged_n_vertices(get()); }
  std::size_t n_edges() const { return hw_winged_n_edges(get()); }
  std::size_t n_faces() const { return hw_winged_n_faces(get()); }
  ///@}
  ///@{
  /// Slots of each kind, deleted ones included: valid ids are below these.
  std::size_t n_vertex_slots() const { return hw_winged_n_vertex_slots(get()); }
  std::size_t n_edge_slots() const { return hw_winged_n_edge_slots(get()); }
  std::size_t n_face_slots() const { return hw_winged_n_face_slots(get()); }
  ///@}

  /// The record of edge `e`: vertices, faces and the four wings.
  hw_wedge_record edge(hw_wedge e) const {
    hw_wedge_record record;
    check(hw_winged_edge(get(), e, &record));
    return record;
  }
  /// A zero-copy view of every edge record, indexed by edge id (see hw_winged_edge_records()),
  /// valid until the next call that modifies the structure.
  values_view<const hw_wedge_record> edge_records() const {
    const hw_wedge_record* records = nullptr;
    std::size_t n = 0;
    check(hw_winged_edge_records(get(), &records, &n));
    return values_view<const hw_wedge_record>(records, n);
  }
  ///@{
  /// Whether the id names a live element.
  bool is_vertex(hw_wvertex v) const { return hw_winged_is_vertex(get(), v); }
  bool is_edge(hw_wedge e) const { return hw_winged_is_edge(get(), e); }
  bool is_face(hw_wface f) const { return hw_winged_is_face(get(), f); }
  ///@}

  /// The edge `v` stores (where its ring starts); invalid for an isolated vertex. Throws for a
  /// vertex that does not exist.
  hw_wedge vertex_edge(hw_wvertex v) const {
    if (!is_vertex(v)) check(HW_ERR_INVALID_HANDLE);
    return hw_winged_vertex_edge(get(), v);
  }
  /// The edge `f` stores (where its loop starts); invalid for a point face. Throws for a face
  /// that does not exist.
  hw_wedge face_edge(hw_wface f) const {
    if (!is_face(f)) check(HW_ERR_INVALID_HANDLE);
    return hw_winged_face_edge(get(), f);
  }

  /// The position of vertex `v`.
  point position(hw_wvertex v) const { return triple(hw_winged_vertex_position, v); }
  /// The unit normal of face `f` (see hw_winged_face_normal()).
  point face_normal(hw_wface f) const { return triple(hw_winged_face_normal, f); }
  /// The unit normal of vertex `v` with this weighting (see hw_winged_vertex_normal()).
  point vertex_normal(hw_wvertex v, NormalWeighting weighting = NormalWeighting::Uniform) const {
    point n{};
    check(hw_winged_vertex_normal(get(), v, to_c(weighting), n.data()));
    return n;
  }
  /// Face normals, x y z per face slot (see hw_winged_face_normals()).
  std::vector<double> face_normals() const {
    std::vector<double> out(3 * n_face_slots());
    check(hw_winged_face_normals(get(), out.data(), out.size() / 3, nullptr));
    return out;
  }
  /// Vertex normals with this weighting, x y z per vertex slot (see hw_winged_vertex_normals()).
  std::vector<double> vertex_normals(NormalWeighting weighting = NormalWeighting::Uniform) const {
    std::vector<double> out(3 * n_vertex_slots());
    check(hw_winged_vertex_normals(get(), to_c(weighting), out.data(), out.size() / 3, nullptr));
    return out;
  }
  /// Moves vertex `v` to `p` (finite).
  void set_vertex_position(hw_wvertex v, const point& p) {
    check(hw_winged_set_vertex_position(get(), v, p.data()));
  }

  /// The edges of `f`'s loop, counter-clockwise from its stored edge.
  edge_range face_edges(hw_wface f) const { return edge_range(around(f, WCirculatorKind::Edges)); }
  /// The corners of `f`, counter-clockwise from its first corner.
  vertex_range face_vertices(hw_wface f) const {
    return vertex_range(around(f, WCirculatorKind::Vertices));
  }
  /// The faces across `f`'s edges (holes skipped).
  face_range face_faces(hw_wface f) const { return face_range(around(f, WCirculatorKind::Faces)); }
  /// The edges at `v`, counter-clockwise.
  edge_range vertex_edges(hw_wvertex v) const {
    return edge_range(around(v, WCirculatorKind::Edges));
  }
  /// The neighbours of `v`, counter-clockwise.
  vertex_range vertex_vertices(hw_wvertex v) const {
    return vertex_range(around(v, WCirculatorKind::Vertices));
  }
  /// The faces around `v`, counter-clockwise (holes skipped).
  face_range vertex_faces(hw_wvertex v) const {
    return face_range(around(v, WCirculatorKind::Faces));
  }

  /// Make vertex, face, solid: returns the new vertex and (point) face.
  std::pair<hw_wvertex, hw_wface> mvfs(const point& p) {
    std::pair<hw_wvertex, hw_wface> made;
    check(hw_winged_mvfs(get(), p.data(), &made.first, &made.second));
    return made;
  }
  /// Make edge, vertex: returns the new edge and vertex.
  std::pair<hw_wedge, hw_wvertex> mev(hw_wface f, hw_wvertex v, const point& p) {
    std::pair<hw_wedge, hw_wvertex> made;
    check(hw_winged_mev(get(), f, v, p.data(), &made.first, &made.second));
    return made;
  }
  /// Make edge, face: returns the new edge and face.
  std::pair<hw_wedge, hw_wface> mef(hw_wface f, hw_wvertex v1, hw_wvertex v2) {
    std::pair<hw_wedge, hw_wface> made;
    check(hw_winged_mef(get(), f, v1, v2, &made.first, &made.second));
    return made;
  }
  /// Euler operator KEV: kills edge `e` and vertex `v` (see hw_winged_kev()).
  void kev(hw_wedge e, hw_wvertex v) { check(hw_winged_kev(get(), e, v)); }
  /// Euler operator KEF: kills edge `e` and face `kill` (see hw_winged_kef()).
  void kef(hw_wedge e, hw_wface kill) { check(hw_winged_kef(get(), e, kill)); }
  /// Euler operator KVFS: kills the last vertex, face `f` and the shell (see hw_winged_kvfs()).
  void kvfs(hw_wface f) { check(hw_winged_kvfs(get(), f)); }
  /// Drops the elements the kill operators deleted; returns the old-to-new maps.
  index_maps garbage_collect() {
    hw_index_maps* maps = nullptr;
    check(hw_winged_garbage_collect(get(), &maps));
    return index_maps(maps);
  }

  /// Throws hw::error naming the first broken invariant, if any.
  void check_invariants() const { check(hw_winged_check(get())); }

  /// A table in a textbook layout; see hw_winged_table().
  std::string table(WTable which, WNaming naming = WNaming::CwCcw,
                    TableFormat format = TableFormat::Text) const {
    return detail::copied_text([&](char* out_text, std::size_t capacity, std::size_t* out_needed) {
      return hw_winged_table(get(), to_c(which), to_c(naming), to_c(format), out_text, capacity,
                             out_needed);
    });
  }

  /// The C object, for calls the wrapper does not cover. Still owned by this structure.
  hw_winged* get() const noexcept { return raw_.get(); }
  /// Whether this object owns a structure (false once moved from).
  explicit operator bool() const noexcept { return static_cast<bool>(raw_); }

 private:
  explicit winged(hw_winged* raw) : raw_(raw) {}

  hw_wcirculator around(hw_wface f, WCirculatorKind kind) const {
    hw_wcirculator c;
    check(hw_wcirc_around_face(get(), f, to_c(kind), &c));
    return c;
  }
  hw_wcirculator around(hw_wvertex v, WCirculatorKind kind) const {
    hw_wcirculator c;
    check(hw_wcirc_around_vertex(get(), v, to_c(kind), &c));
    return c;
  }

  template <class Id>
  point triple(hw_status (*call)(const hw_winged*, Id, double*), Id id) const {
    point p;
    check(call(get(), id, p.data()));
    return p;
  }

  detail::owned<hw_winged, hw_winged_free> raw_;
};

/// A 2D point (x, y).
using point2 = std::array<double, 2>;

/// The points of a 2D point file (.xy, .cin, .node, .poly, .txt, .json), in file order, in the
/// form hw::voronoi takes; see hw_points2d_read().
inline std::vector<point2> read_points2d(const std::string& path) {
  hw_points2d* raw = nullptr;
  check(hw_points2d_read(path.c_str(), &raw));
  const detail::owned<hw_points2d, hw_points2d_free> points(raw);
  const double* xy = nullptr;
  std::size_t n = 0;
  check(hw_points2d_view(points.get(), &xy, &n));
  std::vector<point2> out(n);
  for (std::size_t i = 0; i < n; ++i) out[i] = {xy[2 * i], xy[2 * i + 1]};
  return out;
}

/// Clipped Voronoi cells (owns an hw_voronoi_cells): closed polygons tiling a convex region, with
/// shared corners. Independent of the diagram they came from; immutable, so every method may run
/// concurrently. Failures throw hw::error.
class voronoi_cells {
 public:
  /// Number of cells (one per input site, empty ones included).
  std::size_t size() const { return hw_voronoi_cells_n_cells(get()); }

  /// All cell corners (x, y each), shared between neighbouring cells.
  values_view<const point2> positions() const {
    const double* xy = nullptr;
    std::size_t n = 0;
    check(hw_voronoi_cells_positions(get(), &xy, &n));
    return {reinterpret_cast<const point2*>(xy), n};
  }

  /// Indices into positions() of the cell of `site`, counter-clockwise (empty for duplicates
  /// and cells outside the region).
  values_view<const uint32_t> polygon(hw_site site) const {
    const uint32_t* indices = nullptr;
    std::size_t n = 0;
    check(hw_voronoi_cells_polygon(get(), site, &indices, &n));
    return {indices, n};
  }

  /// The corners of the cell of `site`, counter-clockwise.
  std::vector<point2> polygon_points(hw_site site) const {
    const values_view<const point2> all = positions();
    std::vector<point2> out;
    for (uint32_t i : polygon(site)) out.push_back(all[i]);
    return out;
  }

  /// Area of the cell of `site` (0 when empty).
  double area(hw_site site) const {
    double a = 0;
    check(hw_voronoi_cells_area_centroid(get(), site, &a, nullptr));
    return a;
  }

  /// Centroid of the cell of `site`; throws (Status::NotFound) for an empty cell.
  point2 centroid(hw_site site) const {
    point2 c{};
    check(hw_voronoi_cells_area_centroid(get(), site, nullptr, c.data()));
    return c;
  }

  /// The cells as a half-edge mesh (z = 0); face k belongs to face_sites()[k].
  hw::mesh to_mesh() const {
    hw_mesh* raw = nullptr;
    check(hw_voronoi_cells_mesh(get(), &raw));
    return hw::mesh(raw);
  }

  /// The site of every face of to_mesh().
  std::vector<hw_site> face_sites() const {
    std::size_t n = 0;
    hw_voronoi_cells_face_sites(get(), nullptr, 0, &n);
    std::vector<hw_site> sites(n);
    check(hw_voronoi_cells_face_sites(get(), sites.data(), sites.size(), &n));
    return sites;
  }

  /// The C object, still owned by this wrapper.
  hw_voronoi_cells* get() const noexcept { return raw_.get(); }

 private:
  friend class voronoi;
  explicit voronoi_cells(hw_voronoi_cells* raw) : raw_(raw) {}
  detail::owned<hw_voronoi_cells, hw_voronoi_cells_free> raw_;
};

/// A Delaunay triangulation without its Voronoi diagram (owns an hw_delaunay); immutable, so
/// every method may run concurrently. Failures throw hw::error.
class delaunay {
 public:
  /// Triangulates `sites`; see hw_delaunay_build().
  explicit delaunay(const std::vector<point2>& sites) {
    hw_delaunay* raw = nullptr;
    check(hw_delaunay_build(sites.empty() ? nullptr : sites.front().data(), sites.size(), &raw));
    raw_ = detail::owned<hw_delaunay, hw_delaunay_free>(raw);
  }

  /// The number of triangles (see hw_delaunay_n_triangles()).
  std::size_t n_triangles() const { return hw_delaunay_n_triangles(get()); }
  /// Whether the sites span a plane, a line, a point or nothing (see hw_delaunay_dimension()).
  SiteDimension dimension() const {
    return static_cast<SiteDimension>(hw_delaunay_dimension(get()));
  }

  /// One index array of the triangulation (VoronoiArray::Representative, Triangles,
  /// TriangleTwins or Hull); see hw_delaunay_view().
  values_view<const uint32_t> view(VoronoiArray which) const {
    const uint32_t* data = nullptr;
    std::size_t n = 0;
    check(hw_delaunay_view(get(), to_c(which), &data, &n));
    return {data, n};
  }

  /// The C object, for calls the wrapper does not cover. Still owned by this object.
  hw_delaunay* get() const noexcept { return raw_.get(); }

 private:
  detail::owned<hw_delaunay, hw_delaunay_free> raw_;
};

/// A Voronoi diagram with its Delaunay triangulation (owns an hw_voronoi); immutable, so every
/// method may run concurrently. Failures throw hw::error.
class voronoi {
 public:
  /// Builds the diagram of `sites`; see hw_voronoi_build().
  explicit voronoi(const std::vector<point2>& sites) {
    hw_voronoi* raw = nullptr;
    check(hw_voronoi_build(sites.empty() ? nullptr : sites.front().data(), sites.size(), &raw));
    raw_ = detail::owned<hw_voronoi, hw_voronoi_free>(raw);
  }

  /// The number of sites given, duplicates included.
  std::size_t n_sites() const { return hw_voronoi_n_sites(get()); }
  /// The number of distinct sites (duplicates merged).
  std::size_t n_unique_sites() const { return hw_voronoi_n_unique_sites(get()); }
  /// The number of Delaunay triangles.
  std::size_t n_triangles() const { return hw_voronoi_n_triangles(get()); }
  /// The number of Voronoi vertices.
  std::size_t n_vertices() const { return hw_voronoi_n_vertices(get()); }
  /// The number of Voronoi half-edges.
  std::size_t n_halfedges() const { return hw_voronoi_n_halfedges(get()); }
  /// The dimension the sites span (see ::hw_site_dimension).
  SiteDimension dimension() const {
    return static_cast<SiteDimension>(hw_voronoi_dimension(get()));
  }

  /// One index array of the diagram; see hw_voronoi_view() and ::hw_voronoi_array.
  values_view<const uint32_t> view(VoronoiArray which) const {
    const uint32_t* data = nullptr;
    std::size_t n = 0;
    check(hw_voronoi_view(get(), to_c(which), &data, &n));
    return {data, n};
  }

  /// The sites as given.
  values_view<const point2> sites() const {
    const double* xy = nullptr;
    std::size_t n = 0;
    check(hw_voronoi_sites(get(), &xy, &n));
    return {reinterpret_cast<const point2*>(xy), n};
  }

  /// The Voronoi vertices (circumcentres).
  values_view<const point2> vertices() const {
    const double* xy = nullptr;
    std::size_t n = 0;
    check(hw_voronoi_vertices(get(), &xy, &n));
    return {reinterpret_cast<const point2*>(xy), n};
  }

  /// The edge of half-edge `h`: its two sites and its segment, ray or line.
  hw_voronoi_edge edge(hw_voronoi_halfedge h) const {
    hw_voronoi_edge e;
    check(hw_voronoi_edge_describe(get(), h, &e));
    return e;
  }

  /// The Delaunay triangulation as a half-edge mesh (z = 0, vertex i = site i).
  hw::mesh delaunay_mesh() const {
    hw_mesh* raw = nullptr;
    check(hw_voronoi_delaunay_mesh(get(), &raw));
    return hw::mesh(raw);
  }

  /// The site nearest to `p` (exact); `hint`, a nearby site, speeds the search up.
  hw_site nearest_site(point2 p, hw_site hint = hw_site{HW_INVALID_INDEX}) const {
    hw_site s{HW_INVALID_INDEX};
    check(hw_voronoi_nearest_site(get(), p[0], p[1], hint, &s));
    return s;
  }

  /// Sites whose cells share an edge with the cell of `site`, counter-clockwise.
  std::vector<hw_site> neighbours(hw_site site) const {
    std::size_t n = 0;
    check_or_size(hw_voronoi_neighbours(get(), site, nullptr, 0, &n));
    std::vector<hw_site> out(n);
    check(hw_voronoi_neighbours(get(), site, out.data(), out.size(), &n));
    return out;
  }

  /// The half-edge of the cell of `a` facing the cell of `b`; throws Status::NotFound when the
  /// cells are not adjacent.
  hw_voronoi_halfedge edge_between(hw_site a, hw_site b) const {
    hw_voronoi_halfedge h{HW_INVALID_INDEX};
    check(hw_voronoi_edge_between(get(), a, b, &h));
    return h;
  }

  /// Every cell clipped to the rectangle [min, max].
  voronoi_cells clip(point2 min, point2 max) const {
    hw_voronoi_cells* raw = nullptr;
    check(hw_voronoi_clip_rect(get(), min[0], min[1], max[0], max[1], &raw));
    return voronoi_cells(raw);
  }

  /// Every cell clipped to a convex polygon (either orientation).
  voronoi_cells clip(const std::vector<point2>& convex_polygon) const {
    hw_voronoi_cells* raw = nullptr;
    check(hw_voronoi_clip_convex(get(), convex_polygon.empty() ? nullptr : convex_polygon.front().data(),
                                 convex_polygon.size(), &raw));
    return voronoi_cells(raw);
  }

  /// Nearest-site labels of a width × height raster of [min, max] under `metric`, row-major,
  /// row 0 at the top.
  std::vector<uint32_t> label_image(Metric metric, point2 min, point2 max, uint32_t width,
                                    uint32_t height) const {
    std::vector<uint32_t> labels(static_cast<std::size_t>(width) * height);
    check(hw_voronoi_label_image(get(), to_c(metric), min[0], min[1], max[0], max[1], width, height,
                                 labels.data(), labels.size(), nullptr));
    return labels;
  }

  /// An SVG drawing of `cells` (clipped from this diagram).
  std::string svg(const voronoi_cells& cells,
                  const hw_svg_options& options = hw_svg_options_default()) const {
    std::size_t needed = 0;
    check_or_size(hw_voronoi_svg(get(), cells.get(), &options, nullptr, 0, &needed));
    std::string text(needed, '\0');
    check(hw_voronoi_svg(get(), cells.get(), &options, &text[0], text.size(), &needed));
    text.resize(needed - 1);
    return text;
  }

  /// Writes an SVG drawing of `cells` (clipped from this diagram) to `path`.
  void write_svg(const voronoi_cells& cells, const std::string& path,
                 const hw_svg_options& options = hw_svg_options_default()) const {
    check(hw_voronoi_svg_write(get(), cells.get(), &options, path.c_str()));
  }

  /// The C object, still owned by this wrapper.
  hw_voronoi* get() const noexcept { return raw_.get(); }

 private:
  /// A size query fails with HW_ERR_BUFFER_TOO_SMALL by design; anything else is an error.
  static void check_or_size(hw_status status) {
    if (status != HW_ERR_BUFFER_TOO_SMALL) check(status);
  }
  detail::owned<hw_voronoi, hw_voronoi_free> raw_;
};

/// The outcome of hw::lloyd().
struct lloyd_result {
  /// The relaxed sites.
  std::vector<point2> sites;
  /// The steps taken.
  uint32_t iterations = 0;
  /// How far the sites moved in the last step (the largest distance).
  double max_displacement = 0;
};

/// Lloyd relaxation of `sites` inside the convex polygon `region`; see hw_voronoi_lloyd().
inline lloyd_result lloyd(const std::vector<point2>& sites, const std::vector<point2>& region,
                          uint32_t max_iterations, double tolerance = 0) {
  lloyd_result r;
  r.sites.resize(sites.size());
  check(hw_voronoi_lloyd(sites.empty() ? nullptr : sites.front().data(), sites.size(),
                         region.empty() ? nullptr : region.front().data(), region.size(),
                         max_iterations, tolerance, sites.empty() ? nullptr : r.sites.front().data(),
                         &r.iterations, &r.max_displacement));
  return r;
}

/// GPU-ready arrays of a mesh or a polygon list (owns an hw_render_buffers); see
/// hw_render_buffers_build(). Views stay valid while this object lives.
class render_buffers {
 public:
  /// The buffers of `m`; `report` (the mesh's build diagnostic) adds its non-manifold edges.
  explicit render_buffers(const mesh& m,
                          const hw_render_options& options = hw_render_options_default(),
                          const diagnostic* report = nullptr) {
    hw_render_buffers* raw = nullptr;
    check(hw_render_buffers_build(m.get(), report ? report->get() : nullptr, &options, &raw));
    raw_ = owner(raw);
  }

  /// Fills and outlines of polygons: `corners` holds `dimension` (2 or 3) doubles per corner,
  /// polygon after polygon, `sizes` the corners of each; see hw_render_buffers_from_polygons().
  static render_buffers polygons(const std::vector<double>& corners, uint32_t dimension,
                                 const std::vector<uint32_t>& sizes) {
    if (dimension == 0 || corners.size() % dimension != 0)
      throw error(Status::InvalidInput, "corners: size is not a multiple of the dimension");
    hw_render_buffers* raw = nullptr;
    check(hw_render_buffers_from_polygons(corners.data(), dimension, corners.size() / dimension,
                                          sizes.data(), sizes.size(), &raw));
    return render_buffers(raw);
  }

  /// Fills and outlines of clipped Voronoi cells, polygon `i` being the cell of site `i`; see
  /// hw_render_buffers_from_voronoi_cells().
  static render_buffers cells(const voronoi_cells& c) {
    hw_render_buffers* raw = nullptr;
    check(hw_render_buffers_from_voronoi_cells(c.get(), &raw));
    return render_buffers(raw);
  }

  /// One kind of a doctor's findings over the face list it examined; see
  /// hw_render_buffers_from_finding().
  static render_buffers finding(const doctor_report& report, DoctorFinding kind,
                                const std::vector<double>& positions,
                                const std::vector<uint32_t>& face_sizes,
                                const std::vector<uint32_t>& indices) {
    if (positions.size() % 3 != 0)
      throw error(Status::InvalidInput, "positions: size is not a multiple of 3 (x, y, z)");
    hw_render_buffers* raw = nullptr;
    check(hw_render_buffers_from_finding(report.get(), to_c(kind), positions.data(),
                                         positions.size() / 3, face_sizes.data(), face_sizes.size(),
                                         indices.data(), indices.size(), &raw));
    return render_buffers(raw);
  }

  /// One float array (see hw_render_buffers_floats()), valid while this object lives.
  values_view<const float> floats(RenderFloats which) const {
    const float* data = nullptr;
    std::size_t n = 0;
    check(hw_render_buffers_floats(get(), to_c(which), &data, &n));
    return values_view<const float>(data, n);
  }
  /// One index array (see hw_render_buffers_indices()), valid while this object lives.
  values_view<const uint32_t> indices(RenderIndices which) const {
    const uint32_t* data = nullptr;
    std::size_t n = 0;
    check(hw_render_buffers_indices(get(), to_c(which), &data, &n));
    return values_view<const uint32_t>(data, n);
  }
  /// The number of vertices in the buffers.
  std::size_t n_vertices() const { return hw_render_buffers_n_vertices(get()); }
  /// Floats per interleaved vertex (0 for separate arrays).
  std::size_t stride() const { return hw_render_buffers_stride(get()); }
  /// The box around the vertices: {min, max}.
  std::pair<std::array<float, 3>, std::array<float, 3>> bounds() const {
    std::array<float, 3> lo{}, hi{};
    check(hw_render_buffers_bounds(get(), lo.data(), hi.data()));
    return {lo, hi};
  }
  /// The C object, still owned by these buffers.
  hw_render_buffers* get() const noexcept { return raw_.get(); }

 private:
  using owner = detail::owned<hw_render_buffers, hw_render_buffers_free>;
  explicit render_buffers(hw_render_buffers* raw) : raw_(raw) {}
  owner raw_;
};

/// Surface generators (sweeps, revolutions, ruled surfaces) and primitives; bad parameters throw
/// hw::error.
namespace surface {

/// A position, x y z.
using point = std::array<double, 3>;

namespace detail {
/// Runs a generator `call(hw_mesh** out)` and owns the mesh it makes.
template <class Call>
mesh generate(Call&& call) {
  hw_mesh* raw = nullptr;
  check(call(&raw));
  return mesh::adopt(raw);
}
inline const double* flat(const std::vector<point>& points) {
  return points.empty() ? nullptr : points.front().data();
}
}  // namespace detail

/// The regular tetrahedron (see hw_surface_tetrahedron()).
inline mesh tetrahedron() {
  return detail::generate([&](hw_mesh** out) { return hw_surface_tetrahedron(out); });
}
/// An axis-aligned cube centred at the origin, `side` long (see hw_surface_cube()).
inline mesh cube(double side = 1.0) {
  return detail::generate([&](hw_mesh** out) { return hw_surface_cube(side, out); });
}
/// An icosphere of `radius` after `level` subdivisions (see hw_surface_icosphere()).
inline mesh icosphere(double radius, uint32_t level) {
  return detail::generate([&](hw_mesh** out) { return hw_surface_icosphere(radius, level, out); });
}
/// A closed torus about the z axis (see hw_surface_torus()).
inline mesh torus(double major_radius, double minor_radius, uint32_t major_steps,
                  uint32_t minor_steps, CellFaces faces = CellFaces::Quads) {
  return detail::generate([&](hw_mesh** out) {
    return hw_surface_torus(major_radius, minor_radius, major_steps, minor_steps, to_c(faces), out);
  });
}
/// A flat grid in the plane z = 0 (see hw_surface_grid()).
inline mesh grid(double width, double height, uint32_t cells_x, uint32_t cells_y,
                 CellFaces faces = CellFaces::Quads) {
  return detail::generate([&](hw_mesh** out) {
    return hw_surface_grid(width, height, cells_x, cells_y, to_c(faces), out);
  });
}
/// `profile` swept along `direction` in `steps` rows.
inline mesh sweep(const std::vector<point>& profile, bool closed, const point& direction,
                  uint32_t steps, CellFaces faces = CellFaces::Quads) {
  return detail::generate([&](hw_mesh** out) {
    return hw_surface_sweep(detail::flat(profile), profile.size(), closed, direction.data(), steps,
                            to_c(faces), out);
  });
}
/// `profile` turned about an axis; `angle` in radians, or a full turn when `angle` is omitted.
inline mesh revolution(const std::vector<point>& profile, bool closed, const point& axis_origin,
                       const point& axis_direction, uint32_t steps, double angle = 0.0,
                       Caps caps = Caps::None, CellFaces faces = CellFaces::Quads) {
  return detail::generate([&](hw_mesh** out) {
    return hw_surface_revolution(detail::flat(profile), profile.size(), closed, axis_origin.data(),
                                 axis_direction.data(), angle == 0.0, angle, steps, to_c(caps),
                                 to_c(faces), out);
  });
}
/// Straight rulings from `first[i]` to `second[i]`.
inline mesh ruled(const std::vector<point>& first, const std::vector<point>& second, bool closed,
                  uint32_t steps, CellFaces faces = CellFaces::Quads) {
  if (first.size() != second.size())
    throw error(Status::InvalidInput, "ruled surface polylines differ in length");
  return detail::generate([&](hw_mesh** out) {
    return hw_surface_ruled(detail::flat(first), detail::flat(second), first.size(), closed, steps,
                            to_c(faces), out);
  });
}

}  // namespace surface

}  // namespace hw

#endif  // HALFWING_HPP
