//! No lost work: a render stopped with Ctrl-C writes the image of the passes it completed and
//! says so; a timed render renders passes until its time is up. Every rendering chapter is
//! checked, chapter 08 on the suite's tiny scene file (it has no built-in scenes).

use std::path::Path;
use std::time::{Duration, Instant};
use workbook_tests::binaries::{
    RENDERING_CHAPTERS, chapter_binary, files_in, run_chapter, scene_args,
};

/// Arguments of a small render of `spp` samples per pixel written to `out` (PFM: exact floats).
///
/// Chapters 03 and 04 use independent pixel samples: a stratified sampler lays out its strata
/// for the whole sample count, so the first passes of a render asked for more cover only part
/// of each pixel, and its interrupted image is not that of a shorter render.
fn small_render<'a>(chapter: &str, out: &'a str, stats: &'a str, spp: &'a str) -> Vec<&'a str> {
    let mut args = vec!["render"];
    args.extend(scene_args(chapter));
    args.extend([
        "--width",
        "16",
        "--height",
        "12",
        "--threads",
        "2",
        "--seed",
        "5",
        "--spp",
        spp,
        "--out",
        out,
        "--stats",
        stats,
    ]);
    args.extend(sampler_args(chapter));
    args
}

/// Chapter 01 renders pixel centres; the later chapters are told to take random positions
/// (and chapter 05 independent times: its stratified times, too, are laid out for the whole
/// sample count).
fn sampler_args(chapter: &str) -> &'static [&'static str] {
    match chapter {
        "ch01-whitted" => &[],
        "ch05-motion-blur" => &["--sampler", "random", "--time-sampling", "independent"],
        _ => &["--sampler", "random"],
    }
}

