//! The C smoke test: takes the static library cargo built with the tests, compiles the C
//! consumer program of `c_tests/consumer/main.c` against `include/halfwing.h` with the `cc`
//! crate's compiler, links, runs it. A Rust-only change that breaks the C ABI (or the committed
//! header) fails here, before CMake is ever involved.

use std::path::{Path, PathBuf};
use std::process::Command;

const MANIFEST_DIR: &str = env!("CARGO_MANIFEST_DIR");

/// The static library `cargo test` built beside this test binary: the `staticlib` crate type
/// comes out of the same compilation as the `rlib` the other tests link, so a second cargo
/// build (and a second target directory of a gigabyte) is not needed.
fn static_library() -> PathBuf {
    let test_binary = std::env::current_exe().expect("the test binary has a path");
    let library = test_binary
        .parent()
        .expect("the test binary lies in a directory")
        .join("libhalfwing.a");
    assert!(
        library.is_file(),
        "{} is missing: cargo builds it with the tests",
        library.display()
    );
    library
}

#[test]
fn c_program_builds_links_and_runs_against_the_header() {
    let work = Path::new(env!("CARGO_TARGET_TMPDIR")).join("c-smoke");
    std::fs::create_dir_all(&work).expect("the work directory can be made");
    let library = static_library();
    let target = env!("HALFWING_BUILD_TARGET");
    let compiler = cc::Build::new()
        .target(target)
        .host(target)
        .opt_level(0)
        .cargo_metadata(false)
        .get_compiler();
    let program = work.join("consumer");
    let source = Path::new(MANIFEST_DIR).join("c_tests/consumer/main.c");
    let include = Path::new(MANIFEST_DIR).join("include");
    let output = compiler
        .to_command()
        .args([
            "-std=c11",
            "-Wall",
            "-Wextra",
            "-Wpedantic",
            "-Werror",
            "-I",
        ])
        .arg(include)
        .arg(source)
        .arg("-o")
        .arg(&program)
        .arg(library)
        .args(["-lpthread", "-ldl", "-lm", "-lrt", "-lutil", "-lgcc_s"])
        .output()
        .expect("the C compiler runs");
    assert!(
        output.status.success(),
        "compiling the C consumer failed:\n{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let run = Command::new(&program)
        .output()
        .expect("the C consumer runs");
    let stdout = String::from_utf8_lossy(&run.stdout);
    assert!(
        run.status.success(),
        "C consumer failed: {stdout}{}",
        String::from_utf8_lossy(&run.stderr)
    );
    assert!(
        stdout.contains("V=4 E=6 F=4"),
        "unexpected output: {stdout}"
    );
}
