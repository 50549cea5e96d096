//! The surface's connected components with their topology (Euler characteristic, genus,
//! boundary), orientation (orientable, consistently oriented, outward or inward) and measures
//! (area, bounding box, enclosed volume).

use super::boundary::BoundaryLoop;
use super::measure::{EMPTY_BOX, distance, grow};
use crate::geom::newell_vector;
use crate::soup::{
    BOUNDARY, EdgeDefect, EdgePairing, FaceTable, UNPAIRED, component_volumes, search_orientations,
};
use crate::support::disjoint_sets;

/// One connected component: faces joined through shared edges (any number of faces on an edge).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Component {
    /// Its lowest input face.
    pub first_face: u32,
    /// Number of faces.
    pub n_faces: usize,
    /// Number of distinct edges.
    pub n_edges: usize,
    /// Number of distinct vertices (a vertex shared with another component through a
    /// non-manifold vertex counts in both).
    pub n_vertices: usize,
    /// Number of boundary loops.
    pub n_boundary_loops: usize,
    /// V − E + F.
    pub euler_characteristic: i64,
    /// The genus `(2 − χ − b) / 2` of an orientable 2-manifold component with `b` boundary loops;
    /// `None` for a component that is not one.
    pub genus: Option<u32>,
    /// No boundary edge (every edge has two or more faces).
    pub closed: bool,
    /// No non-manifold edge or vertex.
    pub manifold: bool,
    /// Its faces can be oriented so that every two-face edge is walked both ways.
    pub orientable: bool,
    /// Every two-face edge is walked both ways as given.
    pub consistently_oriented: bool,
    /// The signed volume enclosed by a closed, manifold, consistently oriented component:
    /// positive when it faces outward, negative when inward. `None` for the others. At extreme
    /// coordinates it may overflow to infinity or underflow to zero: [`Component::outward`] has
    /// the sign whatever the magnitude.
    pub volume: Option<f64>,
    /// Whether a closed, manifold, consistently oriented component faces outward (encloses a
    /// positive volume); `None` for the others and for one enclosing no volume.
    pub outward: Option<bool>,
    /// The sum of its faces' areas.
    pub area: f64,
    /// The lowest and highest corner of its bounding box.
    pub bounding_box: [[f64; 3]; 2],
}

impl Component {
    /// The diagonal of the bounding box.
    pub fn diameter(&self) -> f64 {
        distance(self.bounding_box[0], self.bounding_box[1])
    }
}

/// The components and, when some component is not orientable, a witness path of faces.
pub(super) struct Topology {
    pub(super) components: Vec<Component>,
    pub(super) non_orientable_witness: Vec<u32>,
}

/// The component of every face of `surface` (faces sharing an edge, whatever its number of
/// faces, are in one), numbered in order of their lowest face, and the number of components.
pub(crate) fn face_components(surface: &FaceTable<'_>, pairing: &EdgePairing) -> (Vec<u32>, usize) {
    let mut parent: Vec<u32> = (0..surface.n_faces() as u32).collect();
    let face_of = |c: u32| surface.face_of_corner(c as usize) as u32;
    for (c, &p) in pairing.partner.iter().enumerate() {
        if p != BOUNDARY && p != UNPAIRED {
            disjoint_sets::join(&mut parent, 0, face_of(c as u32), face_of(p));
        }
    }
    for problem in &pairing.problems {
        let first = face_of(problem.corners[0]);
        for &c in &problem.corners[1..] {
            disjoint_sets::join(&mut parent, 0, first, face_of(c));
        }
    }
    // Roots are each set's lowest face (see `disjoint_sets`): number the sets in that order.
    let n_components = disjoint_sets::number_sets(&mut parent, |_| false, |_, _| {});
    (parent, n_components)
}

