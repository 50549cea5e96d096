//! Line segments as `glDrawArrays(GL_LINES)` wants them: two `f32` xyz points per segment.

/// A list of line segments, each with the id of the element it shows.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct LineBuffer {
    /// x y z of both ends of every segment: 6 floats per segment.
    pub positions: Vec<f32>,
    /// Per segment, the id of what it draws (an edge, a vertex, a face or a polygon; each builder
    /// says which), so a picked segment leads back to the mesh.
    pub sources: Vec<u32>,
}

impl LineBuffer {
    /// Number of segments.
    pub fn n_segments(&self) -> usize {
        self.sources.len()
    }

    /// Number of points (twice the segments): the `count` of `glDrawArrays`.
    pub fn n_points(&self) -> usize {
        2 * self.sources.len()
    }

    /// Appends the segment from `a` to `b`.
    pub fn push(&mut self, a: [f64; 3], b: [f64; 3], source: u32) {
        push_point(&mut self.positions, a);
        push_point(&mut self.positions, b);
        self.sources.push(source);
    }
}

/// Appends a point as three `f32`s: GPUs want single precision, the kernels keep `f64`.
pub(crate) fn push_point(out: &mut Vec<f32>, p: [f64; 3]) {
    out.extend(p.map(|c| c as f32));
}
