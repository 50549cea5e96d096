//! `hw_render_buffers`: a mesh (or a polygon list) as arrays ready for `glBufferData`, with
//! zero-copy views of each array.

use crate::geom::VertexNormalWeighting;
use crate::render::{
    Bounds, FindingBuffers, MeshBufferOptions, MeshBuffers, PolygonBuffer, PolygonList,
    RenderError, Shading, SurfaceOptions, VertexLayout, finding_buffers, mesh_buffers,
    polygon_buffer, polygon_buffer_2d, voronoi_cell_buffer,
};

use crate::ffi::boundary::error::FfiError;
use crate::ffi::boundary::face_list::face_list_arg;
use crate::ffi::boundary::handle::{free_handle, into_handle};
use crate::ffi::boundary::status::*;
use crate::ffi::boundary::threads::with_threads;
use crate::ffi::boundary::{Out, arg_ref, arg_slice, give_view, guard, guard_value, guard_void};
use crate::ffi::doctor::{finding_kind, hw_doctor_finding, hw_doctor_report, report_ref};
use crate::ffi::mesh::diagnostic::hw_diagnostic;
use crate::ffi::mesh::lifecycle::{hw_mesh, mesh_ref};
use crate::ffi::mesh::normals::{HW_NORMAL_WEIGHTING_ANGLE, hw_normal_weighting, weighting};
use crate::ffi::voronoi::cells::{cells_ref, hw_voronoi_cells};

/// Where the normals of hw_render_buffers_build() come from.
/// \ingroup render
pub type hw_shading = u32;
/// Face normals: faceted; every vertex is split per face.
/// \ingroup render
pub const HW_SHADING_FLAT: hw_shading = 0;
/// Vertex normals with the options' weighting: one render vertex per mesh vertex.
/// \ingroup render
pub const HW_SHADING_SMOOTH: hw_shading = 1;
/// Smooth within regions bounded by edges sharper than the options' crease angle; vertices are
/// split along those edges only.
/// \ingroup render
pub const HW_SHADING_CREASE: hw_shading = 2;
/// The default: the options' `corner_normals`, else the mesh's own corner normals (a file's `vn`,
/// hw_mesh_corner_normals_set()) when `mesh_corner_normals` is true, scaled to unit length. A
/// corner without one — none given, or a zero vector (how a mesh read from an OBJ stores the
/// corners its file gives no normal) or a NaN or infinite one — takes the smooth normal with the
/// options' weighting. ::HW_SHADING_FLAT, ::HW_SHADING_SMOOTH and ::HW_SHADING_CREASE ignore
/// those normals and compute every normal from the positions.
/// \ingroup render
pub const HW_SHADING_CORNER_NORMALS: hw_shading = 3;

