//! The chapter's figures: the diagrams (`diagrams/`), the lecture's aperture series, three
//! focus settings, the naive lens warp against the correct ones, polygonal bokeh, where lens
//! samples land, the circle of confusion against depth, and error against time. Every number
//! the chapter's page quotes from a run is written here too, as a small Markdown file the page
//! includes (`circle_of_confusion.md`, `convergence.md`, `mitsuba_naive.md`).

use crate::aperture::{
    Aperture, LensWarp, sample_uniform_regular_polygon, sample_uniform_regular_polygon_pdf,
};
use crate::circle_of_confusion::{circle_of_confusion_pixels, measured_blur_width};
use crate::lens::Lens;
use crate::render_with;
use crate::scenes::{BOKEH_SPHERE_DEPTHS, BOKEH_WALL_DEPTH, Builtin, DEFAULT_MAX_DEPTH};
use crate::thin_lens::ThinLensCamera;
use ch01_whitted::camera::PinholeCamera;
use ch03_anti_aliasing::{FilterKind, PixelSampler, PixelSamplerKind, ReconstructionFilter};
use common::geometry::Sphere;
use common::image::Image;
use common::render::RenderSettings;
use common::sampler::{IndependentSampler, Sampler};
use common::scene::CameraFrame;
use common::scene::Scene;
use glam::{UVec2, Vec2, Vec3};
use std::path::Path;
use workbench::convergence::{
    Technique, plot_error_vs_spp, plot_error_vs_time, run_convergence, write_convergence_csv,
};
use workbench::figure_set::{FigureSet, Level, RenderQuality};
use workbench::output::figures::{
    Axes, Series, SeriesStyle, comparison_grid, line_plot, scatter_plot,
};
use workbench::output::write_text;

/// The aperture radii of the lecture's series, in scene units: zero, small, large, very large.
pub const APERTURE_SERIES: [(f32, &str); 4] = [
    (0.0, "zero aperture (pinhole)"),
    (0.03, "small aperture, R = 0.03"),
    (0.12, "large aperture, R = 0.12"),
    (0.35, "very large aperture, R = 0.35"),
];

/// Image sizes and budgets: the book's, or small ones for tests and CI.
struct Quality {
    render: RenderQuality,
    /// Samples per pixel of the enlarged details.
    detail_spp: u64,
    /// Points in each lens scatter plot.
    lens_points: u32,
    /// Size of the error-against-time renders.
    convergence_size: (u32, u32),
}

impl Quality {
    fn at(level: Level) -> Self {
        let render = RenderQuality {
            width: level.pick(120, 300),
            height: level.pick(80, 200),
            spp: level.pick(16, 32),
            budgets: level.pick(&[1, 4, 16], &[1, 4, 16, 64, 256]),
            reference_spp: level.pick(256, 2048),
        };
        Quality {
            render,
            detail_spp: level.pick(64, 512),
            lens_points: level.pick(512, 2048),
            convergence_size: level.pick((48, 32), (60, 40)),
        }
    }
}

/// Writes every figure of the chapter into `out`.
pub fn write_all(out: &Path, quick: bool) -> anyhow::Result<()> {
    let mut figures = FigureSet::start("ch04", out, quick)?;
    let quality = Quality::at(figures.level());
    let scene = Builtin::Bokeh.build(DEFAULT_MAX_DEPTH);
    figures.make("the diagrams", |out| {
        crate::lab::diagrams::write_all(&out.join("diagrams"))
    })?;
    let gallery = Gallery::new(&scene, &quality);
    figures.make("the aperture series", |out| aperture_series(out, &gallery))?;
    figures.make("the focus figure", |out| focus_depths(out, &gallery))?;
    figures.make("the naive-warp figure", |out| {
        naive_against_correct(out, &quality, &gallery)
    })?;
    figures.make("the bokeh-shape figure", |out| {
        bokeh_shapes(out, &quality, &gallery)
    })?;
    figures.make("the lens-sample plot", |out| lens_samples(out, &quality))?;
    figures.make("the circle-of-confusion plot", |out| {
        circle_of_confusion_plot(out, &quality)
    })?;
    figures.make("the error-against-time figures", |out| {
        convergence(out, &quality, &scene)
    })?;
    figures.agreement(&crate::lab::agreement::AGREEMENT)?;
    figures.make("the naive warp against Mitsuba 3", naive_against_mitsuba)?;
    figures.finish()
}

