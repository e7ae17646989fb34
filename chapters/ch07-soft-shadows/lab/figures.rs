//! The chapter's figures: the lecture's small and large light; one light of each shape;
//! shadow rays per light; a sphere light sampled by area and by solid angle; the naive disc's
//! wrong penumbra, measured; where the points land on each light; error against time; and the
//! sentences that put the measured numbers into the page.

use crate::estimator::light_sample_contribution;
use crate::reference::disc_on_axis_irradiance;
use crate::sample_stream::SampleStream;
use crate::scenes::{Builder, Builtin, DEFAULT_MAX_DEPTH, camera, floor, matte};
use crate::{
    AreaLight, DiscWarp, LightOptions, LightSampling, LightStrata, Strategy, light_samples,
    render_with,
};
use ch03_anti_aliasing::{FilterKind, PixelSampler, PixelSamplerKind, ReconstructionFilter};
use ch04_depth_of_field::Lens;
use ch05_motion_blur::MotionScene;
use ch06_fuzzy_reflections::TraceOptions;
use common::geometry::{Disc, Parallelogram, Shape, Sphere, Triangle};
use common::image::Image;
use common::metrics::{mean, rmse};
use common::render::RenderSettings;
use common::sampler::{IndependentSampler, Sampler};
use glam::{UVec2, Vec2, Vec3};
use std::path::Path;
use workbench::convergence::{
    ConvergenceRecord, Technique, plot_error_vs_spp, plot_error_vs_time, run_convergence,
    write_convergence_csv,
};
use workbench::figure_set::{FigureSet, Level, RenderQuality};
use workbench::output::figures::{comparison_grid, scatter_plot};
use workbench::output::write_text;

/// Image sizes and budgets: the book's, or small ones for tests and CI.
fn quality(level: Level) -> RenderQuality {
    RenderQuality {
        width: level.pick(96, 320),
        height: level.pick(72, 240),
        spp: level.pick(8, 32),
        budgets: level.pick(&[1, 4], &[1, 4, 16, 32]),
        reference_spp: level.pick(64, 128),
    }
}

/// Writes every figure of the chapter into `out`.
pub fn write_all(out: &Path, quick: bool) -> anyhow::Result<()> {
    let mut figures = FigureSet::start("ch07", out, quick)?;
    let q = quality(figures.level());
    figures.make("the diagrams", |out| {
        crate::lab::diagrams::write_all(&out.join("diagrams"))
    })?;
    figures.make("the gallery of lights", |out| gallery(out, &q))?;
    figures.make("the shadow rays per light", |out| {
        samples_per_light(out, &q)
    })?;
    figures.make("the sphere light's strategies", |out| {
        sphere_strategies(out, &q)
    })?;
    figures.make("the disc warps", |out| disc_warps(out, &q))?;
    figures.make("the light-sample plots", light_points)?;
    figures.make("the error-against-time figures", |out| convergence(out, &q))?;
    let level = figures.level();
    figures.make("the estimator's measurements", |out| {
        measurements(out, level)
    })?;
    figures.agreement(&crate::lab::agreement::AGREEMENT)?;
    figures.finish()
}

/// Renders `scene` at `width x height` with stratified pixel positions, box-filtered.
fn render(
    scene: &MotionScene,
    lights: LightOptions,
    size: (u32, u32),
    spp: u64,
    seed: u64,
) -> Image {
    let settings = RenderSettings::new(size.0, size.1, spp);
    let pixels =
        PixelSampler::new(PixelSamplerKind::Stratified, spp, seed).expect("a positive count");
    let filter = ReconstructionFilter::new(FilterKind::Box, None).expect("the box filter");
    render_with(
        scene,
        lights,
        TraceOptions::default(),
        &Lens::PINHOLE,
        &settings,
        &pixels,
        &filter,
    )
    .image
}

