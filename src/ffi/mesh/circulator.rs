//! Stack circulators: walk around a vertex, around a face or along a loop from C.
//!
//! ```c
//! hw_circulator c;
//! hw_vertex w;
//! if (hw_circ_around_vertex(mesh, v, HW_CIRCULATOR_KIND_VERTICES, &c) == HW_OK)
//!   while (hw_circ_next_vertex(&c, &w)) visit(w);
//! ```
//! Orders: around a vertex, counter-clockwise seen from outside starting at
//! hw_mesh_vertex_halfedge() (the boundary half-edge on a boundary, so a fan is seen whole;
//! at a non-manifold vertex only that half-edge's fan); around a face, counter-clockwise from
//! hw_mesh_face_halfedge(); along a loop, by `next`. Every walk is bounded by the number of
//! half-edges, so a corrupt mesh ends a walk instead of looping.

use crate::mesh::{EdgeId, FaceId, HalfedgeId, Mesh, Step, VertexId, WalkState};

use crate::ffi::boundary::error::FfiError;
use crate::ffi::boundary::status::hw_status;
use crate::ffi::boundary::{Out, arg_mut, guard, next_element};
use crate::ffi::mesh::elements::{HW_INVALID_INDEX, hw_edge, hw_face, hw_halfedge, hw_vertex};
use crate::ffi::mesh::lifecycle::{hw_mesh, mesh_ref};

/// What a circulator yields.
/// \ingroup circulators
pub type hw_circulator_kind = u32;
/// Half-edges: a vertex's outgoing ones, a face's sides, a loop's members.
/// \ingroup circulators
pub const HW_CIRCULATOR_KIND_HALFEDGES: hw_circulator_kind = 0;
/// Around a vertex only: the incoming half-edges (twins of the outgoing ones).
/// \ingroup circulators
pub const HW_CIRCULATOR_KIND_INCOMING: hw_circulator_kind = 1;
/// Vertices: a vertex's neighbours, a face's corners.
/// \ingroup circulators
pub const HW_CIRCULATOR_KIND_VERTICES: hw_circulator_kind = 2;
/// Edges: at a vertex, or the sides of a face.
/// \ingroup circulators
pub const HW_CIRCULATOR_KIND_EDGES: hw_circulator_kind = 3;
/// Faces: around a vertex (outside skipped), or across a face's sides (boundary sides skipped).
/// \ingroup circulators
pub const HW_CIRCULATOR_KIND_FACES: hw_circulator_kind = 4;

/// What a walk circles.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Center {
    Vertex = 0,
    Face = 1,
    Loop = 2,
}

/// A circulator's state, kept on the caller's stack. Fill it with hw_circ_around_vertex(),
/// hw_circ_around_face() or hw_circ_along_loop(); read it with the `hw_circ_next_*` call of its
/// kind. Treat the fields as private. It borrows the mesh: do not modify the mesh while walking.
/// \ingroup circulators
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct hw_circulator {
    /// The mesh walked.
    pub mesh: *const hw_mesh,
    /// The half-edge the walk started at; reaching it again ends the walk.
    pub start: u32,
    /// The half-edge the walk yields next, or `HW_INVALID_INDEX` once it is over.
    pub current: u32,
    /// Steps left before the bound on a walk's length stops it (a corrupt cycle cannot hang).
    pub remaining: u32,
    /// What it walks around: a vertex, a face or a boundary loop (internal code).
    pub center: u32,
    /// What it yields.
    pub kind: hw_circulator_kind,
}

