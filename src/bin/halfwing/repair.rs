//! `halfwing repair IN OUT [options]`: the repair pipeline on a mesh file, with its report.

use crate::args::Args;
use crate::convert::ply_binary;
use crate::failure::{Failure, Outcome};
use crate::files::{read_mesh, write_mesh};
use crate::progress::Progress;
use halfwing::repair::{
    FillMode, HoleFillOptions, RepairOptions, SmallComponents, Tolerance, repair_mesh,
};

const HELP: &str = "\
usage: halfwing repair IN OUT [options]

Repairs IN and writes the result to OUT (format by extension, as for convert): merges duplicate
vertices, removes duplicate faces, builds a manifold (splitting non-manifold vertices, cutting
non-manifold edges, orienting faces consistently and closed parts outward, leaving out faces that
cannot be kept), mends degenerate triangles (collapsing short edges, flipping caps), splits
boundary edges at T-vertices, stitches borders, optionally fills holes and removes small
components, removes
unreferenced vertices. Prints what became of the input's vertices and faces.

options:
  --merge-tolerance T     merge vertices at most T apart (default 0: identical positions)
  --merge-relative R      ... at most R (0 to 1) times the bounding-box diagonal apart
  --degenerate-tolerance T  mend triangles whose corners are within T of a line (default 0:
                          exactly on one line)
  --degenerate-relative R ... within R times the diagonal
  --keep-degenerate-faces leave degenerate triangles as they are
  --t-vertex-tolerance T  split boundary edges at boundary vertices at most T from them
                          (default 0: exactly on the edge)
  --t-vertex-relative R   ... at most R times the diagonal from them
  --keep-t-vertices       leave T-vertices as they are
  --stitch-tolerance T    stitch boundary edges whose ends are at most T apart (default 0)
  --stitch-relative R     ... at most R times the diagonal apart
  --fill-holes N          fill holes of at most N boundary edges (default: none filled; a fill
                          that would fold or intersect the mesh is refused, the hole left open)
  --refine                ... and refine each fill: new vertices inside the hole so that its
                          edges match those of the mesh at the rim
  --fair                  ... refine, then move the new vertices to continue the surface around
                          the hole smoothly (a fill whose fairing does not converge is refused)
  --small-faces N         remove components of at most N faces
  --small-diameter R      remove components at most R (0 to 1) times the largest one's size
  --binary | --ascii      PLY encoding of OUT (default binary)
Exit codes: 0 success, 2 usage error or an option out of range, 3 IN cannot be read or is
malformed as a whole, 4 OUT cannot be written.
";

