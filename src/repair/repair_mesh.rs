//! The repair pipeline: every repair in turn, from a face list to a clean mesh.

use super::fates::Ledger;
use super::{
    FaceFate, FillError, HoleFillOptions, Removal, RepairError, SmallComponents, Tolerance,
    VertexFate, fill_holes, merge_vertices, remove_degenerate_faces, remove_duplicate_faces,
    remove_small_components, remove_t_vertices, remove_unreferenced_vertices, stitch_borders,
};
use crate::mesh::{FaceId, INVALID_INDEX, Mesh, VertexId, compaction_map};
use crate::soup::{BuildPolicy, PolygonSoup};

/// Options of [`repair_mesh`]. The default merges and stitches exact duplicates only, mends
/// exactly degenerate triangles, splits edges at vertices exactly on them, fills no hole and
/// keeps every component.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RepairOptions {
    /// Vertices this close merge (first step).
    pub merge_tolerance: Tolerance,
    /// Triangles this close to a line are mended (after the build), or `None` to leave
    /// degenerate triangles as they are.
    pub degenerate_tolerance: Option<Tolerance>,
    /// Boundary vertices this close to another boundary edge split it (before stitching), or
    /// `None` to leave T-vertices as they are.
    pub t_vertex_tolerance: Option<Tolerance>,
    /// Boundary edges this close stitch (after the build).
    pub stitch_tolerance: Tolerance,
    /// Holes filled (after stitching), if any: see [`fill_holes`]. Off by default: an open
    /// surface (a terrain, a sheet, a scan's outer border) is often open on purpose, and a fill
    /// adds faces no input describes. [`RepairOptions::fill_holes_up_to`] fills the holes of at
    /// most some number of boundary edges.
    pub fill_holes: Option<HoleFillOptions>,
    /// Components removed as small, if any.
    pub small_components: Option<SmallComponents>,
}

impl RepairOptions {
    /// These options, filling every hole of at most `max_edges` boundary edges.
    pub fn fill_holes_up_to(self, max_edges: usize) -> Self {
        RepairOptions {
            fill_holes: Some(HoleFillOptions {
                max_edges,
                ..HoleFillOptions::default()
            }),
            ..self
        }
    }
}

impl Default for RepairOptions {
    fn default() -> Self {
        RepairOptions {
            merge_tolerance: Tolerance::EXACT,
            degenerate_tolerance: Some(Tolerance::EXACT),
            t_vertex_tolerance: Some(Tolerance::EXACT),
            stitch_tolerance: Tolerance::EXACT,
            fill_holes: None,
            small_components: None,
        }
    }
}

/// The steps of [`repair_mesh`], in the order they run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RepairStep {
    /// [`merge_vertices`] with [`RepairOptions::merge_tolerance`].
    MergeVertices,
    /// [`remove_duplicate_faces`].
    RemoveDuplicateFaces,
    /// The build under [`BuildPolicy::Repair`]: non-manifold vertices split, non-manifold edges
    /// cut, faces reoriented to agree, closed components turned outward.
    Build,
    /// [`remove_degenerate_faces`] with [`RepairOptions::degenerate_tolerance`], when set.
    RemoveDegenerateFaces,
    /// [`remove_t_vertices`] with [`RepairOptions::t_vertex_tolerance`], when set.
    RemoveTVertices,
    /// [`stitch_borders`] with [`RepairOptions::stitch_tolerance`].
    StitchBorders,
    /// [`fill_holes`], when [`RepairOptions::fill_holes`] is set: holes it refuses stay open.
    FillHoles,
    /// [`remove_small_components`], when [`RepairOptions::small_components`] is set.
    RemoveSmallComponents,
    /// [`remove_unreferenced_vertices`].
    RemoveUnreferencedVertices,
}

impl RepairStep {
    /// Every step, in the order [`repair_mesh`] runs them.
    pub const ALL: [RepairStep; 9] = [
        RepairStep::MergeVertices,
        RepairStep::RemoveDuplicateFaces,
        RepairStep::Build,
        RepairStep::RemoveDegenerateFaces,
        RepairStep::RemoveTVertices,
        RepairStep::StitchBorders,
        RepairStep::FillHoles,
        RepairStep::RemoveSmallComponents,
        RepairStep::RemoveUnreferencedVertices,
    ];
}

