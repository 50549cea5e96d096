//! Table output: the three namings and three formats, on a mesh with a boundary.

use halfwing::soup::{BuildPolicy, FaceList};
use halfwing::winged::{Naming, TableFormat, Winged};

/// Two triangles sharing edge 1-2: five edges, four of them on the boundary.
fn two_triangles() -> Winged {
    let positions = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [1.0, 1.0, 0.5],
    ];
    let indices = [0, 1, 2, 2, 1, 3];
    Winged::from_face_list(
        &FaceList::triangles(&positions, &indices),
        BuildPolicy::Strict,
    )
    .unwrap()
    .0
}

#[test]
fn text_tables_align_columns_and_mark_holes() {
    let w = two_triangles();
    let text = w.edge_table(Naming::DirectInverse, TableFormat::Text);
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 6);
    assert_eq!(
        lines[0].split_whitespace().collect::<Vec<_>>(),
        ["Id", "Vi", "Vf", "Cd", "Ci", "Ada", "Ads", "Aia", "Ais"]
    );
    // Edge 0 (0 -> 1) borders face 0 and a hole; the hole's wings run round the boundary.
    assert_eq!(
        lines[1].split_whitespace().collect::<Vec<_>>(),
        ["0", "0", "1", "0", "∅", "2", "1", "3", "2"]
    );
    // Edge 1 (1 -> 2) is shared: face 0 walks it forward, face 1 backward.
    assert_eq!(
        lines[2].split_whitespace().collect::<Vec<_>>(),
        ["1", "1", "2", "0", "1", "0", "2", "4", "3"]
    );
    // Columns line up: every row's second column starts where the header's does.
    let column = lines[0].find("Vi").unwrap();
    assert!(
        lines[1..]
            .iter()
            .all(|l| l[column..].starts_with(|c: char| c.is_ascii_digit()))
    );
}

#[test]
fn markdown_and_csv_follow_the_naming() {
    let w = two_triangles();
    let md = w.face_table(Naming::LeftRight, TableFormat::Markdown);
    assert_eq!(md, "| face | edge |\n|---|---|\n| 0 | 0 |\n| 1 | 1 |\n");
    let csv = w.edge_table(Naming::LeftRight, TableFormat::Csv);
    assert_eq!(
        csv.lines().next().unwrap(),
        "edge,vert_origin,vert_destination,face_left,face_right,edge_left_cw,edge_left_ccw,edge_right_cw,edge_right_ccw"
    );
    assert_eq!(csv.lines().nth(1).unwrap(), "0,0,1,0,,2,1,3,2");
    let cw = w.edge_table(Naming::ClockwiseCounterclockwise, TableFormat::Markdown);
    assert_eq!(
        cw.lines().nth(2).unwrap(),
        "| E1 | V1 | V2 | E3 | E2 | E4 | E3 | F1 | ∅ |"
    );
    let vertices = w.vertex_table(Naming::ClockwiseCounterclockwise, TableFormat::Csv);
    assert_eq!(vertices.lines().nth(4).unwrap(), "V4,1,1,0.5,E4");
    let all = w.tables(Naming::DirectInverse, TableFormat::Csv);
    assert_eq!(all.matches("Id,").count(), 3);
}
