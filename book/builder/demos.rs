//! The live demos' module: the `web` crate compiled for WebAssembly and written where the
//! pages load it.
//!
//! A page opened from disk may run a script but not fetch a `.wasm` file, so the module is
//! written as a script, `book/src/demos/web.js`, that sets `window.BOOK_DEMOS_WASM` to the
//! module in base64; `book/theme/demos.js` makes the demos from it. In a student edition the
//! module is compiled from the student's code, so the demos run what the student wrote.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

use anyhow::{Context, Result, bail};
use base64::Engine;
use base64::prelude::BASE64_STANDARD;

use crate::workspace;

/// The target the demos are compiled for; `rust-toolchain.toml` installs it.
const TARGET: &str = "wasm32-unknown-unknown";

/// The cargo profile of the demos (see the workspace's `Cargo.toml`).
const PROFILE: &str = "web";

/// Where the pages find the module, relative to the book's `src/`.
pub const SCRIPT: &str = "demos/web.js";

/// Compiles the demos and writes their script into `book_src`; returns its path.
pub fn build(root: &Path, book_src: &Path) -> Result<PathBuf> {
    let started = Instant::now();
    println!("Compiling the live demos for {TARGET} ...");
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let target_dir = workspace::target_dir(root);
    let status = Command::new(&cargo)
        .args(["build", "--quiet", "-p", "web", "--lib", "--target", TARGET])
        .args(["--profile", PROFILE])
        .arg("--target-dir")
        .arg(&target_dir)
        .current_dir(root)
        .status()
        .with_context(|| format!("cannot run {}", Path::new(&cargo).display()))?;
    if !status.success() {
        bail!(
            "the demos did not compile for {TARGET} (see above); if the target is missing, \
             `rustup target add {TARGET}` adds it (rust-toolchain.toml names it)"
        );
    }
    let module = target_dir.join(TARGET).join(PROFILE).join("web.wasm");
    let bytes = std::fs::read(&module)
        .with_context(|| format!("cannot read the compiled demos, {}", module.display()))?;
    let script = book_src.join(SCRIPT);
    crate::workspace::write_whole(&script, script_of(&bytes))?;
    println!(
        "Demos ready in {:.1} s: {} KiB of WebAssembly in {}",
        started.elapsed().as_secs_f64(),
        bytes.len() / 1024,
        script.display()
    );
    Ok(script)
}

/// The script that hands `module` to the page.
fn script_of(module: &[u8]) -> String {
    format!(
        "// Written by the book's builder from the `web` crate: the live demos' WebAssembly \
         module, in base64.\nwindow.BOOK_DEMOS_WASM = \"{}\";\n",
        BASE64_STANDARD.encode(module)
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_script_carries_the_module_in_base64() {
        let script = script_of(b"\0asm\x01\0\0\0");
        assert!(script.contains("window.BOOK_DEMOS_WASM = \"AGFzbQEAAAA=\";"));
        assert!(script.starts_with("//"));
    }
}