/// How hw_render_buffers_build() builds its arrays. Start from hw_render_options_default().
/// \ingroup render
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct hw_render_options {
    /// ::HW_SHADING_CORNER_NORMALS (the default), ::HW_SHADING_FLAT, ::HW_SHADING_SMOOTH or
    /// ::HW_SHADING_CREASE.
    pub shading: hw_shading,
    /// Weighting of smooth shading (also where ::HW_SHADING_CORNER_NORMALS has no normal) and of
    /// the vertex-normal glyphs (::HW_NORMAL_WEIGHTING_UNIFORM, ::HW_NORMAL_WEIGHTING_AREA,
    /// ::HW_NORMAL_WEIGHTING_ANGLE).
    pub weighting: hw_normal_weighting,
    /// For ::HW_SHADING_CREASE: the dihedral angle in radians (≥ 0) above which an edge is sharp.
    pub crease_angle: f64,
    /// `true`: one ::HW_RENDER_FLOATS_INTERLEAVED array (x y z nx ny nz [u v] per vertex); `false`:
    /// separate ::HW_RENDER_FLOATS_POSITIONS, ::HW_RENDER_FLOATS_NORMALS and ::HW_RENDER_FLOATS_UVS
    /// arrays.
    pub interleaved: bool,
    /// Length of the normal glyphs; 0 takes the mesh's mean edge length.
    pub normal_length: f64,
    /// With ::HW_SHADING_CORNER_NORMALS: use the mesh's own corner normals (a file's `vn`,
    /// hw_mesh_corner_normals_set()) when it has them and `corner_normals` is NULL. The other
    /// shadings ignore them.
    pub mesh_corner_normals: bool,
    /// Give the vertices the mesh's own corner texture coordinates, when it has them and
    /// `corner_uvs` is NULL (a mesh read from an OBJ has (0, 0) at the corners its file gives
    /// none).
    pub mesh_corner_uvs: bool,
    /// NULL, or `3 * n_corners` doubles: a normal per half-edge slot (the corner at the
    /// half-edge's origin), used by ::HW_SHADING_CORNER_NORMALS instead of the mesh's own; a
    /// zero vector means the corner has none. The other shadings ignore it.
    pub corner_normals: *const f64,
    /// NULL, or `2 * n_corners` doubles: a texture coordinate per half-edge slot; the vertices
    /// then carry uvs, as given.
    pub corner_uvs: *const f64,
    /// Half-edge slots in `corner_normals` and `corner_uvs`: must be
    /// `hw_mesh_n_halfedge_slots(mesh)` when either is given.
    pub n_corners: usize,
}

/// The default options: ::HW_SHADING_CORNER_NORMALS (the mesh's own corner normals where it has
/// them, smooth angle-weighted normals elsewhere), a crease angle of 30°, separate arrays,
/// glyphs as long as the mean edge; the mesh's own corner uvs when it has them, no other
/// per-corner attributes.
/// \ingroup render
#[unsafe(no_mangle)]
pub extern "C" fn hw_render_options_default() -> hw_render_options {
    hw_render_options {
        shading: HW_SHADING_CORNER_NORMALS,
        weighting: HW_NORMAL_WEIGHTING_ANGLE,
        crease_angle: 30f64.to_radians(),
        interleaved: false,
        normal_length: 0.0,
        mesh_corner_normals: true,
        mesh_corner_uvs: true,
        corner_normals: std::ptr::null(),
        corner_uvs: std::ptr::null(),
        n_corners: 0,
    }
}

/// What a render-buffer object was built from.
enum Contents {
    Mesh(Box<MeshBuffers>),
    Polygons(Box<PolygonBuffer>),
    Finding(Box<FindingBuffers>),
}

/// GPU-ready arrays of a mesh or a polygon list. Opaque; from hw_render_buffers_build(),
/// hw_render_buffers_from_polygons() or hw_render_buffers_from_voronoi_cells(); release with
/// hw_render_buffers_free(). Immutable: its views stay valid until it is freed, also after the mesh
/// it came from changes or is freed.
/// \ingroup render
pub struct hw_render_buffers {
    contents: Contents,
}

impl From<RenderError> for FfiError {
    fn from(error: RenderError) -> Self {
        match error {
            RenderError::OutOfMemory(refusal) => refusal.into(),
            _ => FfiError::invalid_input(error.to_string()),
        }
    }
}