/// The lecture's pair, and the other built-in scenes.
fn gallery(out: &Path, q: &RenderQuality) -> anyhow::Result<()> {
    let size = (q.width, q.height);
    let lights = LightOptions::with_samples(4);
    let pair = vec![
        (
            format!(
                "a small light ({} wide): nearly hard shadows",
                crate::scenes::SMALL_PANEL
            ),
            render(
                &Builtin::Small.build(DEFAULT_MAX_DEPTH, 1.0),
                lights,
                size,
                q.spp,
                0,
            ),
        ),
        (
            format!(
                "a large light ({} wide), same power: soft shadows",
                10.0 * crate::scenes::SMALL_PANEL
            ),
            render(
                &Builtin::Large.build(DEFAULT_MAX_DEPTH, 1.0),
                lights,
                size,
                q.spp,
                0,
            ),
        ),
    ];
    comparison_grid(&out.join("small_large.png"), &pair, 2, 1)?;
    let others = vec![
        (
            "parallelogram, triangle, disc and sphere lights".to_string(),
            render(
                &Builtin::Shapes.build(DEFAULT_MAX_DEPTH, 1.0),
                lights,
                size,
                q.spp,
                0,
            ),
        ),
        (
            "red, green and blue discs and a point light".to_string(),
            render(
                &Builtin::Several.build(DEFAULT_MAX_DEPTH, 1.0),
                lights,
                size,
                q.spp,
                0,
            ),
        ),
        (
            "a glossy floor reflecting a sphere light and a panel".to_string(),
            render(
                &Builtin::Glossy.build(DEFAULT_MAX_DEPTH, 1.0),
                lights,
                size,
                4 * q.spp,
                0,
            ),
        ),
    ];
    comparison_grid(&out.join("shapes.png"), &others, 3, 1)?;
    Ok(())
}

/// The large light at 1, 4 and 16 shadow rays per light and hit, the same pixel samples.
fn samples_per_light(out: &Path, q: &RenderQuality) -> anyhow::Result<()> {
    let scene = Builtin::Large.build(DEFAULT_MAX_DEPTH, 1.0);
    let spp = (q.spp / 4).max(1);
    let cells: Vec<(String, Image)> = [1u32, 4, 16]
        .iter()
        .map(|&n| {
            (
                format!("{spp} spp x {n} shadow ray(s) per light"),
                render(
                    &scene,
                    LightOptions::with_samples(n),
                    (q.width, q.height),
                    spp,
                    0,
                ),
            )
        })
        .collect();
    comparison_grid(&out.join("samples_per_light.png"), &cells, 3, 1)?;
    Ok(())
}

/// Where the sphere light of [`sphere_light_scene`] is.
const SPHERE_LIGHT_CENTRE: Vec3 = Vec3::new(0.3, 3.0, 0.3);

/// The radius of the sphere light in the figure of the two strategies.
const STRATEGIES_SPHERE_RADIUS: f32 = 0.3;

/// A floor with two balls under a small sphere light 3 above it.
fn sphere_light_scene(radius: f32) -> MotionScene {
    let light = Sphere::new(SPHERE_LIGHT_CENTRE, radius);
    Builder::new()
        .shape(floor(6.0), matte(Vec3::splat(0.7)))
        .shape(
            Shape::Sphere(Sphere::new(Vec3::new(-0.6, 0.5, 0.0), 0.5)),
            matte(Vec3::new(0.8, 0.3, 0.2)),
        )
        .shape(
            Shape::Sphere(Sphere::new(Vec3::new(0.8, 0.35, 0.6), 0.35)),
            matte(Vec3::new(0.2, 0.4, 0.8)),
        )
        .area_light(Shape::Sphere(light), Vec3::splat(10.0 / light.area()))
        .build(
            camera(Vec3::new(0.0, 1.8, 5.0), Vec3::new(0.0, 0.4, 0.0), 45.0),
            DEFAULT_MAX_DEPTH,
        )
}

/// Area against solid-angle sampling of a sphere light, same samples.
fn sphere_strategies(out: &Path, q: &RenderQuality) -> anyhow::Result<()> {
    let scene = sphere_light_scene(STRATEGIES_SPHERE_RADIUS);
    let spp = (q.spp / 2).max(1);
    let cells: Vec<(String, Image)> = [Strategy::Area, Strategy::SolidAngle]
        .iter()
        .map(|&strategy| {
            (
                format!("sphere light sampled by {} ({spp} spp)", strategy.name()),
                render(
                    &scene,
                    LightOptions::default().with_strategy(strategy),
                    (q.width, q.height),
                    spp,
                    0,
                ),
            )
        })
        .collect();
    comparison_grid(&out.join("sphere_strategies.png"), &cells, 2, 1)?;
    Ok(())
}

