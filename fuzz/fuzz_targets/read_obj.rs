//! Fuzzes the OBJ reader: any bytes must give a soup or an error, never a panic, and a soup that is
//! read must be consistent and survive a write and a second read unchanged in shape.
#![no_main]

use halfwing::io::MeshFormat;
use libfuzzer_sys::fuzz_target;

#[path = "common.rs"]
mod common;

fuzz_target!(|bytes: &[u8]| common::check(MeshFormat::Obj, bytes));