/// The `float` arrays of a render-buffer object (see hw_render_buffers_floats()). Lengths are in
/// floats.
/// \ingroup render
pub type hw_render_floats = u32;
/// x y z per vertex (separate layout; empty when interleaved).
/// \ingroup render
pub const HW_RENDER_FLOATS_POSITIONS: hw_render_floats = 0;
/// Unit nx ny nz per vertex (separate layout; empty when interleaved).
/// \ingroup render
pub const HW_RENDER_FLOATS_NORMALS: hw_render_floats = 1;
/// u v per vertex (separate layout with corner uvs; empty otherwise).
/// \ingroup render
pub const HW_RENDER_FLOATS_UVS: hw_render_floats = 2;
/// hw_render_buffers_stride() floats per vertex: x y z nx ny nz [u v] (interleaved layout).
/// \ingroup render
pub const HW_RENDER_FLOATS_INTERLEAVED: hw_render_floats = 3;
/// `GL_LINES` points, x y z, two per segment: every edge (a polygon list: every polygon side).
/// \ingroup render
pub const HW_RENDER_FLOATS_WIREFRAME: hw_render_floats = 4;
/// `GL_LINES` points of the boundary edges (edges with a face on one side only).
/// \ingroup render
pub const HW_RENDER_FLOATS_BOUNDARY: hw_render_floats = 5;
/// `GL_LINES` points of the non-manifold edges reported by the diagnostic given to the build.
/// \ingroup render
pub const HW_RENDER_FLOATS_NON_MANIFOLD: hw_render_floats = 6;
/// `GL_LINES` glyphs of the vertex normals, from each vertex along its normal.
/// \ingroup render
pub const HW_RENDER_FLOATS_VERTEX_NORMALS: hw_render_floats = 7;
/// `GL_LINES` glyphs of the face normals, from each face's centroid.
/// \ingroup render
pub const HW_RENDER_FLOATS_FACE_NORMALS: hw_render_floats = 8;
/// `GL_POINTS` points, x y z: the vertices a doctor's finding names
/// (hw_render_buffers_from_finding(); empty otherwise).
/// \ingroup render
pub const HW_RENDER_FLOATS_POINTS: hw_render_floats = 9;

/// The `uint32_t` arrays of a render-buffer object (see hw_render_buffers_indices()).
/// \ingroup render
pub type hw_render_indices = u32;
/// Three vertex indices per triangle, counter-clockwise from outside: the element buffer.
/// \ingroup render
pub const HW_RENDER_INDICES_TRIANGLES: hw_render_indices = 0;
/// Per triangle, the mesh face (or polygon) it comes from.
/// \ingroup render
pub const HW_RENDER_INDICES_TRIANGLE_FACES: hw_render_indices = 1;
/// Per vertex, the mesh vertex (or polygon) it shows.
/// \ingroup render
pub const HW_RENDER_INDICES_VERTEX_SOURCES: hw_render_indices = 2;
/// Per ::HW_RENDER_FLOATS_WIREFRAME segment, its edge id (or polygon).
/// \ingroup render
pub const HW_RENDER_INDICES_WIREFRAME_SOURCES: hw_render_indices = 3;
/// Per ::HW_RENDER_FLOATS_BOUNDARY segment, its edge id.
/// \ingroup render
pub const HW_RENDER_INDICES_BOUNDARY_SOURCES: hw_render_indices = 4;
/// Per ::HW_RENDER_FLOATS_POINTS point, the item of the finding it shows.
/// \ingroup render
pub const HW_RENDER_INDICES_POINT_SOURCES: hw_render_indices = 5;

fn float_array(contents: &Contents, which: hw_render_floats) -> Result<&[f32], FfiError> {
    if which > HW_RENDER_FLOATS_POINTS {
        return Err(FfiError::invalid_input(format!(
            "unknown render float array {which}"
        )));
    }
    Ok(match contents {
        Contents::Mesh(buffers) => match which {
            HW_RENDER_FLOATS_POSITIONS => &buffers.surface.positions,
            HW_RENDER_FLOATS_NORMALS => &buffers.surface.normals,
            HW_RENDER_FLOATS_UVS => &buffers.surface.uvs,
            HW_RENDER_FLOATS_INTERLEAVED => &buffers.surface.interleaved,
            HW_RENDER_FLOATS_WIREFRAME => &buffers.wireframe.positions,
            HW_RENDER_FLOATS_BOUNDARY => &buffers.boundary.positions,
            HW_RENDER_FLOATS_NON_MANIFOLD => &buffers.non_manifold.positions,
            HW_RENDER_FLOATS_VERTEX_NORMALS => &buffers.vertex_normals.positions,
            HW_RENDER_FLOATS_FACE_NORMALS => &buffers.face_normals.positions,
            _ => &[],
        },
        Contents::Polygons(polygons) => match which {
            HW_RENDER_FLOATS_POSITIONS => &polygons.positions,
            HW_RENDER_FLOATS_NORMALS => &polygons.normals,
            HW_RENDER_FLOATS_WIREFRAME => &polygons.outline.positions,
            _ => &[],
        },
        Contents::Finding(finding) => match which {
            HW_RENDER_FLOATS_POSITIONS => &finding.faces.positions,
            HW_RENDER_FLOATS_NORMALS => &finding.faces.normals,
            HW_RENDER_FLOATS_WIREFRAME => &finding.faces.outline.positions,
            HW_RENDER_FLOATS_BOUNDARY => &finding.lines.positions,
            HW_RENDER_FLOATS_POINTS => &finding.points,
            _ => &[],
        },
    })
}

