//! The `wavepool` binary. Natively: with no command (or only viewer flags) the desktop viewer
//! (`src/viewer.rs`), with `render` or `bench` the headless command line (`src/cli.rs`). In the
//! browser the entry point is the library's `web` module, so the wasm build of this binary is
//! empty.

#[cfg(not(target_arch = "wasm32"))]
mod catalogue;
#[cfg(not(target_arch = "wasm32"))]
mod cli;
#[cfg(not(target_arch = "wasm32"))]
mod viewer;

#[cfg(not(target_arch = "wasm32"))]
fn main() -> std::process::ExitCode {
    cli::main()
}

#[cfg(target_arch = "wasm32")]
fn main() {}
