//! How fast is chapter 08's path tracer beside Mitsuba 3, at the same noise per sample?
//!
//! ```text
//! MITSUBA_PYTHON=/path/to/python cargo bench -p ch08-path-tracing --bench against_mitsuba
//! cargo bench -p ch08-path-tracing --bench against_mitsuba -- --threads 1 --pairs 5
//! ```
//!
//! Two scenes, each rendered by both renderers from the same file:
//! - `cornell`: the chapter's Cornell box at 256 × 256, `max_depth` 8, without Russian roulette
//!   (a mirror sphere, a glass sphere, an area light: planes, spheres and every path segment);
//! - `mesh`: a bumpy sphere of at least 100 000 triangles in the same room, written as a binary
//!   PLY file, so that most of the time goes into finding which triangle a ray meets.
//!
//! Each scene is rendered in `--pairs` back-to-back rounds (3 by default): ours, then Mitsuba's
//! `scalar_rgb`, then its `llvm_ad_rgb`, each with the round's seed. The report is the median
//! samples per second of each and the ratios of ours to theirs, and what each traced its rays
//! with: Mitsuba's Python wheels are built with Embree, which both variants then use for
//! every shape. Mitsuba's time is that of `mi.render` alone (loading and, for the LLVM
//! variant, compiling its kernels in a first render are left out); ours is `render --stats`'
//! `seconds`, which also leaves the loading out.
//!
//! Speed is only half of it: a renderer that traces fewer rays per sample is faster and
//! noisier. So the report also gives each renderer's noise per sample, the variance of a
//! pixel across the rounds' seeds times the samples per pixel, averaged over the image; equal
//! noise per sample makes samples per second the fair comparison.
//!
//! Without `MITSUBA_PYTHON` only ours is timed. This is a benchmark, not a test: nothing here
//! fails on a number.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

use clap::Parser;
use common::geometry::TriangleMesh;
use common::image::Image;
use workbench::agreement::mitsuba_python;
use workbench::output::read_image;
use workbench::test_support::mesh_files::{PlyEncoding, PlyStyle, write_ply};

#[derive(Parser, Debug)]
#[command(about = "Chapter 08 against Mitsuba 3: samples per second at equal noise per sample")]
struct Args {
    /// Render threads of both renderers.
    #[arg(long, default_value_t = 2, value_parser = clap::value_parser!(u32).range(1..=1024))]
    threads: u32,
    /// Back-to-back rounds per scene (the median is reported).
    #[arg(long, default_value_t = 3, value_parser = clap::value_parser!(u64).range(1..=100))]
    pairs: u64,
    /// Samples per pixel.
    #[arg(long, default_value_t = 64, value_parser = clap::value_parser!(u64).range(1..=1_000_000))]
    spp: u64,
    /// Triangles of the mesh scene's bumpy sphere (at least).
    #[arg(long, default_value_t = 100_000, value_parser = clap::value_parser!(u64).range(1..=50_000_000))]
    triangles: u64,
    /// Mitsuba's variants to time beside ours.
    #[arg(long, value_delimiter = ',', default_value = "scalar_rgb,llvm_ad_rgb")]
    variants: Vec<String>,
    /// Keeps the mesh scene and the images in this directory (for profiling one renderer on
    /// the same files) instead of a temporary one.
    #[arg(long, value_name = "DIR")]
    keep: Option<PathBuf>,
    /// Passed by `cargo bench`; ignored.
    #[arg(long, hide = true)]
    bench: bool,
}

/// A scene file and the `-D` parameters it is rendered with.
struct BenchScene {
    name: &'static str,
    file: PathBuf,
    defines: Vec<String>,
}

/// One render: its image, the seconds of the render alone, and what found the rays' hits.
struct Run {
    image: Image,
    seconds: f64,
    /// The acceleration structure the renderer traced with.
    traced_by: &'static str,
}