fn index_array(contents: &Contents, which: hw_render_indices) -> Result<&[u32], FfiError> {
    if which > HW_RENDER_INDICES_POINT_SOURCES {
        return Err(FfiError::invalid_input(format!(
            "unknown render index array {which}"
        )));
    }
    Ok(match contents {
        Contents::Mesh(buffers) => match which {
            HW_RENDER_INDICES_TRIANGLES => &buffers.surface.triangles,
            HW_RENDER_INDICES_TRIANGLE_FACES => &buffers.surface.triangle_faces,
            HW_RENDER_INDICES_VERTEX_SOURCES => &buffers.surface.vertex_sources,
            HW_RENDER_INDICES_WIREFRAME_SOURCES => &buffers.wireframe.sources,
            HW_RENDER_INDICES_BOUNDARY_SOURCES => &buffers.boundary.sources,
            _ => &[],
        },
        Contents::Polygons(polygons) => match which {
            HW_RENDER_INDICES_TRIANGLES => &polygons.triangles,
            HW_RENDER_INDICES_TRIANGLE_FACES => &polygons.triangle_polygons,
            HW_RENDER_INDICES_VERTEX_SOURCES => &polygons.vertex_polygons,
            HW_RENDER_INDICES_WIREFRAME_SOURCES => &polygons.outline.sources,
            _ => &[],
        },
        Contents::Finding(finding) => match which {
            HW_RENDER_INDICES_TRIANGLES => &finding.faces.triangles,
            HW_RENDER_INDICES_TRIANGLE_FACES => &finding.faces.triangle_polygons,
            HW_RENDER_INDICES_VERTEX_SOURCES => &finding.faces.vertex_polygons,
            HW_RENDER_INDICES_WIREFRAME_SOURCES => &finding.faces.outline.sources,
            HW_RENDER_INDICES_BOUNDARY_SOURCES => &finding.lines.sources,
            HW_RENDER_INDICES_POINT_SOURCES => &finding.point_items,
            _ => &[],
        },
    })
}

fn shading(options: &hw_render_options) -> Result<Shading, FfiError> {
    match options.shading {
        HW_SHADING_FLAT => Ok(Shading::Flat),
        HW_SHADING_SMOOTH => Ok(Shading::Smooth(weighting(options.weighting)?)),
        HW_SHADING_CREASE => Ok(Shading::Crease(options.crease_angle)),
        HW_SHADING_CORNER_NORMALS => Ok(Shading::CornerNormals(weighting(options.weighting)?)),
        other => Err(FfiError::invalid_input(format!("unknown shading {other}"))),
    }
}

