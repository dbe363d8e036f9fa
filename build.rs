//! The WGSL shaders go into the binary without their comments (the web build's download is
//! budgeted): each `shaders/*.wgsl` is copied into OUT_DIR with every `//` comment cut, line
//! for line, so a shader error's line number is still the source file's. Read with
//! `wgsl!("name.wgsl")` (src/lib.rs).

use std::{env, fs, path::Path};

fn main() {
    let out = env::var("OUT_DIR").expect("cargo sets OUT_DIR");
    println!("cargo:rerun-if-changed=shaders");
    for entry in fs::read_dir("shaders").expect("the shaders folder") {
        let path = entry.expect("a shader file").path();
        if path.extension().is_none_or(|e| e != "wgsl") {
            continue;
        }
        println!("cargo:rerun-if-changed={}", path.display());
        let text = fs::read_to_string(&path).expect("a WGSL file");
        let lines: Vec<&str> = text.lines().map(|l| l.find("//").map_or(l, |at| &l[..at]).trim()).collect();
        let name = path.file_name().expect("a file name");
        fs::write(Path::new(&out).join(name), lines.join("\n") + "\n").expect("OUT_DIR is writable");
    }
}
