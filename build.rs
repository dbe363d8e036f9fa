//! The WGSL shaders go into the binary without their comments (the web build's download is
//! budgeted): each `shaders/**/*.wgsl` is copied into OUT_DIR with every `//` comment cut, line
//! for line, so a shader error's line number is still the source file's. Read with
//! `wgsl!("name.wgsl")`, or `wgsl!("sea/name.wgsl")` for a scene's folder (src/lib.rs).

use std::{env, fs, path::Path};

fn main() {
    let out = env::var("OUT_DIR").expect("cargo sets OUT_DIR");
    println!("cargo:rerun-if-changed=shaders");
    copy_folder(Path::new("shaders"), Path::new(&out));
}

/// Copies the WGSL files of `from` into `to` without their comments, and its subfolders (a
/// scene's shaders, `shaders/sea/`) into subfolders of `to`.
fn copy_folder(from: &Path, to: &Path) {
    fs::create_dir_all(to).expect("OUT_DIR is writable");
    for entry in fs::read_dir(from).expect("a shaders folder") {
        let path = entry.expect("a shader file").path();
        let name = path.file_name().expect("a file name");
        if path.is_dir() {
            println!("cargo:rerun-if-changed={}", path.display());
            copy_folder(&path, &to.join(name));
            continue;
        }
        if path.extension().is_none_or(|e| e != "wgsl") {
            continue;
        }
        println!("cargo:rerun-if-changed={}", path.display());
        let text = fs::read_to_string(&path).expect("a WGSL file");
        let lines: Vec<&str> = text.lines().map(|l| l.find("//").map_or(l, |at| &l[..at]).trim()).collect();
        fs::write(to.join(name), lines.join("\n") + "\n").expect("OUT_DIR is writable");
    }
}