/// A disc light of radius 1 only 1.4 above a floor with a ball and a block: close enough that
/// the middle of the light and its rim light the floor very differently.
fn disc_light_scene() -> MotionScene {
    let disc = Disc::new(Vec3::new(0.0, 1.4, 0.0), -Vec3::Y, 1.0);
    Builder::new()
        .shape(floor(6.0), matte(Vec3::splat(0.7)))
        .shape(
            Shape::Sphere(Sphere::new(Vec3::new(-0.5, 0.35, 0.3), 0.35)),
            matte(Vec3::new(0.8, 0.3, 0.2)),
        )
        .block(
            Vec3::new(0.3, 0.0, -0.5),
            Vec3::new(0.9, 0.5, 0.1),
            matte(Vec3::new(0.2, 0.4, 0.8)),
        )
        .area_light(Shape::Disc(disc), Vec3::splat(1.5))
        .build(
            camera(Vec3::new(0.0, 1.6, 4.5), Vec3::new(0.0, 0.3, 0.0), 45.0),
            DEFAULT_MAX_DEPTH,
        )
}

/// The three disc warps on a close disc light against a reference, with the error of each:
/// the naive warp's comes from its bias and does not fall with more samples.
fn disc_warps(out: &Path, q: &RenderQuality) -> anyhow::Result<()> {
    let scene = disc_light_scene();
    let size = (q.width / 2, q.height / 2);
    let reference = render(
        &scene,
        LightOptions::with_samples(16),
        size,
        q.reference_spp,
        99,
    );
    let reference_mean = mean(&reference);
    let mut table = String::from(
        "| disc warp | spp | RMSE | relative RMSE | mean brightness against the reference |\n|---|---:|---:|---:|---:|\n",
    );
    let mut csv = String::from("warp,spp,rmse,relative_rmse,mean_ratio\n");
    let mut cells = vec![("reference".to_string(), reference.clone())];
    for warp in DiscWarp::ALL {
        for spp in [q.spp, 4 * q.spp] {
            let image = render(
                &scene,
                LightOptions::with_samples(4).with_disc_warp(warp),
                size,
                spp,
                0,
            );
            let error = rmse(&image, &reference);
            let relative = error / reference_mean.y;
            let ratio = mean(&image).y / reference_mean.y;
            table.push_str(&format!(
                "| {} | {spp} | {error:.4} | {relative:.3} | {ratio:.3} |\n",
                warp.name()
            ));
            csv.push_str(&format!(
                "{},{spp},{error},{relative},{ratio}\n",
                warp.name()
            ));
            if spp == 4 * q.spp {
                cells.push((format!("{} disc warp", warp.name()), image));
            }
        }
    }
    write_text(&out.join("disc_warps.md"), &table)?;
    write_text(&out.join("disc_warps.csv"), &csv)?;
    comparison_grid(&out.join("disc_warps.png"), &cells, 4, 2)?;
    Ok(())
}