fn main() {
    let args = Args::parse();
    let python = mitsuba_python();
    let temporary = tempfile::tempdir().expect("a temporary directory");
    let dir = match &args.keep {
        Some(dir) => {
            std::fs::create_dir_all(dir).expect("the --keep directory can be made");
            dir.as_path()
        }
        None => temporary.path(),
    };
    let scenes = [cornell(), mesh_scene(dir, args.triangles as usize)];
    if python.is_none() {
        println!("MITSUBA_PYTHON is not set: timing ours alone.");
    }
    for scene in &scenes {
        println!(
            "\n{}: 256 x 256, {} spp, {} threads",
            scene.name, args.spp, args.threads
        );
        let mut renderers: Vec<(String, Vec<Run>)> = vec![("ours".to_owned(), Vec::new())];
        if python.is_some() {
            for variant in &args.variants {
                renderers.push((format!("Mitsuba {variant}"), Vec::new()));
            }
        }
        for seed in 0..args.pairs {
            renderers[0].1.push(render_ours(scene, &args, seed, dir));
            if let Some(python) = &python {
                for (k, variant) in args.variants.iter().enumerate() {
                    let run = render_mitsuba(python, variant, scene, &args, seed, dir);
                    renderers[k + 1].1.push(run);
                }
            }
        }
        report(&renderers, args.spp);
    }
}

/// The chapter's Cornell box at 256 × 256 and `max_depth` 8, with Russian roulette switched
/// off, so that every sample follows its path to the depth limit in both renderers.
fn cornell() -> BenchScene {
    BenchScene {
        name: "cornell",
        file: Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/cornell-box.xml"),
        defines: ["width=256", "height=256", "max_depth=8", "rr_depth=1000"]
            .map(String::from)
            .to_vec(),
    }
}

/// The same room with a bumpy sphere of at least `triangles` triangles in place of the two
/// spheres, written with its mesh into `dir`.
fn mesh_scene(dir: &Path, triangles: usize) -> BenchScene {
    let started = Instant::now();
    let mesh = TriangleMesh::bumpy_sphere(triangles);
    let ply = dir.join("bumpy-sphere.ply");
    std::fs::write(
        &ply,
        write_ply(&mesh, None, &PlyStyle::plain(PlyEncoding::LittleEndian)),
    )
    .expect("the mesh is written");
    println!(
        "mesh: a bumpy sphere of {} triangles, made and written in {:.2} s",
        mesh.indices.len(),
        started.elapsed().as_secs_f64()
    );
    let file = dir.join("mesh.xml");
    std::fs::write(&file, MESH_SCENE).expect("the scene is written");
    BenchScene {
        name: "mesh",
        file,
        defines: vec!["max_depth=8".to_owned()],
    }
}

/// The mesh scene: the Cornell box's room and light, and a bumpy sphere of radius 0.6.
const MESH_SCENE: &str = r#"<scene version="3.0.0">
    <default name="spp" value="64"/>
    <default name="max_depth" value="8"/>
    <integrator type="path">
        <integer name="max_depth" value="$max_depth"/>
        <integer name="rr_depth" value="1000"/>
    </integrator>
    <sensor type="perspective">
        <float name="fov" value="40"/>
        <transform name="to_world"><lookat origin="0, 1, 3.8" target="0, 1, 0" up="0, 1, 0"/></transform>
        <sampler type="independent"><integer name="sample_count" value="$spp"/></sampler>
        <film type="hdrfilm">
            <integer name="width" value="256"/>
            <integer name="height" value="256"/>
            <rfilter type="box"/>
        </film>
    </sensor>
    <bsdf type="diffuse" id="white"><rgb name="reflectance" value="0.75, 0.75, 0.75"/></bsdf>
    <bsdf type="diffuse" id="red"><rgb name="reflectance" value="0.65, 0.08, 0.06"/></bsdf>
    <bsdf type="diffuse" id="green"><rgb name="reflectance" value="0.12, 0.55, 0.1"/></bsdf>
    <shape type="rectangle">
        <transform name="to_world"><rotate x="1" angle="-90"/></transform>
        <ref id="white"/>
    </shape>
    <shape type="rectangle">
        <transform name="to_world"><rotate x="1" angle="90"/><translate y="2"/></transform>
        <ref id="white"/>
    </shape>
    <shape type="rectangle">
        <transform name="to_world"><translate y="1" z="-1"/></transform>
        <ref id="white"/>
    </shape>
    <shape type="rectangle">
        <transform name="to_world"><rotate y="1" angle="90"/><translate x="-1" y="1"/></transform>
        <ref id="red"/>
    </shape>
    <shape type="rectangle">
        <transform name="to_world"><rotate y="1" angle="-90"/><translate x="1" y="1"/></transform>
        <ref id="green"/>
    </shape>
    <shape type="ply">
        <string name="filename" value="bumpy-sphere.ply"/>
        <transform name="to_world"><scale value="0.6"/><translate y="0.7"/></transform>
        <ref id="white"/>
    </shape>
    <shape type="rectangle">
        <transform name="to_world"><scale value="0.4"/><rotate x="1" angle="90"/><translate y="1.99"/></transform>
        <emitter type="area"><rgb name="radiance" value="17, 12, 4"/></emitter>
    </shape>