/// Waits for `child` to end, killing it (and failing) if it takes longer than `limit`.
fn wait_at_most(child: &mut std::process::Child, limit: Duration) -> std::process::ExitStatus {
    let start = Instant::now();
    loop {
        if let Some(status) = child.try_wait().expect("the child can be waited for") {
            return status;
        }
        if start.elapsed() > limit {
            child.kill().ok();
            panic!("the render did not stop within {limit:?} of Ctrl-C");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// The samples per pixel in `interrupted: wrote X with N of M samples per pixel`.
fn spp_in_message(stderr: &str, out: &str) -> u64 {
    let prefix = format!("interrupted: wrote {out} with ");
    let start = stderr
        .find(&prefix)
        .unwrap_or_else(|| panic!("no `{prefix}` in: {stderr}"))
        + prefix.len();
    let rest = &stderr[start..];
    let end = rest.find(' ').expect("a number then a space");
    assert!(
        rest[end..].starts_with(" of 1000000000 samples per pixel"),
        "{stderr}"
    );
    rest[..end].parse().expect("a sample count")
}

#[cfg(unix)]
#[test]
fn ctrl_c_writes_the_completed_passes_and_exits_non_zero() {
    std::thread::scope(|scope| {
        for chapter in RENDERING_CHAPTERS {
            scope.spawn(|| interrupt_and_check(chapter));
        }
    });
}

/// Starts a long render of `chapter`, interrupts it, and checks what it wrote and said.
#[cfg(unix)]
fn interrupt_and_check(chapter: &str) {
    {
        let dir = tempfile::tempdir().unwrap();
        let out = dir.path().join("out.pfm");
        let stats = dir.path().join("stats.json");
        let (out, stats) = (out.to_str().unwrap(), stats.to_str().unwrap());
        let mut child = std::process::Command::new(chapter_binary(chapter))
            .args(small_render(chapter, out, stats, "1000000000"))
            .stderr(std::process::Stdio::piped())
            .spawn()
            .expect("the binary starts");
        // Long enough for the handler to be installed and a few passes to complete.
        std::thread::sleep(Duration::from_millis(1000));
        let sent = std::process::Command::new("kill")
            .args(["-INT", &child.id().to_string()])
            .status()
            .expect("`kill` runs");
        assert!(sent.success());
        let status = wait_at_most(&mut child, Duration::from_secs(30));
        let mut stderr = String::new();
        std::io::Read::read_to_string(&mut child.stderr.take().unwrap(), &mut stderr).unwrap();
        assert!(
            !status.success(),
            "{chapter}: an interrupted render exited 0"
        );
        assert_eq!(
            status.code(),
            Some(1),
            "{chapter}: killed rather than stopped: {stderr}"
        );
        assert!(!stderr.contains("panicked"), "{chapter}: {stderr}");
        let spp = spp_in_message(&stderr, out);
        assert!(spp >= 1, "{chapter}: {stderr}");

        let json: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(stats).unwrap()).unwrap();
        assert_eq!(json["interrupted"], true, "{chapter}: {json}");
        assert_eq!(json["spp"], spp, "{chapter}: {json}");
        assert_eq!(json["samples"], 16 * 12 * spp, "{chapter}: {json}");
        assert_eq!(json["nonfinite_samples"], 0, "{chapter}: {json}");
        assert_eq!(
            files_in(dir.path()),
            ["out.pfm", "stats.json"],
            "{chapter}: temp files left"
        );

        // Complete: the image is exactly the render asked for that many samples.
        let partial = workbench::output::read_image(Path::new(out)).unwrap();
        assert_eq!((partial.width, partial.height), (16, 12));
        assert!(partial.pixels.iter().all(|p| p.is_finite()));
        // A render that learns before it renders (its stats say what it trained) splits its
        // whole budget between learning and the image, so its interrupted image, made from
        // what it had learnt so far, is no shorter render's image.
        if json.get("training").is_some() {
            return;
        }
        let again = dir.path().join("again.pfm");
        let again_stats = dir.path().join("again.json");
        let done = run_chapter(
            chapter,
            &small_render(
                chapter,
                again.to_str().unwrap(),
                again_stats.to_str().unwrap(),
                &spp.to_string(),
            ),
        );
        assert!(
            done.status.success(),
            "{}",
            String::from_utf8_lossy(&done.stderr)
        );
        let full = workbench::output::read_image(&again).unwrap();
        assert!(
            partial == full,
            "{chapter}: the interrupted image is not that of {spp} complete samples per pixel"
        );
    }
}

#[test]
fn a_time_budget_renders_passes_until_the_time_is_up() {
    for chapter in RENDERING_CHAPTERS {
        let dir = tempfile::tempdir().unwrap();
        let out = dir.path().join("out.png");
        let stats = dir.path().join("stats.json");
        let binary = chapter_binary(chapter); // built before the clock starts
        let mut args = vec!["render"];
        args.extend(scene_args(chapter));
        args.extend([
            "--width",
            "16",
            "--height",
            "12",
            "--time",
            "0.3",
            "--out",
            out.to_str().unwrap(),
            "--stats",
            stats.to_str().unwrap(),
        ]);
        args.extend(sampler_args(chapter));
        let start = Instant::now();
        let done = std::process::Command::new(binary)
            .args(&args)
            .output()
            .unwrap();
        let elapsed = start.elapsed().as_secs_f64();
        assert!(
            done.status.success(),
            "{}",
            String::from_utf8_lossy(&done.stderr)
        );
        let json: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(&stats).unwrap()).unwrap();
        let seconds = json["seconds"].as_f64().unwrap();
        // At least the budget (a tiny image never finishes early), and not much more: the
        // last pass is sized to fit the time left.
        assert!(
            (0.3..1.5).contains(&seconds),
            "{chapter}: a 0.3 s budget took {seconds} s"
        );
        assert!(elapsed < 10.0, "{chapter}: {elapsed} s");
        assert!(json["spp"].as_u64().unwrap() > 1, "{chapter}: {json}");
        assert_eq!(json["interrupted"], false);
        assert_eq!(json["requested_spp"], serde_json::Value::Null);
    }
}
