//! `halfwing info MODEL`: counts, bounding box and the doctor's summary line.

use crate::args::Args;
use crate::doctor::examine;
use crate::failure::Outcome;
use crate::files::read_mesh;

const HELP: &str = "\
usage: halfwing info MODEL

Prints the numbers of vertices, faces and corners of MODEL (OBJ, OFF or PLY), the bounding box
of its finite vertex positions, and the first line of `halfwing doctor`.
Exit codes: 0 success, 2 usage error, 3 MODEL cannot be read.
";

pub fn run(args: &[String]) -> Outcome {
    let Some(args) = Args::parse(args, &[], &[])? else {
        print!("{HELP}");
        return Ok(0);
    };
    let [path] = args.positional(&["MODEL"])? else {
        unreachable!("one positional argument")
    };
    let soup = read_mesh(path)?;
    let report = examine(path, &soup)?;
    println!("{path}");
    println!("vertices: {}", soup.positions.len());
    println!("faces:    {}", soup.n_faces());
    println!("corners:  {}", soup.indices.len());
    let finite = soup
        .positions
        .iter()
        .filter(|p| p.iter().all(|c| c.is_finite()));
    let mut bounds: Option<[[f64; 3]; 2]> = None;
    for p in finite {
        let b = bounds.get_or_insert([*p, *p]);
        for axis in 0..3 {
            b[0][axis] = b[0][axis].min(p[axis]);
            b[1][axis] = b[1][axis].max(p[axis]);
        }
    }
    match bounds {
        Some([low, high]) => println!(
            "bounding box: [{}, {}, {}] to [{}, {}, {}]",
            low[0], low[1], low[2], high[0], high[1], high[2]
        ),
        None => println!("bounding box: none (no finite vertex)"),
    }
    let summary = report.to_string();
    println!("doctor: {}", summary.lines().next().unwrap_or(""));
    Ok(0)
}
