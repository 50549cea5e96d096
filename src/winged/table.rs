//! The vertex, face and edge tables in the textbook layout (plain text, Markdown or CSV).

use super::structure::Winged;

/// Which convention's column names (and element labels) a table uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Naming {
    /// Baumgart's (his cube): `VSTART VEND EPCW ENCW EPCCW ENCCW FCW FCCW`, elements
    /// labelled from 1 with a letter (`V1`, `E1`, `F1`).
    ClockwiseCounterclockwise,
    /// Granada's: `Vi Vf Cd Ci Ada Ads Aia Ais`, elements numbered from 0.
    DirectInverse,
    /// Wikipedia's: `vert_origin … edge_right_ccw`, elements numbered from 0.
    LeftRight,
}

/// How a table is written.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TableFormat {
    /// Columns aligned with spaces; a missing element (a hole) is `∅`.
    Text,
    /// A Markdown table; a missing element is `∅`.
    Markdown,
    /// Comma-separated values with a header row; a missing element is an empty field.
    Csv,
}

/// Column headers and labelling of one naming convention.
struct Headers {
    vertex: [&'static str; 5],
    face: [&'static str; 2],
    edge: [&'static str; 9],
    /// Label prefixes for vertices, edges and faces; `None` numbers from 0 without a prefix.
    prefixes: Option<[&'static str; 3]>,
}

impl Naming {
    fn headers(self) -> Headers {
        match self {
            Naming::ClockwiseCounterclockwise => Headers {
                vertex: ["VERTEX", "X", "Y", "Z", "ESTART"],
                face: ["FACE", "ESTART"],
                edge: [
                    "EDGE", "VSTART", "VEND", "EPCW", "ENCW", "EPCCW", "ENCCW", "FCW", "FCCW",
                ],
                prefixes: Some(["V", "E", "F"]),
            },
            Naming::DirectInverse => Headers {
                vertex: ["Id", "X", "Y", "Z", "Arista"],
                face: ["Id", "Arista"],
                edge: ["Id", "Vi", "Vf", "Cd", "Ci", "Ada", "Ads", "Aia", "Ais"],
                prefixes: None,
            },
            Naming::LeftRight => Headers {
                vertex: ["vertex", "x", "y", "z", "edge"],
                face: ["face", "edge"],
                edge: [
                    "edge",
                    "vert_origin",
                    "vert_destination",
                    "face_left",
                    "face_right",
                    "edge_left_cw",
                    "edge_left_ccw",
                    "edge_right_cw",
                    "edge_right_ccw",
                ],
                prefixes: None,
            },
        }
    }
}

/// Element kinds, indexing `Headers::prefixes`.
#[derive(Clone, Copy)]
enum Kind {
    Vertex = 0,
    Edge = 1,
    Face = 2,
}

struct Labeller {
    prefixes: Option<[&'static str; 3]>,
    missing: &'static str,
}

impl Labeller {
    fn label(&self, kind: Kind, id: u32) -> String {
        if id == u32::MAX {
            return self.missing.to_string();
        }
        match self.prefixes {
            Some(p) => format!("{}{}", p[kind as usize], u64::from(id) + 1),
            None => id.to_string(),
        }
    }
}

impl Winged {
    /// The vertex table: id, coordinates, stored edge (Baumgart's "Vertex-Edge table").
    pub fn vertex_table(&self, naming: Naming, format: TableFormat) -> String {
        let headers = naming.headers();
        let l = labeller(&headers, format);
        let rows = self.vertices().map(|v| {
            let p = self.positions[v.index()];
            vec![
                l.label(Kind::Vertex, v.0),
                p[0].to_string(),
                p[1].to_string(),
                p[2].to_string(),
                l.label(Kind::Edge, self.vertex_edge[v.index()].0),
            ]
        });
        render(&headers.vertex, rows, format)
    }

    /// The face table: id and stored edge (Baumgart's "Face-Edge table").
    pub fn face_table(&self, naming: Naming, format: TableFormat) -> String {
        let headers = naming.headers();
        let l = labeller(&headers, format);
        let rows = self.faces().map(|f| {
            vec![
                l.label(Kind::Face, f.0),
                l.label(Kind::Edge, self.face_edge[f.index()].0),
            ]
        });
        render(&headers.face, rows, format)
    }

    /// The edge table (Baumgart's "Edge-Edge relation"), columns in the convention's order.
    pub fn edge_table(&self, naming: Naming, format: TableFormat) -> String {
        let headers = naming.headers();
        let l = labeller(&headers, format);
        let rows = self.edges().map(|e| {
            let r = self.rec(e);
            let vertices = [
                l.label(Kind::Vertex, r.start.0),
                l.label(Kind::Vertex, r.end.0),
            ];
            let faces = [
                l.label(Kind::Face, r.left_face.0),
                l.label(Kind::Face, r.right_face.0),
            ];
            let wings = [r.left_prev, r.left_next, r.right_prev, r.right_next]
                .map(|w| l.label(Kind::Edge, w.0));
            let mut row = vec![l.label(Kind::Edge, e.0)];
            row.extend(vertices);
            if naming == Naming::ClockwiseCounterclockwise {
                row.extend(wings);
                row.extend(faces);
            } else {
                row.extend(faces);
                row.extend(wings);
            }
            row
        });
        render(&headers.edge, rows, format)
    }

    /// The three tables, vertex, face and edge, one after another separated by a blank line.
    pub fn tables(&self, naming: Naming, format: TableFormat) -> String {
        [
            self.vertex_table(naming, format),
            self.face_table(naming, format),
            self.edge_table(naming, format),
        ]
        .join("\n")
    }
}

fn labeller(headers: &Headers, format: TableFormat) -> Labeller {
    let missing = if format == TableFormat::Csv {
        ""
    } else {
        "∅"
    };
    Labeller {
        prefixes: headers.prefixes,
        missing,
    }
}

/// Writes a header and rows in `format`; every line ends with a newline.
fn render(header: &[&str], rows: impl Iterator<Item = Vec<String>>, format: TableFormat) -> String {
    let mut table: Vec<Vec<String>> = vec![header.iter().map(|h| h.to_string()).collect()];
    table.extend(rows);
    let mut out = String::new();
    match format {
        TableFormat::Csv => {
            for row in &table {
                out.push_str(&row.join(","));
                out.push('\n');
            }
        }
        TableFormat::Markdown => {
            for (i, row) in table.iter().enumerate() {
                out.push_str(&format!("| {} |\n", row.join(" | ")));
                if i == 0 {
                    out.push_str(&format!("|{}\n", "---|".repeat(row.len())));
                }
            }
        }
        TableFormat::Text => {
            let mut widths = vec![0usize; header.len()];
            for row in &table {
                for (w, cell) in widths.iter_mut().zip(row) {
                    *w = (*w).max(cell.chars().count());
                }
            }
            for row in &table {
                let cells: Vec<String> = row
                    .iter()
                    .zip(&widths)
                    .map(|(cell, &w)| format!("{cell:<w$}"))
                    .collect();
                out.push_str(cells.join("  ").trim_end());
                out.push('\n');
            }
        }
    }
    out
}
