//! Voronoi cells clipped to a convex region: closed polygons that share their vertices.

use super::clip_region::{ClipPolygon, polygon_area_centroid};
use super::delaunay::INVALID;
use super::diagram::{EdgeGeometry, Voronoi};
use super::error::VoronoiError;
use super::parallel::map_indexed;
use crate::soup::PolygonSoup;

/// Every cell of a Voronoi diagram clipped to a convex polygon.
///
/// The cells tile the clip polygon without gaps or overlaps: a Voronoi vertex inside the region,
/// a point where a Voronoi edge crosses the region's boundary, and a corner of the region each
/// exist once in [`ClippedCells::positions`] and are shared by every cell that touches them.
/// Each edge is clipped once for both of its cells, so neighbours always agree. Cells are
/// counter-clockwise and indexed by site; a site whose cell misses the region (possible for sites
/// outside it) and every duplicate site have an empty polygon.
#[derive(Clone, Debug)]
pub struct ClippedCells {
    positions: Vec<[f64; 2]>,
    ranges: Vec<[u32; 2]>,
    indices: Vec<u32>,
    clip: ClipPolygon,
}

/// A point on the clip boundary: edge index and parameter in `[0, 1)` along it.
#[derive(Clone, Copy, Debug)]
struct Perimeter {
    edge: u32,
    t: f64,
}

/// Positions under construction: `[corners][Voronoi vertices inside][boundary crossings]`.
struct Builder<'a> {
    clip: &'a ClipPolygon,
    positions: Vec<[f64; 2]>,
    first_crossing: usize,
    crossings: Vec<Perimeter>,
}

impl Builder<'_> {
    /// Where position `p` sits on the perimeter, if it is a corner or a crossing.
    fn perimeter(&self, p: u32) -> Option<Perimeter> {
        let m = self.clip.vertices().len();
        let p = p as usize;
        if p < m {
            Some(Perimeter {
                edge: p as u32,
                t: 0.0,
            })
        } else if p >= self.first_crossing {
            Some(self.crossings[p - self.first_crossing])
        } else {
            None
        }
    }

    /// Adds the crossing of clip edge `edge` near `x`, snapped onto the edge (or onto a corner).
    fn crossing(&mut self, edge: usize, x: [f64; 2]) -> u32 {
        let m = self.clip.vertices().len();
        let a = self.clip.vertices()[edge];
        let e = self.clip.edge_vector(edge);
        let t = (((x[0] - a[0]) * e[0] + (x[1] - a[1]) * e[1]) / (e[0] * e[0] + e[1] * e[1]))
            .clamp(0.0, 1.0);
        if t == 0.0 {
            return edge as u32;
        }
        if t == 1.0 {
            return ((edge + 1) % m) as u32;
        }
        self.positions.push([a[0] + t * e[0], a[1] + t * e[1]]);
        self.crossings.push(Perimeter {
            edge: edge as u32,
            t,
        });
        (self.positions.len() - 1) as u32
    }

    /// Corners met going counter-clockwise along the boundary strictly after `from` and strictly
    /// before `to` (both on the perimeter).
    fn corners_between(&self, from: Perimeter, to: Perimeter, out: &mut Vec<u32>) {
        let m = self.clip.vertices().len() as u32;
        let steps = if from.edge == to.edge && to.t >= from.t {
            0
        } else {
            let mut s = (to.edge + m - from.edge) % m;
            if s == 0 {
                s = m;
            }
            // Corner `to.edge` is `to` itself when `to` sits at the start of its edge.
            if to.t == 0.0 { s - 1 } else { s }
        };
        for k in 1..=steps {
            out.push((from.edge + k) % m);
        }
    }
}

/// Marks a piece not decided by the parallel pass (never a position index: positions stay
/// below [`INVALID`] − 1 by the site limit).
const UNDECIDED: u32 = INVALID - 1;