/// 256 points on each light shape, in the light's own plane (the sphere: its points seen from
/// a receiver below, projected on the plane across the view).
fn light_points(out: &Path) -> anyhow::Result<()> {
    let mut sampler = IndependentSampler::new(7);
    sampler.start_pixel_sample(UVec2::ZERO, 0);
    let n = 256;
    let stratified = crate::light_samples(n, true, &mut SampleStream(&mut sampler));
    let independent = crate::light_samples(n, false, &mut SampleStream(&mut sampler));
    let quad = Parallelogram::new(
        Vec3::new(-0.9, 0.0, -0.6),
        Vec3::new(1.8, 0.0, 0.0),
        Vec3::new(0.6, 0.0, 1.2),
    );
    let triangle = Triangle::new(
        Vec3::new(-0.9, 0.0, -0.8),
        Vec3::new(0.0, 0.0, 0.9),
        Vec3::new(0.9, 0.0, -0.8),
    );
    let disc = Disc::new(Vec3::ZERO, Vec3::Y, 0.95);
    let sphere = Sphere::new(Vec3::new(0.0, 3.0, 0.0), 0.95);
    // Planar lights from above (x, z); the sphere from the side (x, y - 3), the receiver
    // at the origin below it.
    let on = |shape: crate::LightShape, u: &[Vec2], sampling: crate::LightSampling| -> Vec<Vec2> {
        let light = crate::AreaLight::new(shape, Vec3::ONE);
        let side_view = matches!(shape, crate::LightShape::Sphere(_));
        u.iter()
            .filter_map(|&u| light.sample(Vec3::ZERO, u, sampling))
            .map(|s| {
                if side_view {
                    Vec2::new(s.p.x, s.p.y - 3.0)
                } else {
                    Vec2::new(s.p.x, s.p.z)
                }
            })
            .collect()
    };
    let area = |warp| crate::LightSampling::area(warp);
    let sets = vec![
        (
            "parallelogram, stratified".to_string(),
            on(quad.into(), &stratified, area(DiscWarp::Concentric)),
        ),
        (
            "parallelogram, independent".to_string(),
            on(quad.into(), &independent, area(DiscWarp::Concentric)),
        ),
        (
            "triangle, stratified".to_string(),
            on(triangle.into(), &stratified, area(DiscWarp::Concentric)),
        ),
        (
            "disc, concentric".to_string(),
            on(disc.into(), &stratified, area(DiscWarp::Concentric)),
        ),
        (
            "disc, polar r = R sqrt(u)".to_string(),
            on(disc.into(), &stratified, area(DiscWarp::Polar)),
        ),
        (
            "disc, naive r = R u: crowds the centre".to_string(),
            on(disc.into(), &stratified, area(DiscWarp::Naive)),
        ),
        (
            "sphere by area, seen from the side".to_string(),
            on(sphere.into(), &stratified, area(DiscWarp::Concentric)),
        ),
        (
            "sphere by solid angle: its near side only".to_string(),
            on(
                sphere.into(),
                &stratified,
                crate::LightSampling::solid_angle(),
            ),
        ),
    ];
    scatter_plot(
        &out.join("light_points.png"),
        "256 points on each light (stratified u unless named)",
        &sets,
        [Vec2::splat(-1.0), Vec2::splat(1.0)],
    )?;
    Ok(())
}

/// Error against time on the large light's penumbrae (independent and stratified shadow
/// rays, 1, 4 and 16 per light) and on the sphere light (area and solid angle).
fn convergence(out: &Path, q: &RenderQuality) -> anyhow::Result<()> {
    let size = (q.width / 2, q.height / 2);
    let large = Builtin::Large.build(DEFAULT_MAX_DEPTH, 1.0);
    let reference = render(
        &large,
        LightOptions::with_samples(16),
        size,
        q.reference_spp,
        1_000,
    );
    let technique = |name: String, lights: LightOptions| {
        let scene = &large;
        Technique::new(name, move |spp| render(scene, lights, size, spp, 0))
    };
    let mut techniques = Vec::new();
    for n in [1u32, 4, 16] {
        for strata in [LightStrata::Independent, LightStrata::Stratified] {
            if n == 1 && strata == LightStrata::Stratified {
                continue; // one point has nothing to stratify
            }
            techniques.push(technique(
                format!("{n} {} ray(s) per light", strata.name()),
                LightOptions::with_samples(n).with_strata(strata),
            ));
        }
    }
    let records = run_convergence(&techniques, q.budgets, &reference);
    write_convergence_csv(&out.join("convergence_shadow_rays.csv"), &records)?;
    let one = "1 independent ray(s) per light";
    write_text(
        &out.join("shadow_rays.md"),
        &format!(
            "In this run, {} {}\n",
            equal_time_sentence(&records, one, "16 stratified ray(s) per light"),
            equal_time_sentence(&records, one, "16 independent ray(s) per light")
        ),
    )?;
    plot_error_vs_time(
        &out.join("convergence_shadow_rays.png"),
        "Error against time: shadow rays per light (large light)",
        &records,
    )?;
    plot_error_vs_spp(
        &out.join("convergence_shadow_rays_spp.png"),
        "Error against samples per pixel: shadow rays per light (large light)",
        &records,
    )?;

    let sphere = sphere_light_scene(0.15);
    let reference = render(
        &sphere,
        LightOptions::with_samples(4),
        size,
        q.reference_spp,
        1_000,
    );
    let techniques: Vec<Technique> = [Strategy::Area, Strategy::SolidAngle]
        .iter()
        .map(|&strategy| {
            let scene = &sphere;
            Technique::new(format!("sphere by {}", strategy.name()), move |spp| {
                render(
                    scene,
                    LightOptions::default().with_strategy(strategy),
                    size,
                    spp,
                    0,
                )
            })
        })
        .collect();
    let records = run_convergence(&techniques, q.budgets, &reference);
    write_convergence_csv(&out.join("convergence_sphere.csv"), &records)?;
    write_text(
        &out.join("sphere_convergence.md"),
        &format!(
            "In this run, {}\n",
            equal_spp_sentence(&records, "sphere by area", "sphere by solid-angle")
        ),
    )?;
    plot_error_vs_time(
        &out.join("convergence_sphere.png"),
        "Error against time: a small sphere light by area and by solid angle",
        &records,
    )?;
    Ok(())
}

