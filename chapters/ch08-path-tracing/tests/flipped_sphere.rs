//! A sphere with `flip_normals`: its front faces the centre. Put the camera inside a flipped
//! emitting sphere and it is a dome of light: every pixel that sees the dome shows its
//! radiance, and a white-ish matte disc under it reflects `albedo × radiance` (a furnace:
//! the dome surrounds the disc's whole upper hemisphere). Both only work if hits *and* light
//! samples put the normal inside: with outward normals the dome is black from within, and
//! with an outward normal on light samples only, next-event estimation finds no light and
//! the multiple-importance weights of the BSDF samples leave the disc too dark.

mod support;
use support::render_text;

const ALBEDO: f32 = 0.5;
const RADIANCE: f32 = 2.0;

/// A disc of `ALBEDO` facing up at the origin, seen from above, inside a dome of radius 20
/// glowing `RADIANCE` (a sphere with `flip_normals`, `flip` given).
fn scene(flip: bool) -> String {
    format!(
        r#"<scene version="3.0.0">
    <integrator type="path"><integer name="max_depth" value="2"/></integrator>
    <sensor type="perspective"><float name="fov" value="50"/>
        <transform name="to_world"><lookat origin="0, 4, 3" target="0, 0, 0" up="0, 1, 0"/></transform>
        <sampler type="independent"><integer name="sample_count" value="64"/></sampler>
        <film type="hdrfilm"><integer name="width" value="32"/><integer name="height" value="24"/>
            <rfilter type="box"/></film></sensor>
    <shape type="sphere"><float name="radius" value="20"/>
        <boolean name="flip_normals" value="{flip}"/>
        <emitter type="area"><rgb name="radiance" value="{RADIANCE}"/></emitter></shape>
    <shape type="disk"><transform name="to_world"><rotate x="1" angle="-90"/></transform>
        <bsdf type="diffuse"><rgb name="reflectance" value="{ALBEDO}"/></bsdf></shape>
</scene>"#
    )
}

#[test]
fn a_flipped_emitting_sphere_is_a_dome_that_lights_what_is_inside() {
    let image = render_text(&scene(true));
    let (mut dome, mut disc) = (Vec::new(), Vec::new());
    for p in &image.pixels {
        // A pixel wholly on the dome shows its radiance exactly; the rest is (partly) disc.
        if p.y == RADIANCE {
            dome.push(p.y);
        } else {
            disc.push(p.y);
        }
    }
    assert!(
        dome.len() > image.pixels.len() / 4,
        "only {} of {} pixels show the dome's radiance {RADIANCE}: from inside, a flipped \
         sphere's front faces the camera and must glow (are hit normals turned inwards?)",
        dome.len(),
        image.pixels.len()
    );
    // Pixels wholly inside the disc: the centre of the image.
    let (w, h) = (image.width, image.height);
    let centre: Vec<f32> = (h / 2 - 2..h / 2 + 2)
        .flat_map(|y| (w / 2 - 2..w / 2 + 2).map(move |x| (x, y)))
        .map(|(x, y)| image.get(x, y).y)
        .collect();
    let n = centre.len() as f32;
    let mean = centre.iter().sum::<f32>() / n;
    let variance = centre.iter().map(|v| (v - mean).powi(2)).sum::<f32>() / (n - 1.0);
    let standard_error = (variance / n).sqrt();
    let expected = ALBEDO * RADIANCE;
    assert!(
        (mean - expected).abs() < 4.0 * standard_error + 1e-3,
        "the disc under the dome reflects {mean} ± {standard_error}, expected albedo × \
         radiance = {expected}: a light sample on a flipped sphere must carry the inward \
         normal, or next-event estimation finds the dome's back and MIS weighs the rest down"
    );
}

#[test]
fn without_flip_normals_the_dome_is_dark_from_inside() {
    let image = render_text(&scene(false));
    assert!(
        image.pixels.iter().all(|p| p.max_element() == 0.0),
        "a sphere's outside is its front: seen from inside, its one-sided light shows nothing"
    );
}
