//! `halfwing`: examine, repair and convert mesh files, and draw Voronoi diagrams of point files.
//! Every file is read through the library's readers; `halfwing --help` lists the commands and
//! exit codes.

mod args;
mod convert;
mod doctor;
mod failure;
mod files;
mod info;
mod progress;
mod repair;
mod voronoi;

use failure::{Failure, USAGE};
use std::process::ExitCode;

const HELP: &str = "\
halfwing: examine, repair and convert mesh files (OBJ, OFF, PLY)

usage: halfwing COMMAND [ARGS] (halfwing COMMAND --help for one command)

commands:
  info MODEL                      counts, bounding box and the doctor's summary
  doctor MODEL [--json]           everything wrong with a mesh
  repair IN OUT [options]         repair a mesh and print what changed
  convert IN OUT [--binary|--ascii]
                                  rewrite a mesh in the format of OUT's extension
  voronoi POINTS --svg OUT [--clip x0,y0,x1,y1] [--lloyd N]
                                  draw the Voronoi diagram of a 2D point file

exit codes:
  0  success
  1  doctor: defects found (the mesh is not a clean closed manifold)
  2  usage error (unknown command or option, missing argument)
  3  an input file cannot be read or parsed
  4  an output file cannot be written
  5  the operation refused the input (e.g. too few points)
";

fn main() -> ExitCode {
    // Output piped into a reader that stops early (`halfwing doctor x.obj | head`) ends the
    // program quietly, as it does other command-line tools, instead of a panic on the failed
    // write: Rust ignores SIGPIPE by default.
    #[cfg(target_os = "linux")]
    // SAFETY: restores the default action of one signal before any thread is started.
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
    }
    let args: Vec<String> = std::env::args().skip(1).collect();
    let result = match args.first().map(String::as_str) {
        None | Some("--help" | "-h" | "help") => {
            print!("{HELP}");
            Ok(if args.is_empty() { USAGE } else { 0 })
        }
        Some("info") => info::run(&args[1..]),
        Some("doctor") => doctor::run(&args[1..]),
        Some("repair") => repair::run(&args[1..]),
        Some("convert") => convert::run(&args[1..]),
        Some("voronoi") => voronoi::run(&args[1..]),
        Some(other) => Err(Failure::usage(format!(
            "unknown command {other:?} (halfwing --help lists them)"
        ))),
    };
    match result {
        Ok(code) => ExitCode::from(code),
        Err(failure) => {
            eprintln!("halfwing: {}", failure.message);
            ExitCode::from(failure.code)
        }
    }
}