/// The record of `technique` whose render time is closest to `seconds`.
fn nearest_in_time<'a>(
    records: &'a [ConvergenceRecord],
    technique: &str,
    seconds: f64,
) -> Option<&'a ConvergenceRecord> {
    records
        .iter()
        .filter(|r| r.technique == technique)
        .min_by(|a, b| {
            let gap = |r: &ConvergenceRecord| (r.seconds.ln() - seconds.ln()).abs();
            gap(a).total_cmp(&gap(b))
        })
}

/// "`b` at K spp reaches an RMSE of E_b in T_b, against E_a for `a` at M spp in T_a: F times
/// the error (lower/higher)", for `a` at its largest budget and the `b` render closest to it
/// in time.
fn equal_time_sentence(records: &[ConvergenceRecord], a: &str, b: &str) -> String {
    let Some(ra) = records
        .iter()
        .filter(|r| r.technique == a)
        .max_by_key(|r| r.spp)
    else {
        return format!("no render of {a} was measured.");
    };
    let Some(rb) = nearest_in_time(records, b, ra.seconds) else {
        return format!("no render of {b} was measured.");
    };
    let word = if rb.rmse < ra.rmse { "lower" } else { "higher" };
    let (a, b) = (spoken(a), spoken(b));
    format!(
        "{b} at {} spp reach an RMSE of {:.4} in {:.0} ms, against {:.4} for {a} at {} spp in \
         {:.0} ms: {:.2} times the error, {word}.",
        rb.spp,
        rb.rmse,
        1e3 * rb.seconds,
        ra.rmse,
        ra.spp,
        1e3 * ra.seconds,
        rb.rmse / ra.rmse,
    )
}

/// The two strategies at the largest sample count: their errors, times and ratios.
fn equal_spp_sentence(records: &[ConvergenceRecord], a: &str, b: &str) -> String {
    let last = |name: &str| {
        records
            .iter()
            .filter(|r| r.technique == name)
            .max_by_key(|r| r.spp)
    };
    let (Some(ra), Some(rb)) = (last(a), last(b)) else {
        return "no render was measured.".to_string();
    };
    let word = if rb.rmse < ra.rmse { "lower" } else { "higher" };
    format!(
        "at {} spp sampling by area reaches an RMSE of {:.5} in {:.0} ms and sampling by solid \
         angle {:.5} in {:.0} ms: {:.3} times the error ({word}) for {:.2} times the time.",
        ra.spp,
        ra.rmse,
        1e3 * ra.seconds,
        rb.rmse,
        1e3 * rb.seconds,
        rb.rmse / ra.rmse,
        rb.seconds / ra.seconds,
    )
}

/// A technique's name as words: "16 stratified rays per light", "1 independent ray per light".
fn spoken(technique: &str) -> String {
    if technique.starts_with("1 ") {
        technique.replace("ray(s)", "ray")
    } else {
        technique.replace("ray(s)", "rays")
    }
}

/// Mean and standard error of the mean of `terms`.
fn mean_and_error(terms: &[f64]) -> (f64, f64) {
    let n = terms.len() as f64;
    let mean = terms.iter().sum::<f64>() / n;
    let variance = terms.iter().map(|t| (t - mean).powi(2)).sum::<f64>() / (n - 1.0);
    (mean, (variance / n).sqrt())
}

/// `n` points of `[0, 1)^2`, independent, from the workbook's own sampler.
fn uniform_points(n: usize, seed: u64) -> Vec<Vec2> {
    let mut sampler = IndependentSampler::new(seed);
    sampler.start_pixel_sample(UVec2::ZERO, 0);
    (0..n).map(|_| sampler.get_2d()).collect()
}

