//! Snapshot tests: tiny fixed renders whose summaries are compared with the stored ones.
//!
//! The summary (`workbench::test_support::image_summary`) is a 10-level luminance picture plus
//! the mean colour and the ray count: it catches a reflection that moved, a blur that is
//! missing or too wide, glass that lost its refraction, and a change in how many rays a
//! strategy traces. Seeds are fixed; the summary is compared up to
//! floating-point noise (`workbench::assert_close_snapshot!`).

mod support;

use ch06_fuzzy_reflections::scenes::{Builtin, DEFAULT_MAX_DEPTH};
use ch06_fuzzy_reflections::{BelowSurface, FuzzMethod, GlassStrategy, TraceOptions};
use support::render;
use workbench::test_support::image_summary;

fn snapshot_of(builtin: Builtin, exponent: f32, options: TraceOptions) -> String {
    let scene = builtin.build(DEFAULT_MAX_DEPTH, exponent);
    let out = render(&scene, options, 48, 36, 16, 0);
    assert_eq!(out.stats.nonfinite_samples, 0);
    image_summary(&out.image, out.stats.rays)
}

#[test]
fn floor_glossy_lobe() {
    workbench::assert_close_snapshot!(
        "floor_glossy_lobe",
        snapshot_of(Builtin::Floor, 100.0, TraceOptions::default())
    );
}

#[test]
fn floor_glossy_empirical_disc() {
    let options = TraceOptions {
        fuzz: FuzzMethod::Disc,
        ..TraceOptions::default()
    };
    workbench::assert_close_snapshot!(
        "floor_glossy_empirical_disc",
        snapshot_of(Builtin::Floor, 100.0, options)
    );
}

#[test]
fn frosted_pane() {
    workbench::assert_close_snapshot!(
        "frosted_pane",
        snapshot_of(Builtin::Frosted, 10.0, TraceOptions::default())
    );
}

#[test]
fn plates_reflecting_each_other_stray_rays_reflected() {
    let options = TraceOptions {
        below: BelowSurface::Reflect,
        ..TraceOptions::default()
    };
    workbench::assert_close_snapshot!(
        "plates_reflecting_each_other_stray_rays_reflected",
        snapshot_of(Builtin::Plates, 1000.0, options)
    );
}

#[test]
fn panes_traced_both_ways() {
    let options = TraceOptions {
        glass: GlassStrategy::Both,
        ..TraceOptions::default()
    };
    workbench::assert_close_snapshot!(
        "panes_traced_both_ways",
        snapshot_of(Builtin::Panes, 1e6, options)
    );
}

#[test]
fn panes_one_ray_with_probability_one_half() {
    let options = TraceOptions {
        glass: GlassStrategy::Half,
        ..TraceOptions::default()
    };
    workbench::assert_close_snapshot!(
        "panes_one_ray_with_probability_one_half",
        snapshot_of(Builtin::Panes, 1e6, options)
    );
}