pub fn run(args: &[String]) -> Outcome {
    let Some(args) = Args::parse(
        args,
        &[
            "--binary",
            "--ascii",
            "--keep-degenerate-faces",
            "--keep-t-vertices",
            "--refine",
            "--fair",
        ],
        &[
            "--merge-tolerance",
            "--merge-relative",
            "--degenerate-tolerance",
            "--degenerate-relative",
            "--t-vertex-tolerance",
            "--t-vertex-relative",
            "--stitch-tolerance",
            "--stitch-relative",
            "--fill-holes",
            "--small-faces",
            "--small-diameter",
        ],
    )?
    else {
        print!("{HELP}");
        return Ok(0);
    };
    let [input, output] = args.positional(&["IN", "OUT"])? else {
        unreachable!("two positional arguments")
    };
    let binary = ply_binary(&args, output)?;
    let options = RepairOptions {
        merge_tolerance: tolerance(&args, "--merge-tolerance", "--merge-relative")?,
        degenerate_tolerance: optional_step(
            &args,
            "--keep-degenerate-faces",
            "--degenerate-tolerance",
            "--degenerate-relative",
        )?,
        t_vertex_tolerance: optional_step(
            &args,
            "--keep-t-vertices",
            "--t-vertex-tolerance",
            "--t-vertex-relative",
        )?,
        stitch_tolerance: tolerance(&args, "--stitch-tolerance", "--stitch-relative")?,
        fill_holes: match (args.parsed::<usize>("--fill-holes")?, fill_mode(&args)) {
            (Some(max_edges), mode) => Some(HoleFillOptions {
                max_edges,
                mode,
                ..HoleFillOptions::default()
            }),
            (None, FillMode::Triangulate) => None,
            (None, _) => {
                return Err(Failure::usage(
                    "--refine and --fair need --fill-holes N".into(),
                ));
            }
        },
        small_components: match (
            args.parsed::<usize>("--small-faces")?,
            args.parsed::<f64>("--small-diameter")?,
        ) {
            (Some(_), Some(_)) => {
                return Err(Failure::usage(
                    "--small-faces and --small-diameter exclude each other".into(),
                ));
            }
            (Some(n), None) => Some(SmallComponents::FaceCount(n)),
            (None, Some(r)) => Some(SmallComponents::RelativeDiameter(r)),
            (None, None) => None,
        },
    };
    let soup = read_mesh(input)?;
    let (mesh, fates) = {
        let _progress = Progress::start(format!("repairing {input}"));
        repair_mesh(&soup, &options).map_err(|e| match e {
            halfwing::repair::RepairError::BadTolerance { .. }
            | halfwing::repair::RepairError::BadOption { .. } => Failure::usage(e.to_string()),
            _ => Failure::input(format!("{input}: {e}")),
        })?
    };
    write_mesh(output, &mesh.to_soup(), binary)?;
    let counts = fates.counts();
    println!("{input} -> {output}");
    println!(
        "vertices: {} in, {} out: {} kept, {} merged, {} removed, {} added",
        soup.positions.len(),
        mesh.n_vertices(),
        counts.kept_vertices,
        counts.merged_vertices,
        counts.removed_vertices,
        counts.added_vertices
    );
    println!(
        "faces:    {} in, {} out: {} kept ({} reversed), {} removed, {} added",
        soup.n_faces(),
        mesh.n_faces(),
        counts.kept_faces,
        counts.reversed_faces,
        counts.removed_faces,
        counts.added_faces
    );
    for (what, reasons) in [
        ("vertices", fates.removed_vertices_by_reason()),
        ("faces", fates.removed_faces_by_reason()),
    ] {
        for (reason, count) in reasons {
            println!("  removed {what} ({reason}): {count}");
        }
    }
    println!(
        "flipped edges: {}, split edges: {}, stitched edges: {}",
        fates.flipped_edges, fates.split_edges, fates.stitched_edges
    );
    if options.fill_holes.is_some() {
        println!(
            "holes: {} filled, {} refused (left open)",
            fates.filled_holes, fates.refused_holes
        );
    }
    Ok(0)
}

/// The fill mode the flags ask for: `--fair` refines too.
fn fill_mode(args: &Args) -> FillMode {
    if args.flag("--fair") {
        FillMode::Fair
    } else if args.flag("--refine") {
        FillMode::Refine
    } else {
        FillMode::Triangulate
    }
}

/// The tolerance given by the absolute or the relative option (exact when neither).
fn tolerance(args: &Args, absolute: &str, relative: &str) -> Result<Tolerance, Failure> {
    match (args.parsed::<f64>(absolute)?, args.parsed::<f64>(relative)?) {
        (Some(_), Some(_)) => Err(Failure::usage(format!(
            "{absolute} and {relative} exclude each other"
        ))),
        (Some(t), None) => Ok(Tolerance::Absolute(t)),
        (None, Some(r)) => Ok(Tolerance::Relative(r)),
        (None, None) => Ok(Tolerance::EXACT),
    }
}

/// The tolerance of a step that `keep` turns off (`None`), refusing a tolerance given with it.
fn optional_step(
    args: &Args,
    keep: &str,
    absolute: &str,
    relative: &str,
) -> Result<Option<Tolerance>, Failure> {
    if !args.flag(keep) {
        return tolerance(args, absolute, relative).map(Some);
    }
    if args.value(absolute).is_some() || args.value(relative).is_some() {
        return Err(Failure::usage(format!(
            "{keep} excludes {absolute} and {relative}"
        )));
    }
    Ok(None)
}
