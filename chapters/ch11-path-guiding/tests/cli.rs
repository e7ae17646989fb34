//! The binary's `render`: each `--guiding` on the door-gap room, end to end, what `--stats`
//! says of the training, and the refusals.

use std::path::Path;
use workbench::output::read_image;
use workbench::test_support::{assert_refused, run_binary};

const BINARY: &str = env!("CARGO_BIN_EXE_ch11-path-guiding");

/// The door-gap room.
fn door_gap() -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenes/door-gap.xml")
        .display()
        .to_string()
}

#[test]
fn render_guides_as_told_and_reports_the_training() {
    let dir = tempfile::tempdir().unwrap();
    for guiding in ["off", "radiance", "variance"] {
        let out = dir.path().join(format!("{guiding}.exr"));
        let stats = dir.path().join(format!("{guiding}.json"));
        let run = run_binary(
            BINARY,
            &[
                "render",
                "--scene",
                &door_gap(),
                "--guiding",
                guiding,
                "--width",
                "24",
                "--height",
                "18",
                "--spp",
                "16",
                "--out",
                out.to_str().unwrap(),
                "--stats",
                stats.to_str().unwrap(),
            ],
        );
        assert!(
            run.status.success(),
            "{}",
            String::from_utf8_lossy(&run.stderr)
        );
        let image = read_image(&out).unwrap();
        assert!(image.pixels.iter().all(|p| p.is_finite()));
        assert!(image.pixels.iter().any(|p| p.max_element() > 0.0), "lit");
        let json: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(&stats).unwrap()).unwrap();
        assert_eq!(json["guiding"], guiding);
        if guiding == "off" {
            assert_eq!(json["spp"], 16, "unguided, the budget is the image's");
            assert!(json.get("training").is_none());
        } else {
            // Training of 1, 2 and 4 samples per pixel; the final pass gets the other 9, and
            // the image averages all four passes, each by its samples times the square root
            // of the samples before it (the default): 1 x 0, 2 x 1, 4 x √3, 9 x √7.
            let training = &json["training"];
            assert_eq!(training["spp"], 7, "{json}");
            assert_eq!(json["spp"], 16, "{json}");
            let iterations = training["iterations"].as_array().unwrap();
            assert_eq!(iterations.len(), 3);
            let weights: Vec<f64> = training["pass_weights"]
                .as_array()
                .unwrap()
                .iter()
                .map(|w| w.as_f64().unwrap())
                .collect();
            assert_eq!(training["combine_passes"], "learning", "{json}");
            let raw = [0.0, 2.0, 4.0 * 3f64.sqrt(), 9.0 * 7f64.sqrt()];
            let total: f64 = raw.iter().sum();
            for (w, r) in weights.iter().zip(raw) {
                assert!((w - r / total).abs() < 1e-12, "{json}");
            }
            // Without --bsdf-fraction the fraction is learnt, and stays a probability.
            assert_eq!(json["bsdf_fraction"], "learnt", "{json}");
            let learnt = &training["learnt_fractions"];
            for key in ["min", "mean", "max"] {
                let f = learnt[key].as_f64().unwrap();
                assert!(f > 0.0 && f < 1.0, "{json}");
            }
            assert!(
                iterations
                    .iter()
                    .all(|i| i["memory_bytes"].as_u64().unwrap() > 0)
            );
        }
    }
}

#[test]
fn render_refuses_a_bsdf_fraction_that_leaves_a_technique_out() {
    for fraction in ["0", "1", "1.5", "-0.2", "half"] {
        assert_refused(
            BINARY,
            &[
                "render",
                "--scene",
                &door_gap(),
                "--bsdf-fraction",
                fraction,
                "--out",
                "x.png",
            ],
            "--bsdf-fraction",
        );
    }
    assert_refused(
        BINARY,
        &[
            "render",
            "--scene",
            &door_gap(),
            "--guiding",
            "best",
            "--out",
            "x.png",
        ],
        "--guiding",
    );
    assert_refused(
        BINARY,
        &["render", "--out", "x.png"],
        "render needs a scene",
    );
}
