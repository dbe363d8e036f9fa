//! The `wavepool` binary: natively, the command line (`src/cli.rs`). In the browser the
//! entry point is the library's `web` module, so the wasm build of this binary is empty.

#[cfg(not(target_arch = "wasm32"))]
mod cli;

#[cfg(not(target_arch = "wasm32"))]
fn main() -> std::process::ExitCode {
    cli::main()
}

#[cfg(target_arch = "wasm32")]
fn main() {}
