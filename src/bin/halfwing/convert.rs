//! `halfwing convert IN OUT [--binary|--ascii]`: a mesh file in another format.

use crate::args::Args;
use crate::failure::{Failure, Outcome};
use crate::files::{output_format, read_mesh, write_mesh};
use halfwing::io::MeshFormat;

const HELP: &str = "\
usage: halfwing convert IN OUT [--binary|--ascii]

Reads IN and writes it to OUT, each in the format its extension names (.obj, .off, .ply).
Positions, faces, and the per-corner normals and texture coordinates OBJ carries are kept as
far as OUT's format holds them. PLY is written in binary (little endian) unless --ascii is
given; OBJ and OFF are text, and --binary is refused for them.
Exit codes: 0 success, 2 usage error, 3 IN cannot be read, 4 OUT cannot be written.
";

pub fn run(args: &[String]) -> Outcome {
    let Some(args) = Args::parse(args, &["--binary", "--ascii"], &[])? else {
        print!("{HELP}");
        return Ok(0);
    };
    let [input, output] = args.positional(&["IN", "OUT"])? else {
        unreachable!("two positional arguments")
    };
    let binary = ply_binary(&args, output)?;
    let soup = read_mesh(input)?;
    write_mesh(output, &soup, binary)?;
    Ok(0)
}

/// Whether OUT is written in binary: PLY unless `--ascii`; `--binary` refused for text formats.
pub fn ply_binary(args: &Args, output: &str) -> Result<bool, Failure> {
    let format = output_format(output)?;
    match (args.flag("--binary"), args.flag("--ascii")) {
        (true, true) => Err(Failure::usage(
            "--binary and --ascii exclude each other".into(),
        )),
        (true, false) if format != MeshFormat::Ply => Err(Failure::usage(format!(
            "{output}: {} is written as text only (--binary is for .ply)",
            format.name()
        ))),
        (_, ascii) => Ok(!ascii),
    }
}
