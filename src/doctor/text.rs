//! The report as text (a summary line, then a line per non-empty finding naming its first few
//! elements) and as JSON (every element of every finding).

use std::fmt::{self, Write};

use super::{DoctorReport, Finding};
use crate::support::counted::counted;

/// How many elements of a finding the text names before counting the rest.
const SHOWN: usize = 8;

impl fmt::Display for DoctorReport {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let verdict = match self.not_a_closed_polyhedron() {
            None => "a closed polyhedron".to_string(),
            Some(reason) => format!("not a closed polyhedron: {reason}"),
        };
        writeln!(
            f,
            "{}, {}; {}",
            counted(self.components.len(), "component", "components"),
            counted(self.boundary_loops.len(), "boundary loop", "boundary loops"),
            verdict
        )?;
        if !self.diagnostic.is_clean() {
            writeln!(f, "{}", self.diagnostic)?;
        }
        for (i, component) in self.components.iter().enumerate().take(SHOWN) {
            write!(
                f,
                "component {i}: {}, Euler characteristic {}",
                counted(component.n_faces, "face", "faces"),
                component.euler_characteristic
            )?;
            if let Some(genus) = component.genus {
                write!(f, ", genus {genus}")?;
            }
            if let Some(volume) = component.volume {
                write!(f, ", volume {volume}")?;
            }
            if !component.orientable {
                write!(f, ", not orientable")?;
            }
            writeln!(f)?;
        }
        let counted = |f: &mut fmt::Formatter<'_>, label: &str, items: Vec<String>| {
            if items.is_empty() {
                return Ok(());
            }
            write!(f, "{} {label}:", items.len())?;
            for item in items.iter().take(SHOWN) {
                write!(f, " {item}")?;
            }
            if items.len() > SHOWN {
                write!(f, " and {} more", items.len() - SHOWN)?;
            }
            writeln!(f)
        };
        let faces = |ids: &[u32]| ids.iter().map(|id| format!("f{id}")).collect();
        let edges = |ends: &[[u32; 2]]| ends.iter().map(|[a, b]| format!("v{a}-v{b}")).collect();
        let pairs = |pairs: &[[u32; 2]], prefix: &str| {
            pairs
                .iter()
                .map(|[a, b]| format!("{prefix}{a}={prefix}{b}"))
                .collect()
        };
        counted(
            f,
            Finding::SmallComponents.name(),
            self.small_components
                .iter()
                .map(|c| format!("#{c}"))
                .collect(),
        )?;
        counted(
            f,
            Finding::NonOrientableWitness.name(),
            faces(&self.non_orientable_witness),
        )?;
        counted(
            f,
            Finding::ZeroLengthEdges.name(),
            edges(&self.zero_length_edges),
        )?;
        counted(f, Finding::Needles.name(), faces(&self.needles))?;
        counted(f, Finding::Caps.name(), faces(&self.caps))?;
        counted(
            f,
            Finding::FoldedEdges.name(),
            self.folded_edges
                .iter()
                .map(|e| format!("v{}-v{}", e.vertices[0], e.vertices[1]))
                .collect(),
        )?;
        counted(f, Finding::LongEdges.name(), edges(&self.long_edges))?;
        counted(
            f,
            Finding::DuplicatePositions.name(),
            pairs(&self.duplicate_positions, "v"),
        )?;
        counted(
            f,
            Finding::NearDuplicateVertices.name(),
            pairs(&self.near_duplicate_vertices, "v"),
        )?;
        counted(
            f,
            Finding::DuplicateFaces.name(),
            pairs(&self.duplicate_faces, "f"),
        )?;
        counted(
            f,
            Finding::TVertices.name(),
            self.t_vertices
                .iter()
                .map(|t| format!("v{} on v{}-v{}", t.vertex, t.edge[0], t.edge[1]))
                .collect(),
        )?;
        counted(
            f,
            Finding::SelfIntersections.name(),
            self.self_intersections
                .iter()
                .map(|[a, b]| format!("f{a}×f{b}"))
                .collect(),
        )
    }
}