</scene>
"#;

/// Renders with chapter 08's binary and reads back its image and `--stats` time.
fn render_ours(scene: &BenchScene, args: &Args, seed: u64, dir: &Path) -> Run {
    let out = dir.join(format!("ours-{}-{seed}.pfm", scene.name));
    let stats = dir.join("ours-stats.json");
    let mut command = Command::new(env!("CARGO_BIN_EXE_ch08-path-tracing"));
    command.arg("render").arg("--scene").arg(&scene.file);
    for define in &scene.defines {
        command.arg("-D").arg(define);
    }
    command
        .args(["--spp", &args.spp.to_string()])
        .args(["--seed", &seed.to_string()])
        .args(["--threads", &args.threads.to_string()])
        .arg("--out")
        .arg(&out)
        .arg("--stats")
        .arg(&stats);
    let output = command.output().expect("chapter 08's binary runs");
    assert!(
        output.status.success(),
        "our render of {} failed: {}",
        scene.name,
        String::from_utf8_lossy(&output.stderr)
    );
    let stats: serde_json::Value =
        serde_json::from_slice(&std::fs::read(&stats).expect("the stats are written"))
            .expect("the stats are JSON");
    Run {
        image: read_image(&out).expect("our image is readable"),
        seconds: stats["seconds"]
            .as_f64()
            .expect("the stats hold the seconds"),
        traced_by: "its own BVH",
    }
}

/// Loads the scene (argv 1) in the variant (argv 2) with the sample count (argv 3), the seed
/// (argv 4) and the threads (argv 5) and `-D` parameters (argv 7...); renders it once to warm
/// up (the LLVM variant compiles its kernels then), then again, timed, and writes that image
/// as a linear PFM (argv 6). Prints whether the variant traces with Embree (Mitsuba's own
/// kd-tree otherwise), then the timed render's seconds.
const MITSUBA_SCRIPT: &str = r#"
import sys, time, numpy as np, drjit as dr, mitsuba as mi
mi.set_variant(sys.argv[2])
dr.set_thread_count(int(sys.argv[5]))
params = dict(kv.split("=", 1) for kv in sys.argv[7:])
scene = mi.load_file(sys.argv[1], spp=int(sys.argv[3]), **params)
seed = int(sys.argv[4])
if not sys.argv[2].startswith("scalar"):
    dr.eval(mi.render(scene, seed=seed + 1000)); dr.sync_thread()
start = time.perf_counter()
img = mi.render(scene, seed=seed)
dr.eval(img); dr.sync_thread()
seconds = time.perf_counter() - start
img = np.array(img, dtype=np.float32)[:, :, :3]
h, w, _ = img.shape
with open(sys.argv[6], "wb") as f:
    f.write(b"PF\n%d %d\n-1.0\n" % (w, h))
    f.write(np.ascontiguousarray(img[::-1]).astype("<f4").tobytes())
print("embree", bool(getattr(mi, "MI_ENABLE_EMBREE", False)))
print(seconds)
"#;

