//! The microfacet figures are drawn: the `cos^n` lobe against GGX and Beckmann, the white
//! furnace, and the visible normals' histogram beside their density. Set `MICROFACET_FIGURES=DIR` to keep them in `DIR` and look at them.

use ch09_materials::lab::microfacet_figures as figures;
use common::scene::MicrofacetDistribution;
use std::path::PathBuf;

#[test]
fn the_lobe_and_furnace_figures_are_written() {
    let temporary = tempfile::tempdir().expect("a temporary directory");
    let dir = std::env::var_os("MICROFACET_FIGURES")
        .map(PathBuf::from)
        .unwrap_or_else(|| temporary.path().to_path_buf());
    std::fs::create_dir_all(&dir).expect("the figures' directory");
    let lobes = dir.join("microfacet-lobes.png");
    let furnace = dir.join("microfacet-furnace.png");
    figures::lobes(&lobes, &[0.1, 0.4], 40.0).expect("the lobes figure");
    let alphas = [0.1, 0.5, 1.0];
    let curves = figures::furnace(&furnace, &[0.0, 85.0], &alphas).expect("the furnace figure");
    let table = figures::furnace_markdown(&curves, &alphas);
    assert_eq!(table.lines().count(), 2 + 4, "{table}");
    let visible = dir.join("microfacet-visible-normals.png");
    figures::visible_normals(&visible, MicrofacetDistribution::Ggx, 0.5, 60.0, 200_000)
        .expect("the visible normals figure");
    for path in [lobes, furnace, visible] {
        let size = std::fs::metadata(&path).map(|m| m.len()).unwrap_or(0);
        assert!(size > 10_000, "{} is {size} bytes", path.display());
    }
}
