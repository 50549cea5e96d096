//! Buffers that draw one kind of the doctor's findings over the face list it examined: the
//! faces it names filled, its edges (and the boxes of small components) as lines, its vertices
//! as points.

use crate::doctor::{DoctorReport, Finding};
use crate::soup::{FaceList, FaceTable};

use super::error::RenderError;
use super::line_buffer::push_point;
use super::{Bounds, LineBuffer, PolygonBuffer, PolygonList, polygon_buffer};

/// One finding, ready to draw.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct FindingBuffers {
    /// The faces the finding names, each once, with their own corners: fills and outlines.
    /// Its polygon numbers (`vertex_polygons`, `triangle_polygons`, outline sources) are face
    /// ids of the examined list.
    pub faces: PolygonBuffer,
    /// The edges the finding names, and the 12 edges of each small component's bounding box:
    /// each segment's source is the item of the finding it shows.
    pub lines: LineBuffer,
    /// x y z of every vertex the finding names (`GL_POINTS`).
    pub points: Vec<f32>,
    /// Per point, the item of the finding it shows.
    pub point_items: Vec<u32>,
    /// The box around all of it.
    pub bounds: Bounds,
}

/// The buffers of `kind` in `report`, which must be the doctor's report on `list` (see
/// [`DoctorReport::highlight`] for what each kind draws). Faces on NaN or infinite positions
/// cannot be drawn and are left out, and so are such vertices and edges; everything else the
/// finding names is drawn.
///
/// # Errors
/// [`RenderError::ReportMismatch`] when the report names a face or vertex `list` does not
/// have (it is the report of another list); [`RenderError::MalformedFaceList`] when the sizes
/// of `list` do not add up to its indices.
pub fn finding_buffers(
    report: &DoctorReport,
    kind: Finding,
    list: &FaceList<'_>,
) -> Result<FindingBuffers, RenderError> {
    let table = FaceTable::new(list)
        .map_err(|problem| RenderError::MalformedFaceList(problem.to_string()))?;
    let mismatch = |what, id, count| RenderError::ReportMismatch { what, id, count };
    let highlight = report.highlight(kind);
    let position = |v: u32| -> Result<Option<[f64; 3]>, RenderError> {
        let p = *list
            .positions
            .get(v as usize)
            .ok_or_else(|| mismatch("vertex", v, list.positions.len()))?;
        Ok(p.iter().all(|x| x.is_finite()).then_some(p))
    };

    let mut faces: Vec<u32> = highlight.faces.iter().map(|&(_, f)| f).collect();
    faces.sort_unstable();
    faces.dedup();
    let mut corners = Vec::new();
    let mut sizes = Vec::new();
    let mut drawn_faces = Vec::new();
    for &f in &faces {
        if f as usize >= table.n_faces() {
            return Err(mismatch("face", f, table.n_faces()));
        }
        let face = table.face(f as usize);
        let points: Option<Vec<[f64; 3]>> = face
            .iter()
            .map(|&v| position(v))
            .collect::<Result<_, _>>()?;
        if let Some(points) = points.filter(|p| p.len() >= 3) {
            corners.extend(points);
            sizes.push(face.len() as u32);
            drawn_faces.push(f);
        }
    }
    let mut fills = polygon_buffer(&PolygonList {
        corners: &corners,
        sizes: &sizes,
    })?;
    let face_id = |polygon: &mut u32| *polygon = drawn_faces[*polygon as usize];
    fills.vertex_polygons.iter_mut().for_each(face_id);
    fills.triangle_polygons.iter_mut().for_each(face_id);
    fills.outline.sources.iter_mut().for_each(face_id);

    let mut lines = LineBuffer::default();
    for &(item, [a, b]) in &highlight.edges {
        if let (Some(a), Some(b)) = (position(a)?, position(b)?) {
            lines.push(a, b, item);
        }
    }
    for &(item, [low, high]) in &highlight.boxes {
        push_box(&mut lines, low, high, item);
    }
    let mut points = Vec::new();
    let mut point_items = Vec::new();
    for &(item, v) in &highlight.vertices {
        if let Some(p) = position(v)? {
            push_point(&mut points, p);
            point_items.push(item);
        }
    }
    let bounds = fills
        .bounds
        .union(Bounds::of_points(&lines.positions))
        .union(Bounds::of_points(&points));
    Ok(FindingBuffers {
        faces: fills,
        lines,
        points,
        point_items,
        bounds,
    })
}

/// The 12 edges of the box from `low` to `high`.
fn push_box(lines: &mut LineBuffer, low: [f64; 3], high: [f64; 3], item: u32) {
    let corner = |bits: usize| [0, 1, 2].map(|k| if bits >> k & 1 == 0 { low[k] } else { high[k] });
    for bits in 0..8 {
        for k in 0..3 {
            if bits >> k & 1 == 0 {
                lines.push(corner(bits), corner(bits | 1 << k), item);
            }
        }
    }
}