impl Voronoi {
    /// Clips every cell to `clip` (see [`ClippedCells`]).
    pub fn clip(&self, clip: &ClipPolygon) -> ClippedCells {
        let m = clip.vertices().len();
        let mut b = Builder {
            clip,
            positions: clip.vertices().to_vec(),
            first_crossing: 0,
            crossings: Vec::new(),
        };
        // Voronoi vertices inside (closed test) get a position; the same test decides every edge.
        // Those exactly on the boundary become perimeter points (or the corner they sit on), so
        // that the walk along the boundary knows where they are. The test runs in parallel; the
        // numbering, a prefix count, in one sequential pass.
        let lowest_edge_function: Vec<f64> = map_indexed(self.vertices.len(), |v| {
            let p = self.vertices[v];
            (0..m)
                .map(|i| clip.edge_function(i, p))
                .fold(f64::INFINITY, f64::min)
        });
        let mut vertex_position = vec![INVALID; self.vertices.len()];
        let mut on_boundary = Vec::new();
        b.positions.reserve(self.vertices.len());
        for (v, &lowest) in lowest_edge_function.iter().enumerate() {
            if lowest > 0.0 {
                vertex_position[v] = b.positions.len() as u32;
                b.positions.push(self.vertices[v]);
            } else if lowest == 0.0 {
                on_boundary.push(v);
            }
        }
        drop(lowest_edge_function);
        b.first_crossing = b.positions.len();
        for &v in &on_boundary {
            let p = self.vertices[v];
            let zero = |i: usize| clip.edge_function(i % m, p) == 0.0;
            let i = (0..m).find(|&i| zero(i)).unwrap_or(0);
            vertex_position[v] = if zero(i + 1) {
                ((i + 1) % m) as u32
            } else if zero(i + m - 1) {
                i as u32
            } else {
                b.crossing(i, p)
            };
        }
        // One clipped piece per undirected edge, oriented like its even half-edge. Edges with
        // both ends inside (nearly all) are their own piece and are found in parallel; only the
        // others, which may add boundary crossings, are clipped one after the other.
        let n_edges = self.n_halfedges() / 2;
        let mut pieces: Vec<[u32; 2]> = map_indexed(n_edges, |k| {
            let (o, t) = (self.origin[2 * k], self.origin[2 * k + 1]);
            if o != INVALID && t != INVALID {
                let (po, pt) = (vertex_position[o as usize], vertex_position[t as usize]);
                if po != INVALID && pt != INVALID {
                    return [po, pt];
                }
            }
            [INVALID, UNDECIDED]
        });
        let mut any_piece = false;
        for (k, piece) in pieces.iter_mut().enumerate() {
            if piece[1] == UNDECIDED {
                *piece = self.clip_edge(2 * k as u32, &vertex_position, &mut b);
            }
            any_piece |= piece[0] != INVALID;
        }
        let n_sites = self.delaunay.n_sites();
        let mut ranges = vec![[0u32, 0u32]; n_sites];
        let mut indices = Vec::with_capacity(pieces.len() * 2 + m);
        let owner_of_everything = if any_piece {
            INVALID
        } else {
            self.owner_of(clip.centroid())
        };
        if owner_of_everything != INVALID {
            ranges[owner_of_everything as usize] = [indices.len() as u32, m as u32];
            indices.extend(0..m as u32);
        }
        // Cells in insertion order, which follows the Hilbert curve and so the (spatially
        // coherent) order of the triangles and half-edges: consecutive cells share cache lines.
        // Cells are independent once the pieces exist: runs of them are assembled in parallel
        // into local lists, then concatenated in order.
        let order = &self.delaunay.insertion_order;
        let assemble_run = |run: &[u32]| {
            let mut local = Vec::with_capacity(7 * run.len());
            let mut spans = Vec::with_capacity(run.len());
            let mut cell_pieces = Vec::new();
            for &s in run {
                let start = self.cell_edge[s as usize];
                if start != INVALID && s != owner_of_everything {
                    let first = local.len() as u32;
                    self.assemble_cell(start, &pieces, &b, &mut cell_pieces, &mut local);
                    spans.push([s, first, local.len() as u32 - first]);
                }
            }
            (local, spans)
        };
        #[cfg(feature = "parallel")]
        let runs: Vec<(Vec<u32>, Vec<[u32; 3]>)> = {
            use rayon::prelude::*;
            order.par_chunks(1 << 15).map(assemble_run).collect()
        };
        #[cfg(not(feature = "parallel"))]
        let runs = vec![assemble_run(order)];
        for (local, spans) in runs {
            let offset = indices.len() as u32;
            indices.extend_from_slice(&local);
            for [s, first, len] in spans {
                ranges[s as usize] = [offset + first, len];
            }
        }
        ClippedCells {
            positions: b.positions,
            ranges,
            indices,
            clip: clip.clone(),
        }
    }

