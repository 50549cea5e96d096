//! Nearest-site queries: greedy descent on the Delaunay graph with exact distance comparisons.

use super::delaunay::{Delaunay, Dimension, INVALID};
use super::diagram::Voronoi;
use super::error::VoronoiError;
use super::exact_distance::Metric;
use super::ids::{DelaunayHalfedgeId, SiteId};
use super::incremental::{next_edge, prev_edge};
use std::cmp::Ordering;

impl Delaunay {
    /// Delaunay neighbours of site `v` (counter-clockwise in the planar case; along the line in
    /// the collinear case; empty for duplicates).
    pub fn neighbours(&self, v: SiteId) -> Vec<SiteId> {
        let mut out = Vec::new();
        self.neighbours_into(v.0, &mut out);
        out.into_iter().map(SiteId).collect()
    }

    pub(crate) fn neighbours_into(&self, v: u32, out: &mut Vec<u32>) {
        out.clear();
        match self.dimension {
            Dimension::Plane => {
                let mut last = INVALID;
                for DelaunayHalfedgeId(e) in self.outgoing(SiteId(v)) {
                    out.push(self.triangles[next_edge(e) as usize]);
                    last = e;
                }
                if last != INVALID && self.twins[prev_edge(last) as usize] == INVALID {
                    out.push(self.triangles[prev_edge(last) as usize]);
                }
            }
            Dimension::Line => {
                if let Some(k) = self.hull.iter().position(|&s| s == v) {
                    out.extend(k.checked_sub(1).map(|i| self.hull[i]));
                    out.extend(self.hull.get(k + 1).copied());
                }
            }
            Dimension::Empty | Dimension::Point => {}
        }
    }

    /// The site nearest to `p` (Euclidean, exact; ties go to the smallest index), starting the
    /// descent at `hint` when given (a nearby site makes the query O(1)). `None` without sites.
    ///
    /// Greedy descent is exact on a Delaunay graph: a site that is not nearest always has a
    /// strictly nearer Delaunay neighbour.
    pub fn nearest_site(
        &self,
        p: [f64; 2],
        hint: Option<SiteId>,
    ) -> Result<Option<SiteId>, VoronoiError> {
        if !(p[0].is_finite() && p[1].is_finite()) {
            return Err(VoronoiError::NonFiniteQuery);
        }
        let Some(&first) = self.hull.first() else {
            return Ok(None);
        };
        let start = hint
            .and_then(|h| self.representative_of(h))
            .map_or(first, |h| h.0);
        let mut scratch = Vec::new();
        Ok(Some(SiteId(self.descend(p, start, &mut scratch))))
    }

    /// Greedy descent plus tie resolution; `scratch` avoids allocation in tight loops.
    pub(crate) fn descend(&self, p: [f64; 2], start: u32, scratch: &mut Vec<u32>) -> u32 {
        let (frame, q) = self.query_frame(p);
        let mut v = start;
        if self.dimension == Dimension::Line {
            // The chain may be long; binary search along it instead of walking.
            v = self.nearest_on_line(q, frame);
        }
        loop {
            self.neighbours_into(v, scratch);
            let mut best = v;
            for &w in scratch.iter() {
                if Metric::Euclidean.compare(q, frame[w as usize], frame[best as usize])
                    == Ordering::Less
                {
                    best = w;
                }
            }
            if best == v {
                break;
            }
            v = best;
        }
        // Equidistant nearest sites lie on an empty circle and are linked by Delaunay edges.
        let mut tied = vec![v];
        let mut k = 0;
        while k < tied.len() {
            let u = tied[k];
            self.neighbours_into(u, scratch);
            for &w in scratch.iter() {
                if !tied.contains(&w)
                    && Metric::Euclidean.compare(q, frame[w as usize], frame[v as usize])
                        == Ordering::Equal
                {
                    tied.push(w);
                }
            }
            k += 1;
        }
        tied.into_iter().min().unwrap_or(v)
    }

    /// Sites and query in the exact (scaled) frame when the query survives scaling.
    fn query_frame(&self, p: [f64; 2]) -> (&[[f64; 2]], [f64; 2]) {
        let q = [p[0] * self.scale, p[1] * self.scale];
        if q[0].is_finite() && q[1].is_finite() {
            (self.scaled(), q)
        } else {
            (&self.sites, p)
        }
    }

    fn nearest_on_line(&self, q: [f64; 2], frame: &[[f64; 2]]) -> u32 {
        // Distance to the chain's sites is unimodal along the line.
        let chain = &self.hull;
        let (mut lo, mut hi) = (0usize, chain.len() - 1);
        while lo < hi {
            let mid = (lo + hi) / 2;
            let c = Metric::Euclidean.compare(
                q,
                frame[chain[mid] as usize],
                frame[chain[mid + 1] as usize],
            );
            if c == Ordering::Greater {
                lo = mid + 1
            } else {
                hi = mid
            }
        }
        chain[lo]
    }
}

impl Voronoi {
    /// The site whose cell contains `p` (see [`Delaunay::nearest_site`]).
    pub fn nearest_site(
        &self,
        p: [f64; 2],
        hint: Option<SiteId>,
    ) -> Result<Option<SiteId>, VoronoiError> {
        self.delaunay.nearest_site(p, hint)
    }
}