/// The gallery renders of the bokeh scene, each rendered once however many figures show it.
struct Gallery<'a> {
    scene: &'a Scene,
    settings: RenderSettings,
    rendered: std::cell::RefCell<Vec<(Lens, Image)>>,
}

impl<'a> Gallery<'a> {
    fn new(scene: &'a Scene, quality: &Quality) -> Self {
        Self {
            scene,
            settings: quality.render.gallery(),
            rendered: Default::default(),
        }
    }

    /// The scene through `lens`, rendered now or taken from an earlier figure.
    fn image(&self, lens: Lens) -> Image {
        if let Some((_, image)) = self.rendered.borrow().iter().find(|(l, _)| *l == lens) {
            return image.clone();
        }
        let image = render(self.scene, lens, &self.settings, 0);
        self.rendered.borrow_mut().push((lens, image.clone()));
        image
    }
}

/// Renders the bokeh scene through `lens` with stratified pixel samples and a box filter.
fn render(scene: &Scene, lens: Lens, settings: &RenderSettings, seed: u64) -> Image {
    let spp = match settings.budget {
        common::render::Budget::Samples(spp) => spp,
        common::render::Budget::Seconds(_) => 1,
    };
    let sampler = PixelSampler::new(PixelSamplerKind::Stratified, spp, seed)
        .expect("a positive sample count");
    let filter = ReconstructionFilter::new(FilterKind::Box, None).expect("the box filter");
    render_with(scene, &lens, settings, &sampler, &filter).image
}

/// A disc lens of radius `radius` focused at `focus`.
fn disc(radius: f32, focus: f32) -> Lens {
    Lens::new(radius, focus).expect("the figures' lenses are valid")
}

/// The lecture's series: the same scene, focused on the middle sphere, through a growing
/// aperture.
fn aperture_series(out: &Path, gallery: &Gallery) -> anyhow::Result<()> {
    let cells: Vec<(String, Image)> = APERTURE_SERIES
        .iter()
        .map(|&(radius, label)| {
            let lens = disc(radius, BOKEH_SPHERE_DEPTHS[1]);
            (label.to_string(), gallery.image(lens))
        })
        .collect();
    comparison_grid(&out.join("apertures.png"), &cells, 2, 1)?;
    Ok(())
}

/// One aperture, focused on each of the three spheres in turn.
fn focus_depths(out: &Path, gallery: &Gallery) -> anyhow::Result<()> {
    let names = ["near", "middle", "far"];
    let cells: Vec<(String, Image)> = BOKEH_SPHERE_DEPTHS
        .iter()
        .zip(names)
        .map(|(&depth, name)| {
            let lens = disc(0.12, depth);
            (
                format!("focused on the {name} sphere, d_f = {depth}"),
                gallery.image(lens),
            )
        })
        .collect();
    comparison_grid(&out.join("focus.png"), &cells, 3, 1)?;
    Ok(())
}

/// Where a world point lands on the film of `camera`, in pixels, or `None` behind it.
fn project(camera: &PinholeCamera, point: Vec3) -> Option<Vec2> {
    let frame = &camera.frame;
    let v = point - frame.origin;
    let (x, y, z) = (v.dot(frame.left), v.dot(frame.up), v.dot(frame.forward));
    if z <= 0.0 {
        return None;
    }
    let aspect = camera.width as f32 / camera.height as f32;
    let t = camera.tan_half_fov_x;
    Some(Vec2::new(
        0.5 * (1.0 - x / (z * t)) * camera.width as f32,
        0.5 * (1.0 - y * aspect / (z * t)) * camera.height as f32,
    ))
}