/// Builds the render buffers of a mesh: the triangulated surface (every polygon, non-convex ones
/// included, in O(n log n) for n corners), its vertex attributes as `float`, the wireframe, the
/// boundary, the non-manifold edges of `diagnostic` and the normal glyphs.
///
/// `diagnostic` may be NULL (no non-manifold edges then); when given it must be the one the
/// mesh's build returned (load with ::HW_BUILD_POLICY_REPAIR or ::HW_BUILD_POLICY_SKIP to see the
/// non-manifold edges of a file). `options` may be NULL for hw_render_options_default(). Bad
/// options (an unknown shading or weighting, a negative or non-finite crease angle or glyph length,
/// corner arrays of the wrong size) give `HW_ERR_INVALID_INPUT`.
///
/// Draw the surface with `glDrawElements(GL_TRIANGLES, n, GL_UNSIGNED_INT, 0)` after uploading
/// ::HW_RENDER_INDICES_TRIANGLES as the element buffer, and each line set with
/// `glDrawArrays(GL_LINES, 0, len / 3)`.
///
/// # Safety
/// `mesh` must be NULL or live; `diagnostic` NULL or live; `options` NULL or readable, with its
/// corner arrays NULL or as long as it says; `out_buffers` writable.
/// \ingroup render
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_render_buffers_build(
    mesh: *const hw_mesh,
    diagnostic: *const hw_diagnostic,
    options: *const hw_render_options,
    out_buffers: *mut *mut hw_render_buffers,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_buffers, "out_buffers")?;
        // SAFETY: forwarded from the caller.
        let mesh = unsafe { mesh_ref(mesh) }?;
        // SAFETY: NULL or live per the caller.
        let diagnostic = unsafe { diagnostic.as_ref() }.map(|d| &d.diagnostic);
        // SAFETY: NULL or readable per the caller.
        let options = unsafe { options.as_ref() }
            .copied()
            .unwrap_or_else(|| hw_render_options_default());
        let glyph_length = (options.normal_length != 0.0).then_some(options.normal_length);
        // SAFETY: the arrays hold `n_corners` entries per the caller.
        let (corner_normals, corner_uvs) = unsafe {
            (
                corner_array::<3>(options.corner_normals, options.n_corners, "corner_normals")?,
                corner_array::<2>(options.corner_uvs, options.n_corners, "corner_uvs")?,
            )
        };
        // Explicit arrays first, then the mesh's own attributes when asked for.
        let corner_normals = corner_normals.or_else(|| {
            options
                .mesh_corner_normals
                .then(|| mesh.corner_normals())
                .flatten()
        });
        let corner_uvs =
            corner_uvs.or_else(|| options.mesh_corner_uvs.then(|| mesh.corner_uvs()).flatten());
        let glyph_weighting: VertexNormalWeighting = weighting(options.weighting)?;
        let mesh_options = MeshBufferOptions {
            surface: SurfaceOptions {
                shading: shading(&options)?,
                layout: if options.interleaved {
                    VertexLayout::Interleaved
                } else {
                    VertexLayout::Separate
                },
                corner_normals,
                corner_uvs,
            },
            glyph_weighting,
            glyph_length,
        };
        let buffers = with_threads(|| mesh_buffers(mesh, diagnostic, &mesh_options))?;
        // SAFETY: checked non-NULL; writable per the caller.
        unsafe {
            out.write(into_handle(hw_render_buffers {
                contents: Contents::Mesh(Box::new(buffers)),
            }))
        };
        Ok(())
    })
}

/// Borrows an optional per-corner array of `N` doubles per corner.
///
/// # Safety
/// `data` must be NULL or point to `N * n_corners` doubles.
unsafe fn corner_array<'a, const N: usize>(
    data: *const f64,
    n_corners: usize,
    name: &str,
) -> Result<Option<&'a [[f64; N]]>, FfiError> {
    if data.is_null() {
        return Ok(None);
    }
    // SAFETY: forwarded from the caller; `[f64; N]` has the alignment of `f64`.
    Ok(Some(unsafe {
        arg_slice(data.cast::<[f64; N]>(), n_corners, name)
    }?))
}