/// What [`repair_mesh`] did to every input element. Every input vertex is kept, merged or
/// removed, every input face kept or removed; the output's vertices are the kept input vertices
/// and the added ones ([`RepairFates::added_vertices`]), its faces the kept input faces and the
/// added ones ([`RepairFates::added_faces`]). Filling holes adds faces, and vertices when it
/// refines ([`FillMode::Refine`](super::FillMode::Refine)).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct RepairFates {
    /// The fate of every input vertex.
    pub vertices: Vec<VertexFate>,
    /// The fate of every input face.
    pub faces: Vec<FaceFate>,
    /// Pairs `[output vertex, input vertex]` of output vertices no input vertex became, by
    /// output id: copies of an input vertex (made by splitting non-manifold vertices, cutting
    /// non-manifold edges, and splitting an edge at a T-vertex where stitching did not merge the
    /// copy into it), and vertices a refined hole fill placed (input vertex `INVALID_INDEX`).
    pub added_vertices: Vec<[u32; 2]>,
    /// Edges flipped to mend a degenerate triangle (both its faces kept, with new corners).
    pub flipped_edges: usize,
    /// Boundary edges split at a T-vertex (one per T-vertex; the face beside gains a corner).
    pub split_edges: usize,
    /// Output faces that no input face became: the triangles filling holes, by output id.
    pub added_faces: Vec<u32>,
    /// Pairs of boundary edges stitched into one.
    pub stitched_edges: usize,
    /// Holes filled.
    pub filled_holes: usize,
    /// Holes within [`RepairOptions::fill_holes`]' bounds that filling refused (left open).
    pub refused_holes: usize,
}

/// Counts of a [`RepairFates`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FateCounts {
    /// Input vertices in the output.
    pub kept_vertices: usize,
    /// Input vertices merged into another.
    pub merged_vertices: usize,
    /// Input vertices removed.
    pub removed_vertices: usize,
    /// Output vertices no input vertex became (copies, and vertices of refined hole fills).
    pub added_vertices: usize,
    /// Output faces that no input face became (hole fills).
    pub added_faces: usize,
    /// Input faces in the output.
    pub kept_faces: usize,
    /// Kept faces that run the other way round.
    pub reversed_faces: usize,
    /// Input faces removed.
    pub removed_faces: usize,
}

impl RepairFates {
    /// The number of elements of every fate: kept, merged and removed vertices sum to the input
    /// vertices, kept and added ones to the output's; kept and removed faces sum to the input
    /// faces, kept and added ones to the output's.
    pub fn counts(&self) -> FateCounts {
        let mut counts = FateCounts {
            added_vertices: self.added_vertices.len(),
            added_faces: self.added_faces.len(),
            ..FateCounts::default()
        };
        for fate in &self.vertices {
            match fate {
                VertexFate::Kept(_) => counts.kept_vertices += 1,
                VertexFate::Merged { .. } => counts.merged_vertices += 1,
                VertexFate::Removed(_) => counts.removed_vertices += 1,
            }
        }
        for fate in &self.faces {
            match fate {
                FaceFate::Kept { reversed, .. } => {
                    counts.kept_faces += 1;
                    counts.reversed_faces += usize::from(*reversed);
                }
                FaceFate::Removed(_) => counts.removed_faces += 1,
            }
        }
        counts
    }

    /// How many input faces were removed for each reason, in the order of [`Removal`]
    /// (duplicates counted together).
    pub fn removed_faces_by_reason(&self) -> Vec<(&'static str, usize)> {
        reasons(self.faces.iter().filter_map(|f| match f {
            FaceFate::Removed(why) => Some(*why),
            FaceFate::Kept { .. } => None,
        }))
    }

    /// How many input vertices were removed for each reason.
    pub fn removed_vertices_by_reason(&self) -> Vec<(&'static str, usize)> {
        reasons(self.vertices.iter().filter_map(|v| match v {
            VertexFate::Removed(why) => Some(*why),
            _ => None,
        }))
    }
}

fn reasons(removals: impl Iterator<Item = Removal>) -> Vec<(&'static str, usize)> {
    let mut counts: Vec<(&'static str, usize)> = Vec::new();
    for why in removals {
        let name = why.name();
        match counts.iter_mut().find(|(n, _)| *n == name) {
            Some((_, count)) => *count += 1,
            None => counts.push((name, 1)),
        }
    }
    counts
}

impl Removal {
    /// A short name of the reason, for reports.
    pub fn name(self) -> &'static str {
        match self {
            Removal::Collapsed => "collapsed",
            Removal::Degenerate => "degenerate",
            Removal::Duplicate { .. } => "duplicate",
            Removal::Unbuildable => "unbuildable",
            Removal::SmallComponent => "small component",
            Removal::Unreferenced => "unreferenced",
        }
    }
}

/// The structure between two steps: the face-list repairs work on a soup, the others on a mesh.
enum Work {
    Soup(PolygonSoup),
    Mesh(Box<Mesh>),
}