/// Starts a circulator of `kind` around `center`, from the half-edge `start` finds on the mesh, and
/// writes it through `out` (only on success).
///
/// # Safety
/// `raw_mesh` must be NULL or a live mesh; `out` NULL or writable.
unsafe fn begin(
    raw_mesh: *const hw_mesh,
    center: Center,
    kind: hw_circulator_kind,
    out: *mut hw_circulator,
    start: impl FnOnce(&Mesh) -> Result<HalfedgeId, FfiError>,
) -> hw_status {
    guard(|| {
        let out = Out::new(out, "out")?;
        // SAFETY: forwarded from the caller.
        let mesh = unsafe { mesh_ref(raw_mesh) }?;
        let allowed = match center {
            Center::Vertex => kind <= HW_CIRCULATOR_KIND_FACES,
            Center::Face => kind <= HW_CIRCULATOR_KIND_FACES && kind != HW_CIRCULATOR_KIND_INCOMING,
            Center::Loop => kind == HW_CIRCULATOR_KIND_HALFEDGES,
        };
        if !allowed {
            return Err(FfiError::invalid_input(format!(
                "circulator kind {kind} does not apply here"
            )));
        }
        let step = if center == Center::Vertex {
            Step::Ring
        } else {
            Step::Loop
        };
        let progress = mesh.walk(start(mesh)?, step).state();
        let circulator = hw_circulator {
            mesh: raw_mesh,
            start: progress.start,
            current: progress.current,
            remaining: u32::try_from(progress.remaining).unwrap_or(u32::MAX),
            center: center as u32,
            kind,
        };
        // SAFETY: checked non-NULL, writable per the caller.
        unsafe { out.write(circulator) };
        Ok(())
    })
}

/// Starts a walk around vertex `v`. An isolated vertex gives an empty walk.
///
/// # Safety
/// `mesh` must be NULL or a live mesh; `out` writable.
/// \ingroup circulators
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_circ_around_vertex(
    mesh: *const hw_mesh,
    v: hw_vertex,
    kind: hw_circulator_kind,
    out: *mut hw_circulator,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe {
        begin(mesh, Center::Vertex, kind, out, |m| {
            Ok(m.try_vertex_halfedge(v.into())?)
        })
    }
}

/// Starts a walk around face `f`.
///
/// # Safety
/// `mesh` must be NULL or a live mesh; `out` writable.
/// \ingroup circulators
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_circ_around_face(
    mesh: *const hw_mesh,
    f: hw_face,
    kind: hw_circulator_kind,
    out: *mut hw_circulator,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe {
        begin(mesh, Center::Face, kind, out, |m| {
            Ok(m.try_face_halfedge(f.into())?)
        })
    }
}

/// Starts a walk by `next` from `h`: a face's sides, or a whole boundary loop when `h` is a
/// boundary half-edge. Yields half-edges (`kind` is ::HW_CIRCULATOR_KIND_HALFEDGES).
///
/// # Safety
/// `mesh` must be NULL or a live mesh; `out` writable.
/// \ingroup circulators
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_circ_along_loop(
    mesh: *const hw_mesh,
    h: hw_halfedge,
    out: *mut hw_circulator,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe {
        begin(mesh, Center::Loop, HW_CIRCULATOR_KIND_HALFEDGES, out, |m| {
            Ok(m.check_halfedge(h.into())?)
        })
    }
}

