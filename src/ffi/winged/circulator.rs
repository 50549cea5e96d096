//! Stack circulators over an `hw_winged`: a face's loop and a vertex's ring, from C.
//!
//! ```c
//! hw_wcirculator c;
//! hw_wvertex corner;
//! if (hw_wcirc_around_face(w, f, HW_WCIRCULATOR_KIND_VERTICES, &c) == HW_OK)
//!   while (hw_wcirc_next_vertex(&c, &corner)) visit(corner);
//! ```
//! Every step makes the winged-edge structure's orientation test (is the loop on this edge's
//! left or right side?) for the caller. Orders: around a face, counter-clockwise seen from
//! outside from hw_winged_face_edge() (so from the face's first corner as built); around a
//! vertex, counter-clockwise seen from outside from hw_winged_vertex_edge() (for a boundary
//! vertex, from the edge bordering the hole, so the fan is seen whole; at a non-manifold vertex
//! only that edge's fan). Walks are bounded by the edge count, so a corrupt structure ends a walk
//! instead of looping.

use crate::winged::{EdgeId, EdgeUse, Side, Step, Walk, WalkState, Winged};

use crate::ffi::boundary::error::FfiError;
use crate::ffi::boundary::status::hw_status;
use crate::ffi::boundary::{Out, arg_mut, guard, next_element};
use crate::ffi::mesh::elements::HW_INVALID_INDEX;
use crate::ffi::winged::lifecycle::{hw_wedge, hw_wface, hw_winged, hw_wvertex, winged_ref};

/// What a winged circulator yields.
/// \ingroup winged_circulators
pub type hw_wcirculator_kind = u32;
/// Edges: the edges of a face's loop, or the edges at a vertex.
/// \ingroup winged_circulators
pub const HW_WCIRCULATOR_KIND_EDGES: hw_wcirculator_kind = 0;
/// Vertices: a face's corners, or a vertex's neighbours (the other ends of its edges).
/// \ingroup winged_circulators
pub const HW_WCIRCULATOR_KIND_VERTICES: hw_wcirculator_kind = 1;
/// Faces: the faces across a face's edges, or the faces around a vertex (holes skipped).
/// \ingroup winged_circulators
pub const HW_WCIRCULATOR_KIND_FACES: hw_wcirculator_kind = 2;

/// What a walk circles.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Center {
    Vertex = 0,
    Face = 1,
}

/// A winged circulator's state, kept on the caller's stack. Fill it with
/// hw_wcirc_around_face() or hw_wcirc_around_vertex(); read it with the `hw_wcirc_next_*` call of
/// its kind. Treat the fields as private. It borrows the structure: do not modify the structure
/// while walking.
/// \ingroup winged_circulators
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct hw_wcirculator {
    /// The structure walked.
    pub winged: *const hw_winged,
    /// The edge of the use the walk started from; coming back to that use ends the walk.
    pub start_edge: u32,
    /// The side of that use: 0 left, 1 right.
    pub start_side: u32,
    /// The edge of the use the walk yields next, `HW_INVALID_INDEX` once it is over.
    pub current_edge: u32,
    /// The side of that use: 0 left, 1 right.
    pub current_side: u32,
    /// Steps left before the bound on a walk's length stops it (a corrupt cycle cannot hang).
    pub remaining: u32,
    /// What it walks around: a face or a vertex (internal code).
    pub center: u32,
    /// What it yields.
    pub kind: hw_wcirculator_kind,
}

/// An edge use as two integers (edge, side 0 = left / 1 = right); none is an invalid edge.
fn encode(u: Option<EdgeUse>) -> (u32, u32) {
    match u {
        Some(u) => (u.edge.0, u32::from(u.side == Side::Right)),
        None => (HW_INVALID_INDEX, 0),
    }
}

fn decode(edge: u32, side: u32) -> Option<EdgeUse> {
    (edge != HW_INVALID_INDEX).then(|| {
        let side = if side == 0 { Side::Left } else { Side::Right };
        EdgeUse::new(EdgeId(edge), side)
    })
}

/// Fills a circulator from a fresh walk.
fn begin(
    raw: *const hw_winged,
    walk: Walk<'_>,
    center: Center,
    kind: hw_wcirculator_kind,
) -> Result<hw_wcirculator, FfiError> {
    if kind > HW_WCIRCULATOR_KIND_FACES {
        return Err(FfiError::invalid_input(format!(
            "unknown winged circulator kind {kind}"
        )));
    }
    let state = walk.state();
    let (start_edge, start_side) = encode(state.start);
    let (current_edge, current_side) = encode(state.current);
    Ok(hw_wcirculator {
        winged: raw,
        start_edge,
        start_side,
        current_edge,
        current_side,
        remaining: u32::try_from(state.remaining).unwrap_or(u32::MAX),
        center: center as u32,
        kind,
    })
}

/// Starts a walk around face `f`: its edges or corners in loop order, or the faces across its
/// edges (holes skipped). A point face (made by hw_winged_mvfs()) gives an empty walk.
///
/// # Safety
/// `winged` must be NULL or a live structure; `out` writable.
/// \ingroup winged_circulators
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_wcirc_around_face(
    winged: *const hw_winged,
    f: hw_wface,
    kind: hw_wcirculator_kind,
    out: *mut hw_wcirculator,
) -> hw_status {
    guard(|| {
        let out = Out::new(out, "out")?;
        // SAFETY: forwarded from the caller.
        let w = unsafe { winged_ref(winged) }?;
        let circulator = begin(winged, w.face_loop(f.into())?, Center::Face, kind)?;
        // SAFETY: checked non-NULL, writable per the caller.
        unsafe { out.write(circulator) };
        Ok(())
    })
}

