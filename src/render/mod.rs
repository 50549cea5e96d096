//! Rendering buffers: what `glBufferData` wants (the seed's VBO/EBO slide). Polygon faces become
//! triangle index buffers here by ear clipping.

mod triangulate;

pub use triangulate::{
    EarClipper, FallbackReason, PolygonOutcome, TriangleBuffer, TriangulateError,
    triangulate_faces, triangulate_polygon,
};
