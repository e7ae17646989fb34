//! The chapter binaries, run as a user runs them.
//!
//! Cargo hands a package's integration tests only that package's own binaries
//! (`CARGO_BIN_EXE_<name>`). This crate tests every chapter's, so it finds them where cargo
//! puts them, `target/<profile>/`, next to the `deps/` directory holding the test itself, and
//! asks cargo once per test process to bring them up to date when a source is newer than
//! they are (after `cargo test --workspace`, which has built them, none is).

use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::sync::LazyLock;

/// Every chapter binary that exists now, by package (and binary) name.
pub const CHAPTERS: &[&str] = &[
    "ch01-whitted",
    "ch02-monte-carlo",
    "ch03-anti-aliasing",
    "ch04-depth-of-field",
    "ch05-motion-blur",
    "ch06-fuzzy-reflections",
    "ch07-soft-shadows",
    "ch08-path-tracing",
    "ch09-materials",
    "ch10-optimal-mis",
    "ch11-path-guiding",
];

/// The chapters whose `render` renders (chapter 02 is about estimators; its `render` refuses).
/// Chapters 08 to 11 render only scene files: run them with [`scene_args`].
pub const RENDERING_CHAPTERS: &[&str] = &[
    "ch01-whitted",
    "ch03-anti-aliasing",
    "ch04-depth-of-field",
    "ch05-motion-blur",
    "ch06-fuzzy-reflections",
    "ch07-soft-shadows",
    "ch08-path-tracing",
    "ch09-materials",
    "ch10-optimal-mis",
    "ch11-path-guiding",
];

/// The suite's smallest scene file (8x6 pixels, one sample per pixel, a ball on a floor under
/// a panel light and a dim sky), for chapters that need a scene file to render anything.
pub const TINY_SCENE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/tiny.xml");

/// What `render` of `chapter` needs to render anything, to put after `render`: nothing for
/// the chapters with built-in scenes, `--scene` [`TINY_SCENE`] for chapter 08 and
/// `ch09-materials`, which have none.
/// Tests give the size and sample count they want on the command line; those override the
/// file's.
pub fn scene_args(chapter: &str) -> &'static [&'static str] {
    match chapter {
        "ch08-path-tracing" | "ch09-materials" | "ch10-optimal-mis" | "ch11-path-guiding" => {
            &["--scene", TINY_SCENE]
        }
        _ => &[],
    }
}

/// `target/<profile>`, where cargo writes binaries: the parent of the test's `deps/`.
fn profile_dir() -> PathBuf {
    let exe = std::env::current_exe().expect("the test knows its own path");
    let deps = exe.parent().expect("the test lives in a directory");
    let dir = if deps.file_name().is_some_and(|n| n == "deps") {
        deps.parent().expect("deps/ has a parent")
    } else {
        deps
    };
    dir.to_path_buf()
}

/// Builds every chapter binary once per process, with the profile of this test, unless every
/// one of them is newer than every file it is built from.
///
/// After `cargo test --workspace`, which has just built them, nothing is asked of cargo. Asking
/// would not be free: cargo settles a dependency's features over the packages it is asked to
/// build, so a build of the chapters' binaries alone gives `common` and every chapter other
/// features than the whole workspace's test build did, compiles them all again (two to three
/// minutes on a 2-core machine), and replaces the binaries that build made. Run alone
/// (`cargo test -p workbook-tests`) after a change to a chapter, the binaries are older than
/// the change and cargo brings them up to date.
static BUILT: LazyLock<PathBuf> = LazyLock::new(|| {
    let dir = profile_dir();
    if binaries_are_newer_than_their_sources(&dir) {
        return dir;
    }
    let profile = match dir.file_name().and_then(|n| n.to_str()) {
        Some("debug") | None => "dev".to_string(),
        Some(other) => other.to_string(),
    };
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let mut command = Command::new(cargo);
    command.args(["build", "--quiet", "--bins", "--profile", &profile]);
    for chapter in CHAPTERS {
        command.args(["-p", chapter]);
    }
    let status = command
        .current_dir(Path::new(env!("CARGO_MANIFEST_DIR")))
        .status()
        .expect("cargo runs");
    assert!(status.success(), "building the chapter binaries failed");
    dir
});

/// Whether every chapter binary in `dir` exists and was written after the last change to any
/// file it is built from: the Rust sources and manifests of `common` and the chapters, and the
/// workspace's manifest and lock file.
fn binaries_are_newer_than_their_sources(dir: &Path) -> bool {
    let modified = |path: &Path| std::fs::metadata(path).and_then(|m| m.modified()).ok();
    let oldest_binary = CHAPTERS
        .iter()
        .map(|chapter| modified(&dir.join(format!("{chapter}{}", std::env::consts::EXE_SUFFIX))))
        .collect::<Option<Vec<_>>>()
        .and_then(|times| times.into_iter().min());
    let Some(oldest_binary) = oldest_binary else {
        return false; // one is missing
    };
    let root = Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("the tests live in the workspace");
    let mut sources = vec![root.join("Cargo.toml"), root.join("Cargo.lock")];
    let packages = std::iter::once(root.join("common"))
        .chain(CHAPTERS.iter().map(|c| root.join("chapters").join(c)));
    let mut folders = Vec::new();
    for package in packages {
        sources.push(package.join("Cargo.toml"));
        folders.push(package.join("src"));
    }
    // Every file under each package's `src/` (scenes and snapshots are read when a binary
    // runs, not built into it).
    while let Some(folder) = folders.pop() {
        let Ok(entries) = std::fs::read_dir(&folder) else {
            return false;
        };
        for entry in entries.flatten() {
            let path = entry.path();
            if path.is_dir() {
                folders.push(path);
            } else {
                sources.push(path);
            }
        }
    }
    sources
        .iter()
        .all(|source| modified(source).is_some_and(|time| time < oldest_binary))
}

/// The path of a chapter's binary, built and up to date.
pub fn chapter_binary(chapter: &str) -> PathBuf {
    BUILT.join(format!("{chapter}{}", std::env::consts::EXE_SUFFIX))
}

/// Runs a chapter binary to the end and collects its output.
pub fn run_chapter(chapter: &str, args: &[&str]) -> Output {
    Command::new(chapter_binary(chapter))
        .args(args)
        .output()
        .expect("the chapter binary runs")
}

/// The names of the files in `dir`, sorted.
pub fn files_in(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .map(|entries| {
            entries
                .map(|e| {
                    e.expect("a directory entry")
                        .file_name()
                        .to_string_lossy()
                        .into_owned()
                })
                .collect()
        })
        .unwrap_or_default();
    names.sort();
    names
}