/// Builds fill and outline buffers of a list of polygons — Voronoi cells, regions, any polygons:
/// ::HW_RENDER_FLOATS_POSITIONS and ::HW_RENDER_FLOATS_NORMALS (each polygon's own corners, so
/// polygons can be coloured apart; normals are the polygons' unit normals, +z for counter-clockwise
/// 2D input), ::HW_RENDER_INDICES_TRIANGLES (every polygon triangulated) with
/// ::HW_RENDER_INDICES_TRIANGLE_FACES and ::HW_RENDER_INDICES_VERTEX_SOURCES naming polygons, and
/// the outlines as ::HW_RENDER_FLOATS_WIREFRAME. The other arrays are empty, and the layout is
/// always separate.
///
/// `corners` holds `dimension * n_corners` doubles (`dimension` 2: x y in the plane z = 0;
/// 3: x y z), polygon after polygon; polygon `i` has `sizes[i]` corners, and the sizes must add
/// up to `n_corners`. A polygon of fewer than 3 corners or a NaN or infinite coordinate is
/// refused too; each of these gives `HW_ERR_INVALID_INPUT` with a message naming the polygon
/// (and the corner within it).
///
/// # Safety
/// `corners` must hold `dimension * n_corners` doubles and `sizes` `n_polygons` values (either
/// may be NULL when its count is 0); `out_buffers` writable.
/// \ingroup render
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_render_buffers_from_polygons(
    corners: *const f64,
    dimension: u32,
    n_corners: usize,
    sizes: *const u32,
    n_polygons: usize,
    out_buffers: *mut *mut hw_render_buffers,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_buffers, "out_buffers")?;
        if !(2..=3).contains(&dimension) {
            return Err(FfiError::invalid_input(format!(
                "dimension must be 2 or 3, got {dimension}"
            )));
        }
        // SAFETY: forwarded from the caller; the point arrays have the alignment of `f64`.
        let sizes = unsafe { arg_slice(sizes, n_polygons, "sizes") }?;
        let buffer = if dimension == 2 {
            // SAFETY: as above.
            let planar = unsafe { arg_slice(corners.cast::<[f64; 2]>(), n_corners, "corners") }?;
            polygon_buffer_2d(planar, sizes)?
        } else {
            // SAFETY: as above.
            let spatial = unsafe { arg_slice(corners.cast::<[f64; 3]>(), n_corners, "corners") }?;
            polygon_buffer(&PolygonList {
                corners: spatial,
                sizes,
            })?
        };
        // SAFETY: checked non-NULL; writable per the caller.
        unsafe {
            out.write(into_handle(hw_render_buffers {
                contents: Contents::Polygons(Box::new(buffer)),
            }))
        };
        Ok(())
    })
}

/// Builds fill and outline buffers of the clipped cells of a Voronoi diagram, as
/// hw_render_buffers_from_polygons() would from its cells: polygon `i` is the cell of site `i`,
/// so ::HW_RENDER_INDICES_TRIANGLE_FACES, ::HW_RENDER_INDICES_VERTEX_SOURCES and
/// ::HW_RENDER_INDICES_WIREFRAME_SOURCES name sites (colour a cell by its site). Each cell gets its
/// own copies of its corners (z = 0, normals +z); an empty cell (a duplicate site, or a cell
/// outside the clip region) has no triangle and no outline. The buffers do not depend on `cells`
/// afterwards.
///
/// # Safety
/// `cells` must be NULL or a live `hw_voronoi_cells`; `out_buffers` writable.
/// \ingroup render
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_render_buffers_from_voronoi_cells(
    cells: *const hw_voronoi_cells,
    out_buffers: *mut *mut hw_render_buffers,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_buffers, "out_buffers")?;
        // SAFETY: forwarded from the caller.
        let cells = unsafe { cells_ref(cells) }?;
        let buffer = voronoi_cell_buffer(cells)?;
        // SAFETY: checked non-NULL; writable per the caller.
        unsafe {
            out.write(into_handle(hw_render_buffers {
                contents: Contents::Polygons(Box::new(buffer)),
            }))
        };
        Ok(())
    })
}