/// The components of `surface` (whose edges `pairing` pairs), with the number of `loops` each
/// has (each loop given with a table face along it).
pub(super) fn components(
    surface: &FaceTable<'_>,
    pairing: &EdgePairing,
    positions: &[[f64; 3]],
    non_manifold_vertices: &[u32],
    loops: &[(BoundaryLoop, usize)],
) -> Topology {
    let n_faces = surface.n_faces();
    let (component_of, n_components) = face_components(surface, pairing);
    let mut components: Vec<Component> = (0..n_components)
        .map(|_| Component {
            first_face: u32::MAX,
            closed: true,
            manifold: true,
            consistently_oriented: true,
            bounding_box: EMPTY_BOX,
            ..Component::default()
        })
        .collect();

    // A vertex counts once per component: its first component is remembered, and only a
    // vertex met again from another one (a non-manifold vertex) goes into the sorted list.
    const NONE: u32 = u32::MAX;
    let mut first_component = vec![NONE; positions.len()];
    let mut shared_vertices: Vec<(u32, u32)> = Vec::new();
    for f in 0..n_faces {
        let component = &mut components[component_of[f] as usize];
        component.first_face = component.first_face.min(surface.input_face(f));
        component.n_faces += 1;
        let face = surface.face(f);
        let area = newell_vector(face.iter().map(|&v| positions[v as usize]));
        component.area += 0.5 * distance(area, [0.0; 3]);
        for &v in face {
            let first = &mut first_component[v as usize];
            if *first == NONE {
                *first = component_of[f];
            } else if *first != component_of[f] {
                shared_vertices.push((component_of[f], v));
            }
            grow(&mut component.bounding_box, positions[v as usize]);
        }
        for c in surface.face_range(f) {
            match pairing.partner[c] {
                BOUNDARY => {
                    component.n_edges += 1;
                    component.closed = false;
                }
                UNPAIRED => {}
                p if (p as usize) > c => component.n_edges += 1,
                _ => {}
            }
        }
    }
    for problem in &pairing.problems {
        let component = &mut components
            [component_of[surface.face_of_corner(problem.corners[0] as usize)] as usize];
        component.n_edges += 1;
        match problem.defect {
            EdgeDefect::NonManifold => component.manifold = false,
            EdgeDefect::Inconsistent => component.consistently_oriented = false,
        }
    }
    shared_vertices.sort_unstable();
    shared_vertices.dedup();
    let firsts = (0..positions.len() as u32)
        .filter(|&v| first_component[v as usize] != NONE)
        .map(|v| (first_component[v as usize], v));
    for (component, v) in firsts.chain(shared_vertices) {
        components[component as usize].n_vertices += 1;
        if non_manifold_vertices.binary_search(&v).is_ok() {
            components[component as usize].manifold = false;
        }
    }
    for (_, face) in loops {
        components[component_of[*face] as usize].n_boundary_loops += 1;
    }

    let (orientable, non_orientable_witness) =
        orientability(surface, pairing, &component_of, n_components);
    let closed_and_oriented = |c: usize| {
        let component = &components[c];
        component.closed && component.manifold && component.consistently_oriented
    };
    let component_index: Vec<usize> = component_of.iter().map(|&c| c as usize).collect();
    let volumes = component_volumes(
        surface,
        &component_index,
        n_components,
        closed_and_oriented,
        |v| positions[v as usize],
    );
    for (c, component) in components.iter_mut().enumerate() {
        component.orientable = orientable[c];
        component.euler_characteristic =
            component.n_vertices as i64 - component.n_edges as i64 + component.n_faces as i64;
        if component.manifold && component.orientable {
            let twice_genus =
                2 - component.euler_characteristic - component.n_boundary_loops as i64;
            component.genus = u32::try_from(twice_genus / 2)
                .ok()
                .filter(|_| twice_genus >= 0 && twice_genus % 2 == 0);
        }
        if component.closed && component.manifold && component.consistently_oriented {
            component.volume = Some(volumes[c].volume);
            component.outward = (volumes[c].sign != 0.0).then_some(volumes[c].sign > 0.0);
        }
    }
    Topology {
        components,
        non_orientable_witness,
    }
}

/// Which components are orientable, and a witness for the first that is not: the first
/// conflict of the [`search_orientations`] closes a path along which the orientation flips,
/// from the conflict's two faces back through the search tree to their common ancestor, then
/// across the conflict edge.
fn orientability(
    surface: &FaceTable<'_>,
    pairing: &EdgePairing,
    component_of: &[u32],
    n_components: usize,
) -> (Vec<bool>, Vec<u32>) {
    let search = search_orientations(surface, pairing);
    let mut orientable = vec![true; n_components];
    for &(f, _) in &search.conflicts {
        orientable[component_of[f] as usize] = false;
    }
    let witness = search.conflicts.first().map_or_else(Vec::new, |&(f, g)| {
        closing_path(&search.reached_from, f, g)
            .into_iter()
            .map(|f| surface.input_face(f))
            .collect()
    });
    (orientable, witness)
}

/// The path of faces from `a` up the search tree (`reached_from`, roots their own) to the common
/// ancestor of `a` and `b`, then down to `b`: with the edge between `b` and `a`, a closed path.
fn closing_path(reached_from: &[u32], a: usize, b: usize) -> Vec<usize> {
    let to_root = |mut f: usize| {
        let mut path = vec![f];
        while reached_from[f] as usize != f {
            f = reached_from[f] as usize;
            path.push(f);
        }
        path
    };
    let (mut up, mut down) = (to_root(a), to_root(b));
    // Drop the shared part above the common ancestor (keeping the ancestor once).
    while up.len() > 1 && down.len() > 1 && up[up.len() - 2] == down[down.len() - 2] {
        up.pop();
        down.pop();
    }
    down.pop();
    up.extend(down.into_iter().rev());
    up
}

/// The components whose face count or diameter is at most `ratio` times the largest's (by
/// face count; by diameter), as indices.
pub(super) fn small(components: &[Component], ratio: f64) -> Vec<u32> {
    let most_faces = components.iter().map(|c| c.n_faces).max().unwrap_or(0) as f64;
    let widest = components
        .iter()
        .map(Component::diameter)
        .fold(0.0, f64::max);
    (0..components.len() as u32)
        .filter(|&c| {
            let component = &components[c as usize];
            component.n_faces as f64 <= ratio * most_faces || component.diameter() <= ratio * widest
        })
        .collect()
}
