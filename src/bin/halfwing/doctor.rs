//! `halfwing doctor MODEL [--json]`: everything the doctor finds in a mesh file.

use crate::args::Args;
use crate::failure::{Failure, Outcome};
use crate::files::read_mesh;
use crate::progress::Progress;
use halfwing::doctor::{DoctorOptions, DoctorReport};
use halfwing::soup::PolygonSoup;

const HELP: &str = "\
usage: halfwing doctor MODEL [--json]

Examines MODEL (OBJ, OFF or PLY) and prints what is wrong with it: malformed faces, non-manifold
edges and vertices, orientation, boundary loops, components, duplicates, degenerate and
intersecting faces. With --json, prints every finding as one JSON object.
Exit codes: 0 MODEL is a closed polyhedron (closed, manifold, oriented outward, no
self-intersection, no zero-area face), 1 it is not, 2 usage error, 3 MODEL cannot be read
or its face list is malformed as a whole.
";

pub fn run(args: &[String]) -> Outcome {
    let Some(args) = Args::parse(args, &["--json"], &[])? else {
        print!("{HELP}");
        return Ok(0);
    };
    let [path] = args.positional(&["MODEL"])? else {
        unreachable!("one positional argument")
    };
    let soup = read_mesh(path)?;
    let report = examine(path, &soup)?;
    if args.flag("--json") {
        println!("{}", report.to_json());
    } else {
        print!("{report}");
    }
    Ok(u8::from(report.not_a_closed_polyhedron().is_some()))
}

/// The doctor's report on `soup`, read from `path`, with the default options.
pub fn examine(path: &str, soup: &PolygonSoup) -> Result<DoctorReport, Failure> {
    let _progress = Progress::start(format!("examining {path}"));
    halfwing::doctor::examine(&soup.as_face_list(), &DoctorOptions::default())
        .map_err(|e| Failure::input(format!("{path}: {e}")))
}