/// Builds the buffers that draw one kind of finding of a doctor's report over the face list it
/// examined (the same arrays as given to hw_doctor_examine_indexed()):
/// - the faces it names, each once with its own corners, as ::HW_RENDER_FLOATS_POSITIONS,
///   ::HW_RENDER_FLOATS_NORMALS and ::HW_RENDER_INDICES_TRIANGLES, outlined by
///   ::HW_RENDER_FLOATS_WIREFRAME; ::HW_RENDER_INDICES_TRIANGLE_FACES,
///   ::HW_RENDER_INDICES_VERTEX_SOURCES and ::HW_RENDER_INDICES_WIREFRAME_SOURCES name faces of the
///   list;
/// - the edges it names, and the 12 edges of the bounding box of each small component, as
///   ::HW_RENDER_FLOATS_BOUNDARY segments, whose ::HW_RENDER_INDICES_BOUNDARY_SOURCES are item
///   indices of the finding;
/// - the vertices it names as ::HW_RENDER_FLOATS_POINTS, with ::HW_RENDER_INDICES_POINT_SOURCES
///   (items).
///
/// What each kind names: faces for the orientation witness, needles, caps, duplicate faces and
/// intersecting face pairs; the edge and its two faces for folded edges; the edge for long
/// edges; the vertex for zero-length edges; the vertex and an edge to the vertex it repeats for
/// duplicate positions and near duplicates; the vertex and the edge it lies on for T-vertices.
/// Faces, edges and vertices on NaN or infinite positions cannot be drawn and are left out.
/// `HW_ERR_INVALID_INPUT` for an unknown kind, a report that names a face or vertex the list
/// does not have (it is another list's report) or sizes that do not add up to `n_indices`.
///
/// # Safety
/// `report` must be NULL or live; the arrays as for hw_mesh_from_indexed(); `out_buffers`
/// writable.
/// \ingroup render
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_render_buffers_from_finding(
    report: *const hw_doctor_report,
    kind: hw_doctor_finding,
    positions: *const f64,
    n_vertices: usize,
    face_sizes: *const u32,
    n_faces: usize,
    indices: *const u32,
    n_indices: usize,
    out_buffers: *mut *mut hw_render_buffers,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_buffers, "out_buffers")?;
        // SAFETY: forwarded from the caller.
        let (report, list) = unsafe {
            (
                report_ref(report)?,
                face_list_arg(
                    positions, n_vertices, face_sizes, n_faces, indices, n_indices,
                )?,
            )
        };
        let buffers = finding_buffers(report, finding_kind(kind)?, &list)?;
        // SAFETY: checked non-NULL; writable per the caller.
        unsafe {
            out.write(into_handle(hw_render_buffers {
                contents: Contents::Finding(Box::new(buffers)),
            }))
        };
        Ok(())
    })
}

/// Releases render buffers (their views die with them). NULL is a no-op; a second free is
/// refused (within the limits the ownership conventions at the top of the header state).
///
/// # Safety
/// `buffers` must be NULL or from this library, not in use by another thread.
/// \ingroup render
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_render_buffers_free(buffers: *mut hw_render_buffers) {
    // SAFETY: forwarded from the caller.
    guard_void(|| unsafe { free_handle(buffers, "hw_render_buffers") });
}

/// Borrows the contents of a `const hw_render_buffers *` argument.
///
/// # Safety
/// `buffers` must be NULL or live.
unsafe fn contents_ref<'a>(buffers: *const hw_render_buffers) -> Result<&'a Contents, FfiError> {
    // SAFETY: forwarded from the caller.
    Ok(&unsafe { arg_ref(buffers, "buffers") }?.contents)
}