/// Renders only the `side x side` window of the full-size image centred on `centre`, with
/// `spp` samples per pixel: enlarged details of a highlight, converged without paying for
/// the whole image.
fn render_window(
    scene: &Scene,
    lens: Lens,
    quality: &Quality,
    centre: Vec2,
    side: u32,
    spp: u64,
) -> Image {
    let camera = ThinLensCamera::new(
        PinholeCamera::of(&scene.camera, quality.render.width, quality.render.height),
        lens,
    );
    let side = side.min(quality.render.width).min(quality.render.height);
    let start = |c: f32, size: u32| {
        (c - side as f32 / 2.0)
            .clamp(0.0, (size - side) as f32)
            .floor()
    };
    let offset = Vec2::new(
        start(centre.x, quality.render.width),
        start(centre.y, quality.render.height),
    );
    let settings = RenderSettings {
        progress: true,
        ..RenderSettings::new(side, side, spp)
    };
    let sampler =
        PixelSampler::new(PixelSamplerKind::Stratified, spp, 0).expect("a positive sample count");
    let filter = ReconstructionFilter::new(FilterKind::Box, None).expect("the box filter");
    common::render::render(&settings, &sampler, &filter, |p_film, sampler| {
        let ray = camera.generate_ray(p_film + offset, sampler);
        ch01_whitted::tracer::trace(scene, &ray, 1)
    })
    .image
}

/// A hole of the far wall, as the camera of `scene` sees it at `width x height`.
fn highlight_on_film(scene: &Scene, quality: &Quality) -> Vec2 {
    let camera = PinholeCamera::of(&scene.camera, quality.render.width, quality.render.height);
    // The hole at x = -1.2 on the upper row (see `scenes`), near the middle of the picture.
    let wall_z = 7.0 - BOKEH_WALL_DEPTH;
    project(&camera, Vec3::new(-1.12, 2.68, wall_z)).expect("the wall is in front")
}

/// The naive lens warp against the concentric one, with the near sphere in focus so that the
/// far wall's holes blur into large discs; below, the same highlight enlarged.
fn naive_against_correct(out: &Path, quality: &Quality, gallery: &Gallery) -> anyhow::Result<()> {
    let scene = gallery.scene;
    let lens = disc(0.12, BOKEH_SPHERE_DEPTHS[0]);
    let warps = [
        (
            LensWarp::Naive,
            "naive warp r = ξ2: too bright in the middle",
        ),
        (LensWarp::Polar, "corrected polar warp"),
        (LensWarp::Concentric, "concentric warp (Mitsuba's)"),
    ];
    // The full pictures of the two extremes; the details below show all three warps.
    let images: Vec<(String, Image)> = [warps[0], warps[2]]
        .iter()
        .map(|&(warp, label)| (label.to_string(), gallery.image(lens.with_warp(warp))))
        .collect();
    comparison_grid(&out.join("naive_vs_correct.png"), &images, 2, 1)?;
    let centre = highlight_on_film(scene, quality);
    let side = quality.render.height / 4;
    let crops: Vec<(String, Image)> = warps
        .iter()
        .map(|&(warp, _)| {
            (
                format!("{} warp, enlarged, {} spp", warp.name(), quality.detail_spp),
                render_window(
                    scene,
                    lens.with_warp(warp),
                    quality,
                    centre,
                    side,
                    quality.detail_spp,
                ),
            )
        })
        .collect();
    let scale = (300 / side).max(1);
    comparison_grid(&out.join("naive_vs_correct_crops.png"), &crops, 3, scale)?;
    Ok(())
}

/// The blurred highlights take the aperture's shape: a disc, a pentagon, a hexagon.
fn bokeh_shapes(out: &Path, quality: &Quality, gallery: &Gallery) -> anyhow::Result<()> {
    let scene = gallery.scene;
    let base = disc(0.12, BOKEH_SPHERE_DEPTHS[0]);
    let shapes = [
        (Aperture::Disc, "disc"),
        (
            Aperture::polygon(5, 0.3).map_err(anyhow::Error::msg)?,
            "5 blades",
        ),
        (
            Aperture::polygon(6, 0.0).map_err(anyhow::Error::msg)?,
            "6 blades",
        ),
    ];
    let centre = highlight_on_film(scene, quality);
    let side = quality.render.height / 4;
    let mut full = Vec::new();
    let mut crops = Vec::new();
    for (aperture, label) in shapes {
        let lens = base.with_aperture(aperture);
        full.push((format!("aperture: {label}"), gallery.image(lens)));
        crops.push((
            format!("{label}, enlarged"),
            render_window(scene, lens, quality, centre, side, quality.detail_spp),
        ));
    }
    comparison_grid(&out.join("bokeh_shapes.png"), &full, 3, 1)?;
    let scale = (300 / side).max(1);
    comparison_grid(&out.join("bokeh_shapes_crops.png"), &crops, 3, scale)?;
    Ok(())
}