/// The numbers the page quotes that are no image: the naive disc warp's bias at one receiver,
/// what stratifying 16 shadow rays does to a penumbra's variance, and how much of a sphere
/// light sampling by area wastes. Each is written as a sentence that holds whatever the
/// numbers come out as.
fn measurements(out: &Path, level: Level) -> anyhow::Result<()> {
    let n = level.pick(20_000, 400_000);

    // The naive disc: a receiver 0.3 under the centre of a disc light of radius 0.6.
    let (radius, height) = (0.6f32, 0.3f32);
    let disc = Disc::new(Vec3::new(0.0, height, 0.0), -Vec3::Y, radius);
    let light = AreaLight::new(disc, Vec3::ONE);
    let exact = f64::from(disc_on_axis_irradiance(Vec3::ONE, radius, height).x);
    let points = uniform_points(n, 5);
    let mut text = format!(
        "A receiver {height} under the centre of a disc light of radius {radius} and radiance 1 \
         receives exactly $\\pi R^2/(h^2+R^2) = {exact:.4}$. With {n} shadow rays, each warp \
         estimates:\n\n| disc warp | estimate | against the exact value | standard errors off |\n\
         |---|---:|---:|---:|\n"
    );
    for warp in DiscWarp::ALL {
        let terms: Vec<f64> = points
            .iter()
            .map(|&u| {
                f64::from(
                    light_sample_contribution(
                        Vec3::ZERO,
                        Vec3::Y,
                        &light,
                        u,
                        LightSampling::area(warp),
                        &mut |_| true,
                    )
                    .x,
                )
            })
            .collect();
        let (estimate, error) = mean_and_error(&terms);
        text.push_str(&format!(
            "| {} | {estimate:.4} | {:.3} times | {:.1} |\n",
            warp.name(),
            estimate / exact,
            (estimate - exact).abs() / error
        ));
    }
    write_text(&out.join("naive_disc.md"), &text)?;

    // A penumbra: a floor point that sees only the part x < 0.37 of a unit panel 1 above it.
    let panel = AreaLight::new(
        Parallelogram::new(Vec3::new(-0.2, 1.0, -0.7), Vec3::X, Vec3::Z),
        Vec3::ONE,
    );
    let estimates = level.pick(400, 4000);
    let variance_of_16 = |stratified: bool| -> f64 {
        let mut sampler = IndependentSampler::new(7);
        let values: Vec<f64> = (0..estimates)
            .map(|i| {
                sampler.start_pixel_sample(UVec2::ZERO, i as u64);
                let u = light_samples(16, stratified, &mut SampleStream(&mut sampler));
                f64::from(
                    crate::estimator::estimate_irradiance(
                        Vec3::ZERO,
                        Vec3::Y,
                        &panel,
                        &u,
                        LightSampling::area(DiscWarp::Concentric),
                        |s| s.p.x < 0.37,
                    )
                    .x,
                )
            })
            .collect();
        let (_, error) = mean_and_error(&values);
        error * error * values.len() as f64
    };
    let (independent, stratified) = (variance_of_16(false), variance_of_16(true));
    let ratio = stratified / independent;
    let word = if ratio < 1.0 { "less" } else { "more" };
    write_text(
        &out.join("penumbra_strata.md"),
        &format!(
            "At a floor point that sees a part of a panel light, over {estimates} estimates of \
             16 shadow rays each, the stratified rays' estimate has {ratio:.3} times the \
             variance of the independent rays' ({word}).\n"
        ),
    )?;

    // A sphere light by area: how many of its points face away from the receiver.
    let (sphere_radius, centre) = (STRATEGIES_SPHERE_RADIUS, SPHERE_LIGHT_CENTRE);
    let sphere = AreaLight::new(Sphere::new(centre, sphere_radius), Vec3::ONE);
    let d = centre.length();
    let away = points
        .iter()
        .filter_map(|&u| sphere.sample(Vec3::ZERO, u, LightSampling::area(DiscWarp::Concentric)))
        .filter(|s| s.n.dot(-s.p) <= 0.0)
        .count();
    let visible = 0.5 * (1.0 - sphere_radius / d);
    write_text(
        &out.join("sphere_cap.md"),
        &format!(
            "For the sphere light of the two renders above (radius {sphere_radius}, its centre \
             {d:.2} from the floor's point at the origin), the visible cap is $(1 - R/d)/2 = {visible:.3}$ of \
             its area. Of {n} points drawn by area, {:.3} faced away from the receiver (the \
             formula says {:.3}): those shadow rays are spent on light that cannot arrive.\n",
            away as f64 / points.len() as f64,
            1.0 - visible
        ),
    )?;
    Ok(())
}