/// Advances `circulator` (which must yield `kind`) to the next element: `Some(id)` or `None` when
/// the walk is over.
///
/// # Safety
/// `circulator` must be NULL or point to a circulator whose mesh is still live.
pub(crate) unsafe fn advance(
    circulator: *mut hw_circulator,
    kind: hw_circulator_kind,
) -> Result<Option<u32>, FfiError> {
    // SAFETY: forwarded from the caller.
    let c = unsafe { arg_mut(circulator, "circulator") }?;
    let yields_halfedges =
        kind == HW_CIRCULATOR_KIND_HALFEDGES && c.kind == HW_CIRCULATOR_KIND_INCOMING;
    if c.kind != kind && !yields_halfedges {
        return Err(FfiError::invalid_input(format!(
            "circulator of kind {} read as kind {kind}",
            c.kind
        )));
    }
    // SAFETY: the circulator's mesh is live per the caller.
    let mesh = unsafe { mesh_ref(c.mesh) }?;
    let step = if c.center == Center::Vertex as u32 {
        Step::Ring
    } else {
        Step::Loop
    };
    let progress = WalkState {
        start: c.start,
        current: c.current,
        remaining: c.remaining as usize,
        step,
    };
    let mut walk = mesh.resume_walk(progress);
    let on_face = c.center == Center::Face as u32;
    let mut found = None;
    for h in walk.by_ref() {
        let id = match c.kind {
            HW_CIRCULATOR_KIND_HALFEDGES => h.0,
            HW_CIRCULATOR_KIND_INCOMING => h.twin().0,
            HW_CIRCULATOR_KIND_VERTICES if on_face => mesh.origin(h).0,
            HW_CIRCULATOR_KIND_VERTICES => mesh.target(h).0,
            HW_CIRCULATOR_KIND_EDGES => h.edge().0,
            HW_CIRCULATOR_KIND_FACES if on_face => mesh.face(h.twin()).0,
            _ => mesh.face(h).0,
        };
        // Faces skip the outside; every other kind yields each step.
        if id != HW_INVALID_INDEX {
            found = Some(id);
            break;
        }
    }
    let progress = walk.state();
    c.current = progress.current;
    c.remaining = progress.remaining as u32;
    Ok(found)
}

/// Writes the next element of a circulator through `out` (see `next_element`).
///
/// # Safety
/// As for `advance`; `out` NULL or writable.
unsafe fn next_into<T>(
    circulator: *mut hw_circulator,
    kind: hw_circulator_kind,
    out: *mut T,
    wrap: impl FnOnce(u32) -> T,
) -> bool {
    // SAFETY: forwarded from the caller.
    unsafe { next_element(out, || Ok(advance(circulator, kind)?.map(wrap))) }
}

/// Next half-edge of a ::HW_CIRCULATOR_KIND_HALFEDGES or ::HW_CIRCULATOR_KIND_INCOMING circulator.
///
/// # Safety
/// `circulator` must be NULL or a circulator over a live, unmodified mesh; `out` writable.
/// \ingroup circulators
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_circ_next_halfedge(
    circulator: *mut hw_circulator,
    out: *mut hw_halfedge,
) -> bool {
    unsafe {
        next_into(circulator, HW_CIRCULATOR_KIND_HALFEDGES, out, |idx| {
            HalfedgeId(idx).into()
        })
    }
}

/// Next vertex of a ::HW_CIRCULATOR_KIND_VERTICES circulator.
///
/// # Safety
/// `circulator` must be NULL or a circulator over a live, unmodified mesh; `out` writable.
/// \ingroup circulators
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_circ_next_vertex(
    circulator: *mut hw_circulator,
    out: *mut hw_vertex,
) -> bool {
    unsafe {
        next_into(circulator, HW_CIRCULATOR_KIND_VERTICES, out, |idx| {
            VertexId(idx).into()
        })
    }
}

/// Next edge of a ::HW_CIRCULATOR_KIND_EDGES circulator.
///
/// # Safety
/// `circulator` must be NULL or a circulator over a live, unmodified mesh; `out` writable.
/// \ingroup circulators
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_circ_next_edge(
    circulator: *mut hw_circulator,
    out: *mut hw_edge,
) -> bool {
    unsafe {
        next_into(circulator, HW_CIRCULATOR_KIND_EDGES, out, |idx| {
            EdgeId(idx).into()
        })
    }
}

/// Next face of a ::HW_CIRCULATOR_KIND_FACES circulator.
///
/// # Safety
/// `circulator` must be NULL or a circulator over a live, unmodified mesh; `out` writable.
/// \ingroup circulators
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_circ_next_face(
    circulator: *mut hw_circulator,
    out: *mut hw_face,
) -> bool {
    unsafe {
        next_into(circulator, HW_CIRCULATOR_KIND_FACES, out, |idx| {
            FaceId(idx).into()
        })
    }
}