/// Where lens samples land on the unit aperture: the naive warp crowds the centre.
fn lens_samples(out: &Path, quality: &Quality) -> anyhow::Result<()> {
    let mut sampler = IndependentSampler::new(7);
    let mut uniforms = Vec::new();
    for i in 0..quality.lens_points {
        sampler.start_pixel_sample(UVec2::ZERO, u64::from(i));
        uniforms.push(sampler.get_2d());
    }
    let mut sets: Vec<(String, Vec<Vec2>)> = LensWarp::ALL
        .iter()
        .rev()
        .map(|&warp| {
            (
                format!("{} disc", warp.name()),
                uniforms.iter().map(|&u| warp.sample(u)).collect(),
            )
        })
        .collect();
    sets.push((
        "hexagon (6 blades)".to_string(),
        uniforms
            .iter()
            .map(|&u| sample_uniform_regular_polygon(u, 6, 0.0))
            .collect(),
    ));
    debug_assert!(
        sets[3]
            .1
            .iter()
            .all(|&p| { sample_uniform_regular_polygon_pdf(p, 6, 0.0) > 0.0 })
    );
    scatter_plot(
        &out.join("lens_samples.png"),
        &format!("{} lens samples on the unit aperture", quality.lens_points),
        &sets,
        [Vec2::splat(-1.0), Vec2::ONE],
    )?;
    Ok(())
}

/// The circle of confusion against depth: the formula as lines, traced rays as dots.
fn circle_of_confusion_plot(out: &Path, quality: &Quality) -> anyhow::Result<()> {
    let frame = CameraFrame::look_at(Vec3::ZERO, Vec3::Z, Vec3::Y).expect("a valid frame");
    let pinhole = PinholeCamera::new(frame, 40.0, 360, 240);
    let focus = BOKEH_SPHERE_DEPTHS[1];
    let depths: Vec<f32> = (0..=200).map(|i| 1.0 + 19.0 * i as f32 / 200.0).collect();
    let measured_depths: &[f32] = if quality.render.width < 200 {
        &[2.0, 5.0, 10.0, 18.0]
    } else {
        &[1.5, 2.5, 4.0, 5.5, 7.0, 9.0, 12.0, 16.0, 20.0]
    };
    let mut series = Vec::new();
    for radius in [0.03, 0.12, 0.35] {
        series.push(Series::new(
            format!("the circle of confusion, R = {radius}"),
            depths
                .iter()
                .map(|&d| {
                    let c = circle_of_confusion_pixels(&pinhole, radius, focus, d);
                    (f64::from(d), f64::from(c))
                })
                .collect(),
            SeriesStyle::Line,
        ));
    }
    // Measured: the band of film positions that see a small sphere, less the sphere's own size.
    let radius = 0.12;
    let rho = 0.002;
    let camera = ThinLensCamera::new(pinhole, disc(radius, focus));
    let pixels_per_tangent_unit = pinhole.width as f32 / (2.0 * pinhole.tan_half_fov_x);
    let measured: Vec<(f64, f64)> = measured_depths
        .iter()
        .map(|&d| {
            let sphere = Sphere::new(Vec3::new(0.0, 0.0, d), rho);
            let own = 2.0 * rho / d * pixels_per_tangent_unit;
            (
                f64::from(d),
                f64::from(measured_blur_width(&camera, &sphere) - own),
            )
        })
        .collect();
    let predicted = |d: f64| {
        f64::from(circle_of_confusion_pixels(
            &pinhole, radius, focus, d as f32,
        ))
    };
    write_text(
        &out.join("circle_of_confusion.md"),
        &circle_of_confusion_table(&measured, predicted, radius, focus),
    )?;
    series.push(Series::new(
        "R = 0.12, measured from traced rays",
        measured,
        SeriesStyle::Points,
    ));
    let axes = Axes::linear(
        "depth d (scene units; focus d_f = 7)",
        "circle of confusion (pixels of a 360-pixel-wide, 40° image)",
    );
    line_plot(
        &out.join("circle_of_confusion.png"),
        "Blur against depth",
        &axes,
        &series,
    )?;
    Ok(())
}