/// Starts a walk around vertex `v`: its edges or neighbours counter-clockwise, or the faces
/// around it (holes skipped). An isolated vertex gives an empty walk.
///
/// # Safety
/// `winged` must be NULL or a live structure; `out` writable.
/// \ingroup winged_circulators
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_wcirc_around_vertex(
    winged: *const hw_winged,
    v: hw_wvertex,
    kind: hw_wcirculator_kind,
    out: *mut hw_wcirculator,
) -> hw_status {
    guard(|| {
        let out = Out::new(out, "out")?;
        // SAFETY: forwarded from the caller.
        let w = unsafe { winged_ref(winged) }?;
        let circulator = begin(winged, w.vertex_ring(v.into())?, Center::Vertex, kind)?;
        // SAFETY: checked non-NULL, writable per the caller.
        unsafe { out.write(circulator) };
        Ok(())
    })
}

/// The id a circulator of `kind` around `center` yields for use `u`, or invalid to skip it
/// (a hole).
fn element(w: &Winged, u: EdgeUse, center: u32, kind: hw_wcirculator_kind) -> u32 {
    let r = &w.edge_records()[u.edge.index()];
    let on_face = center == Center::Face as u32;
    match kind {
        HW_WCIRCULATOR_KIND_EDGES => u.edge.0,
        HW_WCIRCULATOR_KIND_VERTICES if on_face => r.tail(u.side).0,
        HW_WCIRCULATOR_KIND_VERTICES => r.head(u.side).0,
        HW_WCIRCULATOR_KIND_FACES if on_face => r.face(u.side.opposite()).0,
        _ => r.face(u.side).0,
    }
}

/// Advances `circulator` (which must yield `kind`): `Some(id)`, or `None` when the walk is over.
///
/// # Safety
/// `circulator` must be NULL or point to a circulator whose structure is still live.
unsafe fn advance(
    circulator: *mut hw_wcirculator,
    kind: hw_wcirculator_kind,
) -> Result<Option<u32>, FfiError> {
    // SAFETY: forwarded from the caller.
    let c = unsafe { arg_mut(circulator, "circulator") }?;
    if c.kind != kind {
        return Err(FfiError::invalid_input(format!(
            "winged circulator of kind {} read as kind {kind}",
            c.kind
        )));
    }
    // SAFETY: the circulator's structure is live per the caller.
    let w = unsafe { winged_ref(c.winged) }?;
    let step = if c.center == Center::Vertex as u32 {
        Step::Ring
    } else {
        Step::Loop
    };
    let mut walk = w.resume_walk(WalkState {
        start: decode(c.start_edge, c.start_side),
        current: decode(c.current_edge, c.current_side),
        step,
        remaining: c.remaining as usize,
    });
    let mut found = None;
    for u in walk.by_ref() {
        let id = element(w, u, c.center, c.kind);
        if id != HW_INVALID_INDEX {
            found = Some(id);
            break;
        }
    }
    let state = walk.state();
    (c.current_edge, c.current_side) = encode(state.current);
    c.remaining = u32::try_from(state.remaining).unwrap_or(u32::MAX);
    Ok(found)
}

/// Writes the next element of a circulator through `out` (see `next_element`).
///
/// # Safety
/// As for `advance`; `out` NULL or writable.
unsafe fn next_into<T>(
    circulator: *mut hw_wcirculator,
    kind: hw_wcirculator_kind,
    out: *mut T,
    wrap: impl FnOnce(u32) -> T,
) -> bool {
    // SAFETY: forwarded from the caller.
    unsafe { next_element(out, || Ok(advance(circulator, kind)?.map(wrap))) }
}

/// Next edge of a ::HW_WCIRCULATOR_KIND_EDGES circulator.
///
/// # Safety
/// `circulator` must be NULL or a circulator over a live, unmodified structure; `out` writable.
/// \ingroup winged_circulators
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_wcirc_next_edge(
    circulator: *mut hw_wcirculator,
    out: *mut hw_wedge,
) -> bool {
    unsafe {
        next_into(circulator, HW_WCIRCULATOR_KIND_EDGES, out, |idx| hw_wedge {
            idx,
        })
    }
}

/// Next vertex of a ::HW_WCIRCULATOR_KIND_VERTICES circulator.
///
/// # Safety
/// `circulator` must be NULL or a circulator over a live, unmodified structure; `out` writable.
/// \ingroup winged_circulators
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_wcirc_next_vertex(
    circulator: *mut hw_wcirculator,
    out: *mut hw_wvertex,
) -> bool {
    unsafe {
        next_into(circulator, HW_WCIRCULATOR_KIND_VERTICES, out, |idx| {
            hw_wvertex { idx }
        })
    }
}

/// Next face of a ::HW_WCIRCULATOR_KIND_FACES circulator.
///
/// # Safety
/// `circulator` must be NULL or a circulator over a live, unmodified structure; `out` writable.
/// \ingroup winged_circulators
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_wcirc_next_face(
    circulator: *mut hw_wcirculator,
    out: *mut hw_wface,
) -> bool {
    unsafe {
        next_into(circulator, HW_WCIRCULATOR_KIND_FACES, out, |idx| hw_wface {
            idx,
        })
    }
}
