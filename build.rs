//! Build script: gives the shared library its ELF soname and tells the C smoke test which target
//! it is compiling for.

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    let target = std::env::var("TARGET").unwrap_or_default();
    println!("cargo:rustc-env=HALFWING_BUILD_TARGET={target}");

    // A stable soname lets programs linked against libhalfwing.so keep loading it across
    // compatible releases: one ABI per major version, or per minor version while at 0.x.
    if target.contains("linux") {
        let major = std::env::var("CARGO_PKG_VERSION_MAJOR").unwrap_or_default();
        let minor = std::env::var("CARGO_PKG_VERSION_MINOR").unwrap_or_default();
        let abi = if major == "0" {
            format!("0.{minor}")
        } else {
            major
        };
        println!("cargo:rustc-cdylib-link-arg=-Wl,-soname,libhalfwing.so.{abi}");
    }
}