/// A zero-copy view of one `float` array: `*out_data` (NULL when empty) and its length in floats
/// `*out_len`, ready for `glBufferData(GL_ARRAY_BUFFER, *out_len * sizeof(float), *out_data, ...)`.
///
/// # Safety
/// `buffers` must be NULL or live; `out_data` and `out_len` writable.
/// \ingroup render
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_render_buffers_floats(
    buffers: *const hw_render_buffers,
    which: hw_render_floats,
    out_data: *mut *const f32,
    out_len: *mut usize,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe {
        give_view(out_data, "out_data", out_len, || {
            float_array(contents_ref(buffers)?, which)
        })
    }
}

/// A zero-copy view of one `uint32_t` array: `*out_data` (NULL when empty) and its length
/// `*out_len` in elements (three per triangle for ::HW_RENDER_INDICES_TRIANGLES).
///
/// # Safety
/// `buffers` must be NULL or live; `out_data` and `out_len` writable.
/// \ingroup render
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_render_buffers_indices(
    buffers: *const hw_render_buffers,
    which: hw_render_indices,
    out_data: *mut *const u32,
    out_len: *mut usize,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe {
        give_view(out_data, "out_data", out_len, || {
            index_array(contents_ref(buffers)?, which)
        })
    }
}

/// Number of render vertices (entries of the per-vertex arrays); 0 for NULL.
///
/// # Safety
/// `buffers` must be NULL or live.
/// \ingroup render
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_render_buffers_n_vertices(buffers: *const hw_render_buffers) -> usize {
    // SAFETY: forwarded from the caller.
    guard_value(0, || {
        Ok(match unsafe { contents_ref(buffers) }? {
            Contents::Mesh(buffers) => buffers.surface.n_vertices(),
            Contents::Polygons(polygons) => polygons.vertex_polygons.len(),
            Contents::Finding(finding) => finding.faces.vertex_polygons.len(),
        })
    })
}

/// Floats per vertex of ::HW_RENDER_FLOATS_INTERLEAVED (6: x y z nx ny nz; 8 with uvs), 0 when the
/// arrays are separate; 0 for NULL. The byte stride of `glVertexAttribPointer` is this times
/// `sizeof(float)`; normals start at float 3 and uvs at float 6.
///
/// # Safety
/// `buffers` must be NULL or live.
/// \ingroup render
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_render_buffers_stride(buffers: *const hw_render_buffers) -> usize {
    // SAFETY: forwarded from the caller.
    guard_value(0, || {
        Ok(match unsafe { contents_ref(buffers) }? {
            Contents::Mesh(buffers) if !buffers.surface.interleaved.is_empty() => {
                buffers.surface.stride
            }
            _ => 0,
        })
    })
}

/// The box around the vertices, to frame a camera: `out_min` and `out_max` receive x y z each.
/// With no vertex, min is +infinity and max -infinity. Both outputs are required: NULL for
/// either gives `HW_ERR_NULL_ARGUMENT` and writes neither.
///
/// # Safety
/// `buffers` must be NULL or live; `out_min` and `out_max` must each point to 3 writable floats.
/// \ingroup render
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_render_buffers_bounds(
    buffers: *const hw_render_buffers,
    out_min: *mut f32,
    out_max: *mut f32,
) -> hw_status {
    guard(|| {
        let (out_min, out_max) = (
            Out::new(out_min.cast::<[f32; 3]>(), "out_min")?,
            Out::new(out_max.cast::<[f32; 3]>(), "out_max")?,
        );
        // SAFETY: forwarded from the caller.
        let bounds: Bounds = match unsafe { contents_ref(buffers) }? {
            Contents::Mesh(buffers) => buffers.surface.bounds,
            Contents::Polygons(polygons) => polygons.bounds,
            Contents::Finding(finding) => finding.bounds,
        };
        // SAFETY: checked non-NULL; 3 writable floats per the caller (alignment of f32).
        unsafe {
            out_min.write(bounds.min);
            out_max.write(bounds.max);
        }
        Ok(())
    })
}