    /// Appends to `out` the corners of the cell whose boundary cycle starts at half-edge
    /// `start`: the clipped pieces of its edges in order and, where a piece ends on the region's
    /// boundary, the region's corners up to where the next piece starts.
    fn assemble_cell(
        &self,
        start: u32,
        pieces: &[[u32; 2]],
        b: &Builder,
        cell_pieces: &mut Vec<[u32; 2]>,
        out: &mut Vec<u32>,
    ) {
        cell_pieces.clear();
        let mut h = start;
        loop {
            let p = pieces[(h >> 1) as usize];
            if p[0] != INVALID {
                cell_pieces.push(if h & 1 == 0 { p } else { [p[1], p[0]] });
            }
            h = self.next[h as usize];
            if h == start {
                break;
            }
        }
        let Some(&[first_start, _]) = cell_pieces.first() else {
            return;
        };
        for (i, &[start, end]) in cell_pieces.iter().enumerate() {
            out.push(start);
            // The next piece's start, without a division per corner for the wrap-around.
            let next_start = cell_pieces.get(i + 1).map_or(first_start, |p| p[0]);
            // A piece ending on the boundary is followed by the boundary up to where the next
            // piece starts (nothing when the next piece starts right there).
            if end != next_start
                && let (Some(exit), Some(entry)) = (b.perimeter(end), b.perimeter(next_start))
            {
                out.push(end);
                b.corners_between(exit, entry, out);
            }
        }
    }

    /// The site owning point `p`; used when no edge crosses the region, i.e. the whole region
    /// lies in one cell.
    fn owner_of(&self, p: [f64; 2]) -> u32 {
        self.nearest_site(p, None).ok().flatten().unwrap_or(INVALID)
    }

    /// Clips the edge of even half-edge `h`: `[start, end]` positions, or `[INVALID; 2]` when
    /// nothing of positive length is left.
    fn clip_edge(&self, h: u32, vertex_position: &[u32], b: &mut Builder) -> [u32; 2] {
        const NONE: [u32; 2] = [INVALID, INVALID];
        let clip = b.clip;
        let m = clip.vertices().len();
        let (o, t) = (self.origin(h), self.target(h));
        // Parametrise as base + s·dir with s in [lo, hi]; the finite end (if any) is at s = 0.
        // An in-ray (from infinity) is clipped as the ray from its finite end, then reversed.
        let (base, dir, far, mut lo, mut hi, reversed) = match self.geometry(h) {
            EdgeGeometry::Segment { from, to } => {
                if vertex_position[o as usize] != INVALID && vertex_position[t as usize] != INVALID
                {
                    return [vertex_position[o as usize], vertex_position[t as usize]];
                }
                (
                    from,
                    [to[0] - from[0], to[1] - from[1]],
                    Some(to),
                    0.0,
                    1.0,
                    false,
                )
            }
            EdgeGeometry::Ray { origin, direction } => {
                (origin, direction, None, 0.0, f64::INFINITY, o == INVALID)
            }
            EdgeGeometry::Line { point, direction } => (
                point,
                direction,
                None,
                f64::NEG_INFINITY,
                f64::INFINITY,
                false,
            ),
        };
        let (mut enter, mut exit) = (usize::MAX, usize::MAX);
        for i in 0..m {
            let f0 = clip.edge_function(i, base);
            // For segments use the end's own edge function so the test agrees with the vertex's.
            let rate = match far {
                Some(to) => clip.edge_function(i, to) - f0,
                None => clip.edge_rate(i, dir),
            };
            if rate == 0.0 {
                if f0 < 0.0 {
                    return NONE;
                }
                continue;
            }
            let s = -f0 / rate;
            if rate > 0.0 {
                if s > lo {
                    lo = s;
                    enter = i;
                }
            } else if s < hi {
                hi = s;
                exit = i;
            }
        }
        if lo.partial_cmp(&hi) != Some(std::cmp::Ordering::Less) {
            return NONE;
        }
        let at = |s: f64| [base[0] + s * dir[0], base[1] + s * dir[1]];
        let start = if enter == usize::MAX {
            // No entering constraint: the start is the finite end of the edge, inside.
            let v = if reversed { t } else { o };
            vertex_position[v as usize]
        } else {
            b.crossing(enter, at(lo))
        };
        // Without an exit constraint a segment's far end is inside (a ray always exits).
        let end = if exit == usize::MAX {
            vertex_position[t as usize]
        } else {
            b.crossing(exit, at(hi))
        };
        if start == INVALID || end == INVALID || start == end {
            return NONE;
        }
        if reversed { [end, start] } else { [start, end] }
    }
}