/// Runs the repairs on `soup`, in the order of [`RepairStep::ALL`], and builds the result:
/// merge duplicate vertices, remove duplicate faces, build under [`BuildPolicy::Repair`]
/// (split non-manifold vertices, cut non-manifold edges, reorient, turn closed components
/// outward, leave out faces it cannot keep), mend degenerate triangles and split boundary
/// edges at T-vertices (each when asked, as by default), stitch borders, fill holes (when
/// asked), remove small components (when asked), remove unreferenced vertices. The mesh comes
/// from a last build under
/// [`BuildPolicy::Repair`], which only turns closed components that stitching closed outward.
///
/// The returned mesh passes [`Mesh::check`] and builds again under [`BuildPolicy::Strict`]
/// from [`Mesh::to_soup`]; vertex positions and corner data follow their elements as each
/// repair says. The fates ([`RepairFates`]) say what became of every input vertex and face.
///
/// O(n log n). Refused, with nothing built, for bad options (as each repair refuses them) and
/// for a malformed face list (sizes and indices disagree, an index naming no vertex, corner
/// data not one per corner).
pub fn repair_mesh(
    soup: &PolygonSoup,
    options: &RepairOptions,
) -> Result<(Mesh, RepairFates), RepairError> {
    let mut ledger = Ledger::new(soup.positions.len(), soup.n_faces());
    let mut work = Work::Soup(soup.clone());
    let mut edits = StepEdits::default();
    for step in RepairStep::ALL {
        run(step, &mut work, options, &mut ledger, &mut edits)?;
    }
    let mesh = match work {
        Work::Mesh(mesh) => *mesh,
        Work::Soup(soup) => build(&soup, &mut ledger)?,
    };
    Ok((
        mesh,
        RepairFates {
            vertices: ledger.vertex_fates(),
            faces: ledger.face_fates(),
            added_vertices: ledger.added_vertices(),
            added_faces: ledger.added_faces(),
            flipped_edges: edits.flipped_edges,
            split_edges: edits.split_edges,
            stitched_edges: edits.stitched_edges,
            filled_holes: edits.filled_holes,
            refused_holes: edits.refused_holes,
        },
    ))
}

/// What the steps did beyond the fates of elements.
#[derive(Default)]
struct StepEdits {
    flipped_edges: usize,
    split_edges: usize,
    stitched_edges: usize,
    filled_holes: usize,
    refused_holes: usize,
}

/// Runs one step, recording its fates in `ledger` and its other edits in `edits`.
fn run(
    step: RepairStep,
    work: &mut Work,
    options: &RepairOptions,
    ledger: &mut Ledger,
    edits: &mut StepEdits,
) -> Result<(), RepairError> {
    match step {
        RepairStep::MergeVertices => {
            let report = merge_vertices(soup(work, ledger), options.merge_tolerance)?;
            ledger.map_vertices(
                &report.maps.vertices,
                &report.merged_vertices,
                Removal::Unreferenced,
            );
            ledger.map_faces(&report.maps.faces, |_| Removal::Collapsed);
        }
        RepairStep::RemoveDuplicateFaces => {
            let soup = soup(work, ledger);
            let input = ledger.input_faces(soup.n_faces());
            let report = remove_duplicate_faces(soup)?;
            let mut kept_for = vec![INVALID_INDEX; input.len()];
            for &[gone, kept] in &report.duplicate_faces {
                kept_for[gone as usize] = input[kept as usize];
            }
            ledger.map_vertices(&report.maps.vertices, &[], Removal::Unreferenced);
            ledger.map_faces(&report.maps.faces, |f| Removal::Duplicate {
                of: kept_for[f as usize],
            });
        }
        RepairStep::Build => {
            if let Work::Soup(soup) = work {
                *work = Work::Mesh(Box::new(build(soup, ledger)?));
            }
        }
        RepairStep::RemoveDegenerateFaces => {
            if let Some(tolerance) = options.degenerate_tolerance {
                let report = remove_degenerate_faces(mesh(work, ledger)?, tolerance)?;
                ledger.apply(&report, Removal::Degenerate);
                edits.flipped_edges += report.flipped_faces.len();
            }
        }
        RepairStep::RemoveTVertices => {
            if let Some(tolerance) = options.t_vertex_tolerance {
                let mesh = mesh(work, ledger)?;
                let report = remove_t_vertices(mesh, tolerance)?;
                ledger.map_vertices(&report.maps.vertices, &[], Removal::Unbuildable);
                let sources: Vec<u32> = report
                    .vertex_copies
                    .iter()
                    .map(|&v| report.maps.vertices[v as usize])
                    .collect();
                let first = mesh.n_vertices() - sources.len();
                ledger.add_vertices(first as u32, &sources);
                edits.split_edges += sources.len();
            }
        }
        RepairStep::StitchBorders => {
            let report = stitch_borders(mesh(work, ledger)?, options.stitch_tolerance)?;
            ledger.apply(&report, Removal::Unbuildable);
            edits.stitched_edges += report.stitched_halfedges.len();
        }
        RepairStep::FillHoles => {
            if let Some(fill) = options.fill_holes {
                let mesh = mesh(work, ledger)?;
                let first_vertex = mesh.n_vertex_slots();
                let report = fill_holes(mesh, &fill).map_err(|e| match e {
                    FillError::BadOption { name, value, range } => {
                        RepairError::BadOption { name, value, range }
                    }
                    other => unreachable!("fill_holes refuses only options: {other}"),
                })?;
                let mut added: Vec<u32> = report
                    .filled
                    .iter()
                    .flat_map(|hole| hole.faces.iter().map(|f| f.0))
                    .collect();
                added.sort_unstable();
                ledger.add_faces(&added);
                // Copies welded where a hole passed twice through one point: merged, their ids
                // kept until the mesh is compacted.
                let welded: Vec<[u32; 2]> = report
                    .welded_vertices
                    .iter()
                    .map(|&[gone, kept]| [gone.0, kept.0])
                    .collect();
                let mut unchanged: Vec<u32> = (0..mesh.n_vertex_slots() as u32).collect();
                for &[gone, _] in &welded {
                    unchanged[gone as usize] = INVALID_INDEX;
                }
                ledger.map_vertices(&unchanged, &welded, Removal::Unbuildable);
                // Refined fills place vertices at new positions (copying no input vertex); a
                // refused one may leave deleted ids, compacted with the others later.
                let placed = vec![INVALID_INDEX; mesh.n_vertex_slots() - first_vertex];
                ledger.add_vertices(first_vertex as u32, &placed);
                // A refused fill may leave a deleted face id behind: the ids are compacted as
                // the mesh turns into a face list.
                let deleted: Vec<bool> = (0..mesh.n_face_slots() as u32)
                    .map(|f| mesh.is_face_deleted(FaceId(f)))
                    .collect();
                ledger.map_faces(&compaction_map(deleted.len(), &deleted), |_| {
                    Removal::Unbuildable
                });
                edits.filled_holes += report.filled.len();
                edits.refused_holes += report.refused.len();
            }
        }
        RepairStep::RemoveSmallComponents => {
            if let Some(small) = options.small_components {
                let report = remove_small_components(soup(work, ledger), small)?;
                ledger.map_vertices(&report.maps.vertices, &[], Removal::SmallComponent);
                ledger.map_faces(&report.maps.faces, |_| Removal::SmallComponent);
            }
        }
        RepairStep::RemoveUnreferencedVertices => {
            let report = remove_unreferenced_vertices(soup(work, ledger))?;
            ledger.map_vertices(&report.maps.vertices, &[], Removal::Unreferenced);
        }
    }
    Ok(())
}