impl DoctorReport {
    /// The whole report as one JSON object: every finding with every element (keys as the
    /// fields are named). Non-finite numbers are written as `null`.
    pub fn to_json(&self) -> String {
        let mut out = String::new();
        let d = &self.diagnostic;
        out.push('{');
        let verdict = self.not_a_closed_polyhedron();
        let _ = write!(
            out,
            "\"closed_polyhedron\":{},\"reason\":{},\"manifold\":{},\"closed\":{},\"oriented\":{}",
            verdict.is_none(),
            verdict.map_or("null".to_string(), json_string),
            self.is_manifold(),
            self.is_closed(),
            self.is_oriented()
        );
        let ids = [
            ("faces_too_small", &d.faces_too_small),
            ("faces_out_of_range", &d.faces_out_of_range),
            ("faces_repeated_vertex", &d.faces_repeated_vertex),
            ("non_finite_vertices", &d.non_finite_vertices),
            ("non_manifold_vertices", &d.non_manifold_vertices),
            ("unreferenced_vertices", &d.isolated_vertices),
            ("zero_area_faces", &d.degenerate_faces),
            ("small_components", &self.small_components),
            ("non_orientable_witness", &self.non_orientable_witness),
            ("needles", &self.needles),
            ("caps", &self.caps),
        ];
        for (key, list) in ids {
            let _ = write!(
                out,
                ",\"{key}\":{}",
                json_list(list.iter().map(u32::to_string))
            );
        }
        let pair = |[a, b]: &[u32; 2]| format!("[{a},{b}]");
        let pairs = [
            ("zero_length_edges", &self.zero_length_edges),
            ("long_edges", &self.long_edges),
            ("duplicate_positions", &self.duplicate_positions),
            ("near_duplicate_vertices", &self.near_duplicate_vertices),
            ("duplicate_faces", &self.duplicate_faces),
            ("self_intersections", &self.self_intersections),
        ];
        for (key, list) in pairs {
            let _ = write!(out, ",\"{key}\":{}", json_list(list.iter().map(pair)));
        }
        let edge_reports = [
            ("non_manifold_edges", &d.non_manifold_edges),
            ("inconsistent_edges", &d.inconsistent_edges),
        ];
        let edge = |vertices: [u32; 2], faces: &[u32]| {
            format!(
                "{{\"vertices\":[{},{}],\"faces\":{}}}",
                vertices[0],
                vertices[1],
                json_list(faces.iter().map(u32::to_string))
            )
        };
        for (key, list) in edge_reports {
            let edges = list.iter().map(|e| edge(e.vertices, &e.faces));
            let _ = write!(out, ",\"{key}\":{}", json_list(edges));
        }
        let folded = self.folded_edges.iter().map(|e| edge(e.vertices, &e.faces));
        let _ = write!(out, ",\"folded_edges\":{}", json_list(folded));
        let fans = self.non_manifold_vertex_fans.iter().map(|v| {
            let fans = v
                .fans
                .iter()
                .map(|fan| json_list(fan.iter().map(u32::to_string)));
            format!("{{\"vertex\":{},\"fans\":{}}}", v.vertex, json_list(fans))
        });
        let _ = write!(out, ",\"non_manifold_vertex_fans\":{}", json_list(fans));
        let loops = self.boundary_loops.iter().map(|l| {
            format!(
                "{{\"vertices\":{},\"perimeter\":{},\"face\":{}}}",
                json_list(l.vertices.iter().map(u32::to_string)),
                json_number(l.perimeter),
                l.face
            )
        });
        let _ = write!(out, ",\"boundary_loops\":{}", json_list(loops));
        let components = self.components.iter().map(|c| {
            format!(
                "{{\"first_face\":{},\"faces\":{},\"edges\":{},\"vertices\":{},\
                 \"boundary_loops\":{},\"euler_characteristic\":{},\"genus\":{},\"closed\":{},\
                 \"manifold\":{},\"orientable\":{},\"consistently_oriented\":{},\"volume\":{},\
                 \"outward\":{},\
                 \"area\":{},\"bounding_box\":[{},{}]}}",
                c.first_face,
                c.n_faces,
                c.n_edges,
                c.n_vertices,
                c.n_boundary_loops,
                c.euler_characteristic,
                c.genus.map_or("null".to_string(), |g| g.to_string()),
                c.closed,
                c.manifold,
                c.orientable,
                c.consistently_oriented,
                c.volume.map_or("null".to_string(), json_number),
                c.outward.map_or("null".to_string(), |o| o.to_string()),
                json_number(c.area),
                json_list(c.bounding_box[0].iter().map(|&x| json_number(x))),
                json_list(c.bounding_box[1].iter().map(|&x| json_number(x))),
            )
        });
        let _ = write!(out, ",\"components\":{}", json_list(components));
        let t_vertices = self.t_vertices.iter().map(|t| {
            format!(
                "{{\"vertex\":{},\"edge\":[{},{}],\"face\":{}}}",
                t.vertex, t.edge[0], t.edge[1], t.face
            )
        });
        let _ = write!(out, ",\"t_vertices\":{}", json_list(t_vertices));
        out.push('}');
        out
    }
}

fn json_list(items: impl Iterator<Item = String>) -> String {
    let items: Vec<String> = items.collect();
    format!("[{}]", items.join(","))
}

/// A finite number as JSON writes it (shortest round-trip form), else `null`.
fn json_number(x: f64) -> String {
    if x.is_finite() {
        format!("{x:?}")
    } else {
        "null".to_string()
    }
}

fn json_string(text: &str) -> String {
    let mut out = String::from("\"");
    for ch in text.chars() {
        match ch {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if (c as u32) < 0x20 => {
                let _ = write!(out, "\\u{:04x}", c as u32);
            }
            c => out.push(c),
        }
    }
    out.push('"');
    out
}