impl ClippedCells {
    /// All vertex positions (corners of the region first, then Voronoi vertices inside it, then
    /// boundary crossings).
    pub fn positions(&self) -> &[[f64; 2]] {
        &self.positions
    }

    /// `[start, length]` of every site's cell in [`ClippedCells::indices`]: the cell of site `s`
    /// is `indices[start..start + length]`.
    pub fn cell_ranges(&self) -> &[[u32; 2]] {
        &self.ranges
    }

    /// Number of sites (cells, empty ones included).
    pub fn n_cells(&self) -> usize {
        self.ranges.len()
    }

    /// Position indices of all cells (in an internal, spatially coherent order; see
    /// [`ClippedCells::cell_ranges`]).
    pub fn indices(&self) -> &[u32] {
        &self.indices
    }

    /// The clip region.
    pub fn clip_region(&self) -> &ClipPolygon {
        &self.clip
    }

    /// Position indices of the cell of `site`, counter-clockwise (empty when the cell misses the
    /// region or the site is a duplicate).
    pub fn cell(&self, site: u32) -> Result<&[u32], VoronoiError> {
        let Some(&[start, len]) = self.ranges.get(site as usize) else {
            return Err(VoronoiError::InvalidSite {
                site,
                count: self.ranges.len(),
            });
        };
        Ok(&self.indices[start as usize..(start + len) as usize])
    }

    /// The polygon of the cell of `site`.
    pub fn cell_polygon(&self, site: u32) -> Result<Vec<[f64; 2]>, VoronoiError> {
        Ok(self
            .cell(site)?
            .iter()
            .map(|&i| self.positions[i as usize])
            .collect())
    }

    /// Area of the cell of `site` (0 for an empty cell).
    pub fn cell_area(&self, site: u32) -> Result<f64, VoronoiError> {
        Ok(polygon_area_centroid(&self.cell_polygon(site)?).0)
    }

    /// Centroid of the cell of `site`, `None` for an empty cell.
    pub fn cell_centroid(&self, site: u32) -> Result<Option<[f64; 2]>, VoronoiError> {
        let poly = self.cell_polygon(site)?;
        Ok(if poly.is_empty() {
            None
        } else {
            Some(polygon_area_centroid(&poly).1)
        })
    }

    /// The cells as a polygon soup (z = 0) with shared vertices, so the half-edge builder gets a
    /// connected mesh, plus the site of every face (empty cells are left out).
    pub fn to_polygon_soup(&self) -> (PolygonSoup, Vec<u32>) {
        let mut soup = PolygonSoup {
            positions: self.positions.iter().map(|p| [p[0], p[1], 0.0]).collect(),
            ..PolygonSoup::default()
        };
        let mut face_site = Vec::new();
        for (s, &[start, len]) in self.ranges.iter().enumerate() {
            let cell = &self.indices[start as usize..(start + len) as usize];
            if cell.len() >= 3 {
                soup.face_sizes.push(cell.len() as u32);
                soup.indices.extend_from_slice(cell);
                face_site.push(s as u32);
            }
        }
        (soup, face_site)
    }
}
