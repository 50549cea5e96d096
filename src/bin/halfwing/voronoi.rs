//! `halfwing voronoi POINTS --svg OUT [--clip x0,y0,x1,y1] [--lloyd N]`: a Voronoi diagram as SVG.

use crate::args::Args;
use crate::failure::{Failure, Outcome};
use crate::progress::Progress;
use halfwing::voronoi::{ClipPolygon, LloydOptions, SvgOptions, Voronoi, lloyd_relaxation, to_svg};

const HELP: &str = "\
usage: halfwing voronoi POINTS --svg OUT [--clip x0,y0,x1,y1] [--lloyd N]

Draws the Voronoi diagram of the 2D points in POINTS (.xy, .cin: a point per line; .node, .poly:
Triangle's format; .txt: a count, then a point per line; .json: an array of coordinates),
clipped to the rectangle --clip (default: the points' bounding box grown by a tenth), as an SVG
file OUT. --lloyd N first moves the points N times to the centroids of their clipped cells.
Exit codes: 0 success, 2 usage error, 3 POINTS cannot be read, 4 OUT cannot be written,
5 the points or the rectangle are refused (no point, non-finite coordinates, empty rectangle).
";

pub fn run(args: &[String]) -> Outcome {
    let Some(args) = Args::parse(args, &[], &["--svg", "--clip", "--lloyd"])? else {
        print!("{HELP}");
        return Ok(0);
    };
    let [input] = args.positional(&["POINTS"])? else {
        unreachable!("one positional argument")
    };
    let output = args
        .value("--svg")
        .ok_or_else(|| Failure::usage("--svg OUT is required".into()))?;
    let clip = args.value("--clip").map(rectangle).transpose()?;
    let lloyd = args.parsed::<u32>("--lloyd")?.unwrap_or(0);
    let mut points =
        halfwing::io::read_points2d(input).map_err(|e| Failure::input(e.to_string()))?;
    if points.is_empty() {
        return Err(Failure::refused(format!("{input}: no points")));
    }
    let refused = |e: halfwing::voronoi::VoronoiError| Failure::refused(format!("{input}: {e}"));
    let [low, high] = clip.unwrap_or_else(|| grown_box(&points));
    let region = ClipPolygon::rectangle(low, high).map_err(refused)?;
    let _progress = Progress::start(format!("computing the diagram of {input}"));
    if lloyd > 0 {
        let options = LloydOptions {
            max_iterations: lloyd,
            tolerance: 0.0,
        };
        points = lloyd_relaxation(&points, &region, options)
            .map_err(refused)?
            .sites;
    }
    let voronoi = Voronoi::new(&points).map_err(refused)?;
    let svg = to_svg(&voronoi, &voronoi.clip(&region), &SvgOptions::default());
    std::fs::write(output, svg)
        .map_err(|e| Failure::output(format!("{output}: cannot write: {e}")))?;
    Ok(0)
}

/// `x0,y0,x1,y1` as two corners.
fn rectangle(text: &str) -> Result<[[f64; 2]; 2], Failure> {
    let values: Vec<f64> = text
        .split(',')
        .map(|t| t.trim().parse::<f64>())
        .collect::<Result<_, _>>()
        .map_err(|_| Failure::usage(format!("--clip {text:?}: expected x0,y0,x1,y1")))?;
    match values[..] {
        [x0, y0, x1, y1] => Ok([[x0.min(x1), y0.min(y1)], [x0.max(x1), y0.max(y1)]]),
        _ => Err(Failure::usage(format!(
            "--clip {text:?}: expected x0,y0,x1,y1"
        ))),
    }
}

/// The points' bounding box grown by a tenth of its size (by 1 when all points coincide).
fn grown_box(points: &[[f64; 2]]) -> [[f64; 2]; 2] {
    let mut low = [f64::INFINITY; 2];
    let mut high = [f64::NEG_INFINITY; 2];
    for p in points
        .iter()
        .filter(|p| p[0].is_finite() && p[1].is_finite())
    {
        for axis in 0..2 {
            low[axis] = low[axis].min(p[axis]);
            high[axis] = high[axis].max(p[axis]);
        }
    }
    let extent = (high[0] - low[0]).max(high[1] - low[1]);
    let margin = if extent > 0.0 { extent * 0.1 } else { 1.0 };
    [
        [low[0] - margin, low[1] - margin],
        [high[0] + margin, high[1] + margin],
    ]
}
