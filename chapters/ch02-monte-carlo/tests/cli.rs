//! The binary: samples as CSV, and bad input refused with a message, never a panic.

use std::process::Output;
use workbench::test_support::run_binary;

const BINARY: &str = env!("CARGO_BIN_EXE_ch02-monte-carlo");

fn run(args: &[&str]) -> Output {
    run_binary(BINARY, args)
}

fn assert_refused(args: &[&str], expected: &str) {
    workbench::test_support::assert_refused(BINARY, args, expected);
}

#[test]
fn samples_are_written_as_csv_with_their_density() {
    let dir = tempfile::tempdir().unwrap();
    for (warp, header, columns, extra) in [
        ("disc-polar", "x,y,pdf", 3, None),
        ("triangle", "x,y,pdf", 3, None),
        ("cosine-hemisphere", "x,y,z,pdf", 4, None),
        ("cos-lobe", "x,y,z,pdf", 4, Some("1000000")),
    ] {
        let path = dir.path().join(format!("{warp}.csv"));
        let mut args = vec![
            "samples",
            "--warp",
            warp,
            "--n",
            "500",
            "--seed",
            "3",
            "--out",
            path.to_str().unwrap(),
        ];
        if let Some(exponent) = extra {
            args.extend(["--exponent", exponent]);
        }
        let out = run(&args);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let text = std::fs::read_to_string(&path).unwrap();
        let mut lines = text.lines();
        assert_eq!(lines.next(), Some(header));
        let rows: Vec<Vec<f64>> = lines
            .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
            .collect();
        assert_eq!(rows.len(), 500);
        for row in &rows {
            assert_eq!(row.len(), columns);
            assert!(row.iter().all(|v| v.is_finite()), "{warp}: {row:?}");
            assert!(row[columns - 1] > 0.0, "{warp}: a sample with zero density");
        }
    }
}

#[test]
fn the_same_seed_gives_the_same_samples() {
    let dir = tempfile::tempdir().unwrap();
    let write = |name: &str, seed: &str| {
        let path = dir.path().join(name);
        let out = run(&[
            "samples",
            "--warp",
            "sphere",
            "--n",
            "50",
            "--seed",
            seed,
            "--out",
            path.to_str().unwrap(),
        ]);
        assert!(out.status.success());
        std::fs::read_to_string(path).unwrap()
    };
    assert_eq!(write("a.csv", "9"), write("b.csv", "9"));
    assert_ne!(write("a.csv", "9"), write("c.csv", "10"));
}

#[test]
fn bad_input_is_refused_with_a_clear_message() {
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("out.csv");
    let csv = csv.to_str().unwrap();
    let cases: &[(&[&str], &str)] = &[
        (
            &["samples", "--warp", "teapot", "--n", "5", "--out", csv],
            "teapot",
        ),
        (
            &["samples", "--warp", "disc-polar", "--n", "0", "--out", csv],
            "--n",
        ),
        (
            &["samples", "--warp", "disc-polar", "--n", "-2", "--out", csv],
            "-2",
        ),
        (
            &[
                "samples",
                "--warp",
                "cos-lobe",
                "--n",
                "5",
                "--exponent",
                "-1",
                "--out",
                csv,
            ],
            "exponent",
        ),
        (
            &[
                "samples",
                "--warp",
                "cos-lobe",
                "--n",
                "5",
                "--exponent",
                "nan",
                "--out",
                csv,
            ],
            "exponent",
        ),
        (
            &[
                "samples",
                "--warp",
                "disc-polar",
                "--n",
                "5",
                "--exponent",
                "3",
                "--out",
                csv,
            ],
            "exponent",
        ),
        (&["samples", "--warp", "disc-polar", "--n", "5"], "--out"),
        (&["render", "--out", csv], "renders no scene"),
    ];
    for (args, expected) in cases {
        assert_refused(args, expected);
    }
    assert!(!std::path::Path::new(csv).exists());
    let blocker = dir.path().join("file");
    std::fs::write(&blocker, b"x").unwrap();
    let inside = blocker.join("out.csv");
    assert_refused(
        &[
            "samples",
            "--warp",
            "sphere",
            "--n",
            "5",
            "--out",
            inside.to_str().unwrap(),
        ],
        "cannot create the directory",
    );
}