/// Error against time for the three disc warps: the uniform ones converge, the naive one
/// converges to the wrong image.
fn convergence(out: &Path, quality: &Quality, scene: &Scene) -> anyhow::Result<()> {
    let (width, height) = quality.convergence_size;
    let settings = |spp| RenderSettings::new(width, height, spp);
    let lens = disc(0.12, BOKEH_SPHERE_DEPTHS[0]);
    // Random pixel samples: each technique differs only in its lens warp.
    let render_random = |warp: LensWarp, spp: u64, seed: u64| {
        let sampler =
            PixelSampler::new(PixelSamplerKind::Random, spp, seed).expect("a positive count");
        let filter = ReconstructionFilter::new(FilterKind::Box, None).expect("the box filter");
        render_with(
            scene,
            &lens.with_warp(warp),
            &settings(spp),
            &sampler,
            &filter,
        )
        .image
    };
    let reference = render_random(LensWarp::Concentric, quality.render.reference_spp, 1_000);
    let techniques: Vec<Technique> = LensWarp::ALL
        .iter()
        .map(|&warp| Technique::new(warp.name(), move |spp| render_random(warp, spp, 0)))
        .collect();
    let records = run_convergence(&techniques, quality.render.budgets, &reference);
    write_convergence_csv(&out.join("convergence.csv"), &records)?;
    plot_error_vs_time(
        &out.join("convergence.png"),
        "Error against time: lens warps (bokeh scene)",
        &records,
    )?;
    plot_error_vs_spp(
        &out.join("convergence_spp.png"),
        "Error against samples per pixel: lens warps (bokeh scene)",
        &records,
    )?;
    write_text(&out.join("convergence.md"), &convergence_sentence(&records))?;
    Ok(())
}

/// The measured blur beside the formula's, depth by depth, and the largest difference.
fn circle_of_confusion_table(
    measured: &[(f64, f64)],
    predicted: impl Fn(f64) -> f64,
    radius: f32,
    focus: f32,
) -> String {
    let mut table = String::from(
        "| depth d | the formula (pixels) | traced rays (pixels) | difference (pixels) |\n\
         |---:|---:|---:|---:|\n",
    );
    let mut worst: f64 = 0.0;
    for &(d, m) in measured {
        let p = predicted(d);
        worst = worst.max((m - p).abs());
        table.push_str(&format!("| {d} | {p:.2} | {m:.2} | {:+.4} |\n", m - p));
    }
    table.push_str(&format!(
        "\nWith a lens of radius {radius} focused at {focus}, the traced rays and the formula \
         differ by at most {worst:.4} pixels at the depths measured in this run.\n"
    ));
    table
}

/// A sentence for the page: each warp's RMSE at the largest budget, with the comparison
/// worded from the numbers, and how much each fell from the smallest budget to the largest.
fn convergence_sentence(records: &[workbench::convergence::ConvergenceRecord]) -> String {
    let ends = |warp: LensWarp| {
        let mine: Vec<_> = records
            .iter()
            .filter(|r| r.technique == warp.name())
            .collect();
        let first = mine.iter().min_by_key(|r| r.spp).map(|r| (r.spp, r.rmse));
        let last = mine.iter().max_by_key(|r| r.spp).map(|r| (r.spp, r.rmse));
        first.zip(last).unwrap_or(((0, f64::NAN), (0, f64::NAN)))
    };
    let (naive, polar, concentric) = (
        ends(LensWarp::Naive),
        ends(LensWarp::Polar),
        ends(LensWarp::Concentric),
    );
    let above_both = naive.1.1 > polar.1.1 && naive.1.1 > concentric.1.1;
    let below_both = naive.1.1 < polar.1.1 && naive.1.1 < concentric.1.1;
    let comparison = if above_both {
        "higher than"
    } else if below_both {
        "lower than"
    } else {
        "between"
    };
    let fall = |(first, last): ((u64, f64), (u64, f64))| first.1 / last.1;
    format!(
        "In the run that made these figures, at {} samples per pixel the naive warp's RMSE is \
         {:.3}, {comparison} the polar warp's {:.3} and the concentric warp's {:.3}. Going from \
         {} to {} samples per pixel divided the RMSE of the polar and concentric warps by \
         {:.1} and {:.1}, and the naive warp's by {:.1}; pure noise, which falls as one over \
         the square root of the sample count, would be divided by {:.1}.\n",
        naive.1.0,
        naive.1.1,
        polar.1.1,
        concentric.1.1,
        naive.0.0,
        naive.1.0,
        fall(polar),
        fall(concentric),
        fall(naive),
        (naive.1.0 as f64 / naive.0.0.max(1) as f64).sqrt(),
    )
}