/// The work as a soup, a mesh being turned into its face list (deleted elements compacted).
fn soup<'a>(work: &'a mut Work, ledger: &mut Ledger) -> &'a mut PolygonSoup {
    if let Work::Mesh(mesh) = work {
        let deleted: Vec<bool> = (0..mesh.n_vertex_slots() as u32)
            .map(|v| mesh.is_vertex_deleted(VertexId(v)))
            .collect();
        let map = compaction_map(deleted.len(), &deleted);
        ledger.map_vertices(&map, &[], Removal::Unbuildable);
        // Faces of a built mesh are never deleted by the steps: face ids carry over.
        *work = Work::Soup(mesh.to_soup());
    }
    match work {
        Work::Soup(soup) => soup,
        Work::Mesh(_) => unreachable!("turned into a soup above"),
    }
}

/// The work as a mesh, a soup being built first.
fn mesh<'a>(work: &'a mut Work, ledger: &mut Ledger) -> Result<&'a mut Mesh, RepairError> {
    if let Work::Soup(soup) = work {
        *work = Work::Mesh(Box::new(build(soup, ledger)?));
    }
    match work {
        Work::Mesh(mesh) => Ok(mesh.as_mut()),
        Work::Soup(_) => unreachable!("built above"),
    }
}

/// Builds under [`BuildPolicy::Repair`] and records what the build changed.
fn build(soup: &PolygonSoup, ledger: &mut Ledger) -> Result<Mesh, RepairError> {
    let (mesh, diagnostic) =
        Mesh::from_soup(soup, BuildPolicy::Repair).map_err(RepairError::Build)?;
    ledger.reverse_faces(&diagnostic.reoriented_faces);
    let mut skipped = vec![false; soup.n_faces()];
    for &f in &diagnostic.skipped_faces {
        skipped[f as usize] = true;
    }
    let faces = compaction_map(skipped.len(), &skipped);
    ledger.map_faces(&faces, |_| Removal::Unbuildable);
    ledger.add_vertices(soup.positions.len() as u32, &diagnostic.vertex_copies);
    ledger.remove_vertices(&diagnostic.non_finite_vertices, Removal::Unbuildable);
    Ok(mesh)
}