/// Renders with Mitsuba 3 in `variant` and reads back its image and time.
fn render_mitsuba(
    python: &str,
    variant: &str,
    scene: &BenchScene,
    args: &Args,
    seed: u64,
    dir: &Path,
) -> Run {
    let out = dir.join(format!("mitsuba-{variant}-{}-{seed}.pfm", scene.name));
    let output = Command::new(python)
        .arg("-c")
        .arg(MITSUBA_SCRIPT)
        .arg(&scene.file)
        .arg(variant)
        .arg(args.spp.to_string())
        .arg(seed.to_string())
        .arg(args.threads.to_string())
        .arg(&out)
        .args(&scene.defines)
        .output()
        .unwrap_or_else(|e| panic!("cannot run {python}: {e}"));
    assert!(
        output.status.success(),
        "Mitsuba ({variant}) failed on {}: {}",
        scene.name,
        String::from_utf8_lossy(&output.stderr)
    );
    let stdout = String::from_utf8_lossy(&output.stdout);
    let traced_by = if stdout.lines().any(|line| line.trim() == "embree True") {
        "Embree"
    } else {
        "its own kd-tree"
    };
    let seconds = stdout
        .lines()
        .last()
        .and_then(|line| line.trim().parse().ok())
        .unwrap_or_else(|| panic!("Mitsuba printed no time: {stdout}"));
    Run {
        image: read_image(&out).expect("Mitsuba's image is readable"),
        seconds,
        traced_by,
    }
}

/// Prints each renderer's median samples per second, its ratio to ours, its noise per
/// sample, and what it traced with: Mitsuba's wheels trace with Embree, whose kernels use the
/// widest vector instructions the processor has, where ours are written for four lanes.
fn report(renderers: &[(String, Vec<Run>)], spp: u64) {
    let image = &renderers[0].1[0].image;
    let samples = f64::from(image.width * image.height) * spp as f64;
    let ours = median_rate(&renderers[0].1, samples);
    println!(
        "{:<24} {:>14} {:>12} {:>18} {:>14}  traced by",
        "renderer", "samples/s", "ours/theirs", "noise per sample", "mean radiance"
    );
    for (name, runs) in renderers {
        let rate = median_rate(runs, samples);
        let noise = noise_per_sample(runs, spp)
            .map_or_else(|| "(needs 2 rounds)".to_owned(), |n| format!("{n:.4}"));
        println!(
            "{name:<24} {rate:>14.0} {:>12.3} {noise:>18} {:>14.5}  {}",
            ours / rate,
            mean_radiance(runs),
            runs[0].traced_by
        );
    }
}

/// The median of the runs' samples per second.
fn median_rate(runs: &[Run], samples: f64) -> f64 {
    let mut rates: Vec<f64> = runs.iter().map(|run| samples / run.seconds).collect();
    rates.sort_by(f64::total_cmp);
    rates[rates.len() / 2]
}

/// The variance of a pixel's channels across the runs (each of another seed), averaged over
/// the image, times the samples per pixel: the variance of one sample.
fn noise_per_sample(runs: &[Run], spp: u64) -> Option<f64> {
    if runs.len() < 2 {
        return None;
    }
    let n = runs.len() as f64;
    let pixels = runs[0].image.pixels.len();
    let mut total = 0.0;
    for p in 0..pixels {
        for channel in 0..3 {
            let values = runs
                .iter()
                .map(|run| f64::from(run.image.pixels[p][channel]));
            let mean = values.clone().sum::<f64>() / n;
            total += values.map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0);
        }
    }
    Some(total / (3 * pixels) as f64 * spp as f64)
}

/// The mean of every pixel channel of every run: the two renderers must agree on it.
fn mean_radiance(runs: &[Run]) -> f64 {
    let values = runs.iter().flat_map(|run| run.image.pixels.iter());
    let count = runs.len() * runs[0].image.pixels.len() * 3;
    values.map(|p| f64::from(p.x + p.y + p.z)).sum::<f64>() / count as f64
}