/// The thin-lens scene file rendered with the naive lens warp, measured against Mitsuba 3's
/// stored renders: the comparison catches the wrong density (`mitsuba_naive.md`).
fn naive_against_mitsuba(out: &Path) -> anyhow::Result<()> {
    use workbench::agreement::ReferenceRenders;
    let set = &crate::lab::agreement::AGREEMENT;
    let mut text = String::from(
        "| scene | lens warp | RMSE ours | RMSE Mitsuba | bias_blocks ours | bias_blocks Mitsuba | the check |\n\
         |---|---|---:|---:|---:|---:|---|\n",
    );
    for entry in set.scenes {
        let renders = ReferenceRenders::load(&set.stored_renders_dir(), entry.name)?;
        let (scene, side, settings, sampler) =
            crate::lab::scene_file::for_agreement(&set.file(entry), &crate::lab::CAPABILITIES)
                .map_err(anyhow::Error::msg)?;
        for warp in [side.lens.warp, LensWarp::Naive] {
            let lens = side.lens.with_warp(warp);
            let image = render_with(&scene, &lens, &settings, &sampler, &side.film.filter).image;
            let a = renders.agreement(&image);
            text.push_str(&format!(
                "| {} | {} | {:.2e} | {:.2e} | {:.3} | {:.3} | {} |\n",
                entry.name,
                warp.name(),
                a.ours.rmse,
                a.other.rmse,
                a.ours.bias_blocks,
                a.other.bias_blocks,
                if a.holds() { "passes" } else { "fails" },
            ));
        }
    }
    write_text(&out.join("mitsuba_naive.md"), &text)?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn projection_inverts_the_pinhole_ray() {
        let scene = Builtin::Bokeh.build(DEFAULT_MAX_DEPTH);
        let camera = PinholeCamera::of(&scene.camera, scene.film.width, scene.film.height);
        let p_film = Vec2::new(100.5, 37.25);
        let ray = camera.generate_ray(p_film);
        let back = project(&camera, ray.at(5.0)).unwrap();
        assert!((back - p_film).length() < 1e-3, "{back}");
    }

    #[test]
    fn the_convergence_sentence_words_the_comparison_from_the_numbers() {
        let record =
            |warp: LensWarp, spp: u64, rmse: f64| workbench::convergence::ConvergenceRecord {
                technique: warp.name().to_string(),
                spp,
                seconds: spp as f64,
                rmse,
                relmse: rmse,
            };
        let run = |naive_last: f64| {
            convergence_sentence(&[
                record(LensWarp::Naive, 1, 0.8),
                record(LensWarp::Naive, 16, naive_last),
                record(LensWarp::Polar, 1, 0.8),
                record(LensWarp::Polar, 16, 0.2),
                record(LensWarp::Concentric, 1, 0.8),
                record(LensWarp::Concentric, 16, 0.25),
            ])
        };
        assert!(
            run(0.4).contains("0.400, higher than the polar"),
            "{}",
            run(0.4)
        );
        assert!(
            run(0.1).contains("0.100, lower than the polar"),
            "{}",
            run(0.1)
        );
        assert!(run(0.22).contains("between the polar"), "{}", run(0.22));
        assert!(run(0.4).contains("would be divided by 4.0"), "{}", run(0.4));
    }

    #[test]
    fn the_circle_of_confusion_table_reports_the_largest_difference() {
        let table = circle_of_confusion_table(&[(2.0, 10.5), (4.0, 4.75)], |d| 20.0 / d, 0.1, 5.0);
        assert!(table.contains("| 2 | 10.00 | 10.50 | +0.5000 |"), "{table}");
        assert!(table.contains("differ by at most 0.5000 pixels"), "{table}");
    }
}
