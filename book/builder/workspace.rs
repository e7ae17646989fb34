//! Where the workspace is, and which of its files are source.

use std::path::{Path, PathBuf};
use std::process::Command;

use anyhow::{Context, Result, bail};

/// The workspace root: the directory above this package.
///
/// The builder is always run from a checkout (`cargo run -p book`), so the path cargo compiled
/// it from is the right one, whatever the current directory.
pub fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("the book package sits inside the workspace")
        .to_path_buf()
}

/// The directory cargo builds into: `$CARGO_TARGET_DIR` if set, else `target/` in the workspace.
pub fn target_dir(root: &Path) -> PathBuf {
    match std::env::var_os("CARGO_TARGET_DIR") {
        Some(dir) => root.join(dir),
        None => root.join("target"),
    }
}

/// Generated or private paths that are never source, for trees outside git.
const NOT_SOURCE: &[&str] = &[
    "target",
    ".git",
    "out",
    "book/site",
    "book/src/figures",
    "book/src/demos",
];

/// The workspace's source files, relative to `root`, sorted.
///
/// In a git checkout these are the files git tracks plus new files it would track (not yet added
/// but not ignored either), so a chapter file written a minute ago is included. Outside git, the
/// tree is walked, leaving out the generated directories in [`NOT_SOURCE`].
pub fn source_files(root: &Path) -> Result<Vec<PathBuf>> {
    let mut files = if root.join(".git").exists() {
        git_files(root)?
    } else {
        files_under_but(root, |relative| {
            NOT_SOURCE.iter().any(|skip| relative == Path::new(skip))
        })?
        .into_iter()
        .map(|path| path.strip_prefix(root).unwrap_or(&path).to_path_buf())
        .collect()
    };
    files.sort();
    files.dedup();
    Ok(files)
}

fn git_files(root: &Path) -> Result<Vec<PathBuf>> {
    let output = Command::new("git")
        .args([
            "ls-files",
            "-z",
            "--cached",
            "--others",
            "--exclude-standard",
        ])
        .current_dir(root)
        .output()
        .context("cannot run `git ls-files` (is git installed?)")?;
    if !output.status.success() {
        bail!(
            "`git ls-files` failed: {}",
            String::from_utf8_lossy(&output.stderr)
        );
    }
    let listing = String::from_utf8(output.stdout).context("git listed a non-UTF-8 path")?;
    Ok(listing
        .split('\0')
        .filter(|path| !path.is_empty())
        .map(PathBuf::from)
        // A file deleted but not yet committed is still listed as tracked.
        .filter(|path| root.join(path).is_file())
        .collect())
}

/// Every file under `dir` (its path, `dir` joined to the part below it), in no particular order.
pub fn files_under(dir: &Path) -> Result<Vec<PathBuf>> {
    files_under_but(dir, |_| false)
}

/// The `.rs` files under `dir` (none if it does not exist), leaving out build outputs and hidden
/// folders, which hold no one's source.
pub fn rust_files_under(dir: &Path) -> Result<Vec<PathBuf>> {
    if !dir.exists() {
        return Ok(Vec::new());
    }
    let generated = |relative: &Path| {
        relative
            .file_name()
            .is_some_and(|name| name == "target" || name.to_string_lossy().starts_with('.'))
    };
    let mut files = files_under_but(dir, generated)?;
    files.retain(|path| path.extension().is_some_and(|ext| ext == "rs"));
    Ok(files)
}

/// Every file under `dir`, leaving out the files and folders whose path below `dir` is
/// `left_out`, and all they hold.
pub fn files_under_but(dir: &Path, left_out: impl Fn(&Path) -> bool) -> Result<Vec<PathBuf>> {
    let mut files = Vec::new();
    let walk = walkdir::WalkDir::new(dir)
        .follow_links(true)
        .into_iter()
        .filter_entry(|entry| !left_out(entry.path().strip_prefix(dir).unwrap_or(entry.path())));
    for entry in walk {
        let entry =
            entry.with_context(|| format!("cannot list everything under {}", dir.display()))?;
        if !entry.file_type().is_dir() {
            files.push(entry.into_path());
        }
    }
    Ok(files)
}

/// Writes `contents` to `path` whole or not at all (the demos' script, a checkpointed
/// exercise, the sealed solutions, a table), creating its folder first: the workbench's
/// `write_atomic`, which every image and figure goes through too.
pub fn write_whole(path: &Path, contents: impl AsRef<[u8]>) -> Result<()> {
    if let Some(dir) = path.parent().filter(|dir| !dir.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).with_context(|| format!("cannot create {}", dir.display()))?;
    }
    workbench::output::write_atomic(path, |out| out.write_all(contents.as_ref()))?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn walking_skips_generated_directories() {
        let dir = tempfile::tempdir().unwrap();
        for file in [
            "Cargo.toml",
            "src/lib.rs",
            "target/debug/x",
            "book/site/index.html",
        ] {
            let path = dir.path().join(file);
            std::fs::create_dir_all(path.parent().unwrap()).unwrap();
            std::fs::write(path, "").unwrap();
        }
        let files = source_files(dir.path()).unwrap();
        assert_eq!(
            files,
            [PathBuf::from("Cargo.toml"), PathBuf::from("src/lib.rs")]
        );
    }
}
