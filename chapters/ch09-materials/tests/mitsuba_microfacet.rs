//! The microfacet BSDFs evaluate to what Mitsuba 3 evaluates them to: `f cos θ` and the
//! density, on a grid of direction pairs, for `roughconductor`, `roughdielectric` and
//! `roughplastic` with both distributions. And Mitsuba's sampling delivers, on average, the
//! albedo that our `eval` integrates to (by quadrature over the facets): its choices, weights
//! and radiance scaling are the ones our `eval` describes. Needs a Python with the `mitsuba` package, so it is
//! ignored by default. Run it with
//!
//! ```text
//! MITSUBA_PYTHON=/path/to/python cargo test -p ch09-materials --test mitsuba_microfacet -- --ignored --nocapture
//! ```
//!
//! `tests/mitsuba_microfacet.py` asks Mitsuba (the `scalar_rgb` variant) for its values.

use ch09_materials::microfacet::coating::Coating;
use ch09_materials::microfacet::{
    LocalBsdf, NormalDistribution, RoughConductor, RoughDielectric, RoughPlastic,
    RoughPlasticParameters, albedo,
};
use common::scene::MicrofacetDistribution::{self, Beckmann, Ggx};
use glam::Vec3;
use serde_json::{Value, json};
use std::io::Write;
use std::process::{Command, Stdio};

/// How far a value may be from Mitsuba's, relatively, above the floor [`FLOOR`]. Both compute
/// in single precision with the same formulas; the plastic's coating table is summed in double
/// precision here.
const TOLERANCE: f64 = 1e-3;
/// Below this, values are compared absolutely (a grazing `f cos θ` of `10⁻⁹` has no digits
/// that matter).
const FLOOR: f64 = 1e-4;

/// One BSDF on both sides: ours, and Mitsuba's dictionary for it.
struct Case {
    name: String,
    ours: Box<dyn LocalBsdf>,
    theirs: Value,
    /// Whether directions below the surface count (glass).
    both_sides: bool,
    /// The roughness, where the albedo's quadrature puts its nodes.
    alpha: f32,
    /// `int_ior / ext_ior` for glass, whose albedo includes refraction.
    eta: Option<f32>,
}

fn name(kind: MicrofacetDistribution) -> &'static str {
    match kind {
        Beckmann => "beckmann",
        Ggx => "ggx",
    }
}

fn rgb(v: Vec3) -> Value {
    json!({"type": "rgb", "value": [v.x, v.y, v.z]})
}

fn cases() -> Vec<Case> {
    let mut cases = Vec::new();
    let (eta, k) = (Vec3::new(0.2, 0.92, 1.1), Vec3::new(3.9, 2.45, 2.14));
    for kind in [Beckmann, Ggx] {
        for (au, av) in [(0.05f32, 0.05f32), (0.3, 0.3), (0.1, 0.4)] {
            let ours = RoughConductor {
                distribution: NormalDistribution::new(kind, au, av),
                eta,
                k,
                specular_reflectance: Vec3::ONE,
            };
            let theirs = json!({"type": "roughconductor", "distribution": name(kind),
                "alpha_u": au, "alpha_v": av, "eta": rgb(eta), "k": rgb(k)});
            cases.push(Case {
                name: format!("roughconductor {} {au}/{av}", name(kind)),
                ours: Box::new(ours),
                theirs,
                both_sides: false,
                alpha: au.max(av),
                eta: None,
            });
        }
        for alpha in [0.1f32, 0.5] {
            let ours = RoughDielectric::new(NormalDistribution::isotropic(kind, alpha), 1.5, 1.0);
            let theirs = json!({"type": "roughdielectric", "distribution": name(kind),
                "alpha": alpha, "int_ior": 1.5, "ext_ior": 1.0});
            cases.push(Case {
                name: format!("roughdielectric {} {alpha}", name(kind)),
                ours: Box::new(ours),
                theirs,
                both_sides: true,
                alpha,
                eta: Some(1.5),
            });
            let diffuse = Vec3::new(0.2, 0.5, 0.8);
            let parameters = RoughPlasticParameters {
                kind,
                alpha,
                eta: 1.49,
                diffuse_reflectance: diffuse,
                specular_reflectance: Vec3::ONE,
                nonlinear: false,
            };
            // Kept to the end of the test process: a case outlives the function that makes it.
            let coating: &'static Coating = Box::leak(Box::new(parameters.coating()));
            let ours = RoughPlastic::new(parameters, coating);
            let theirs = json!({"type": "roughplastic", "distribution": name(kind),
                "alpha": alpha, "int_ior": 1.49, "ext_ior": 1.0,
                "diffuse_reflectance": rgb(diffuse)});
            cases.push(Case {
                name: format!("roughplastic {} {alpha}", name(kind)),
                ours: Box::new(ours),
                theirs,
                both_sides: false,
                alpha,
                eta: None,
            });
        }
    }
    // Mitsuba's optional factors and the plastic's `nonlinear`.
    let tint = Vec3::new(0.9, 0.6, 0.3);
    let ours = RoughConductor {
        distribution: NormalDistribution::isotropic(Ggx, 0.2),
        eta,
        k,
        specular_reflectance: tint,
    };
    cases.push(Case {
        name: "roughconductor ggx 0.2, specular_reflectance".into(),
        ours: Box::new(ours),
        theirs: json!({"type": "roughconductor", "distribution": "ggx", "alpha": 0.2,
            "eta": rgb(eta), "k": rgb(k), "specular_reflectance": rgb(tint)}),
        both_sides: false,
        alpha: 0.2,
        eta: None,
    });
    let ours = RoughDielectric {
        specular_reflectance: tint,
        specular_transmittance: Vec3::ONE - tint * 0.5,
        ..RoughDielectric::new(NormalDistribution::isotropic(Ggx, 0.2), 1.33, 1.0)
    };
    cases.push(Case {
        name: "roughdielectric ggx 0.2, specular factors".into(),
        ours: Box::new(ours),
        theirs: json!({"type": "roughdielectric", "distribution": "ggx", "alpha": 0.2,
            "int_ior": 1.33, "ext_ior": 1.0, "specular_reflectance": rgb(tint),
            "specular_transmittance": rgb(Vec3::ONE - tint * 0.5)}),
        both_sides: true,
        alpha: 0.2,
        eta: Some(1.33),
    });
    let diffuse = Vec3::new(0.9, 0.4, 0.1);
    let parameters = RoughPlasticParameters {
        kind: Ggx,
        alpha: 0.2,
        eta: 1.6,
        diffuse_reflectance: diffuse,
        specular_reflectance: tint,
        nonlinear: true,
    };
    // Kept to the end of the test process: a case outlives the function that makes it.
    let coating: &'static Coating = Box::leak(Box::new(parameters.coating()));
    let ours = RoughPlastic::new(parameters, coating);
    cases.push(Case {
        name: "roughplastic ggx 0.2, nonlinear, specular_reflectance".into(),
        ours: Box::new(ours),
        theirs: json!({"type": "roughplastic", "distribution": "ggx", "alpha": 0.2,
            "int_ior": 1.6, "ext_ior": 1.0, "diffuse_reflectance": rgb(diffuse),
            "specular_reflectance": rgb(tint), "nonlinear": true}),
        both_sides: false,
        alpha: 0.2,
        eta: None,
    });
    cases
}

fn direction(theta: f32, phi: f32) -> Vec3 {
    let (sin, cos) = theta.to_radians().sin_cos();
    let (sin_phi, cos_phi) = phi.to_radians().sin_cos();
    Vec3::new(sin * cos_phi, sin * sin_phi, cos)
}

/// `wo` at five angles, `wi` over a grid of the hemisphere (both, for glass, and `wo` from
/// below too).
fn pairs(both_sides: bool) -> Vec<(Vec3, Vec3)> {
    let mut pairs = Vec::new();
    let sides: &[f32] = if both_sides { &[1.0, -1.0] } else { &[1.0] };
    for &so in sides {
        for theta_o in [0.0, 30.0, 60.0, 80.0, 89.0] {
            let wo = direction(theta_o, 0.0) * Vec3::new(1.0, 1.0, so);
            for &si in sides {
                for theta_i in [0.0, 10.0, 25.0, 40.0, 55.0, 70.0, 85.0] {
                    for phi in [0.0, 60.0, 150.0, 180.0] {
                        let wi = direction(theta_i, phi) * Vec3::new(1.0, 1.0, si);
                        pairs.push((wo, wi));
                    }
                }
            }
        }
    }
    pairs
}

/// Samples per direction of Mitsuba's albedo estimate.
const ALBEDO_SAMPLES: usize = 10_000;

/// The directions the albedo is estimated from.
fn albedo_from(both_sides: bool) -> Vec<Vec3> {
    let above = [
        direction(0.0, 0.0),
        direction(60.0, 0.0),
        direction(85.0, 0.0),
    ];
    let below = above.map(|w| -w);
    if both_sides {
        above.into_iter().chain(below).collect()
    } else {
        above.to_vec()
    }
}

/// Mitsuba's answer for one case.
struct Answer {
    values: Vec<[f64; 4]>,
    /// Per direction: the mean weight and its standard error, per channel.
    albedo: Vec<[f64; 6]>,
}

fn mitsuba_values(python: &str, request: &Value) -> Vec<Answer> {
    let script = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/mitsuba_microfacet.py");
    let mut child = Command::new(python)
        .arg(script)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .unwrap_or_else(|e| panic!("cannot run {python}: {e}"));
    child
        .stdin
        .take()
        .expect("stdin is piped")
        .write_all(request.to_string().as_bytes())
        .expect("the script reads its cases");
    let output = child.wait_with_output().expect("the script finishes");
    assert!(output.status.success(), "{script} failed");
    let answers: Value = serde_json::from_slice(&output.stdout).expect("the script writes JSON");
    let numbers = |row: &Value| -> Vec<f64> {
        row.as_array()
            .expect("a row of numbers")
            .iter()
            .map(|x| x.as_f64().expect("a number"))
            .collect()
    };
    let rows = |value: &Value| -> Vec<Vec<f64>> {
        value
            .as_array()
            .expect("a list of rows")
            .iter()
            .map(numbers)
            .collect()
    };
    answers
        .as_array()
        .expect("one answer per case")
        .iter()
        .map(|answer| Answer {
            values: rows(&answer["values"])
                .into_iter()
                .map(|r| r.try_into().expect("r, g, b, pdf"))
                .collect(),
            albedo: rows(&answer["albedo"])
                .into_iter()
                .map(|r| r.try_into().expect("means and errors"))
                .collect(),
        })
        .collect()
}

/// `∫ f cos θ_i dω_i` of our `eval` by quadrature over the facets.
fn ours_albedo(case: &Case, wo: Vec3) -> [f64; 3] {
    let eval = |wi| case.ours.eval(wo, wi);
    let mut total = albedo::reflected(wo, case.alpha, eval);
    if let Some(eta) = case.eta {
        total += albedo::refracted(wo, case.alpha, eta, eval);
    }
    total.to_array()
}

#[test]
#[ignore = "needs Mitsuba 3 (set MITSUBA_PYTHON)"]
fn microfacet_bsdfs_evaluate_as_mitsuba_does() {
    let Ok(python) = std::env::var("MITSUBA_PYTHON") else {
        panic!("set MITSUBA_PYTHON to a Python with the mitsuba package");
    };
    let cases = cases();
    let request: Vec<Value> = cases
        .iter()
        .map(|c| {
            let pairs: Vec<Value> = pairs(c.both_sides)
                .iter()
                .map(|(wo, wi)| json!([[wo.x, wo.y, wo.z], [wi.x, wi.y, wi.z]]))
                .collect();
            let from: Vec<Value> = albedo_from(c.both_sides)
                .iter()
                .map(|w| json!([w.x, w.y, w.z]))
                .collect();
            json!({"bsdf": c.theirs, "pairs": pairs, "albedo_from": from,
                "samples": ALBEDO_SAMPLES})
        })
        .collect();
    let theirs = mitsuba_values(&python, &Value::Array(request));
    let mut failures = Vec::new();
    for (case, answer) in cases.iter().zip(&theirs) {
        let mut worst = (0.0f64, String::new());
        for ((wo, wi), theirs) in pairs(case.both_sides).iter().zip(&answer.values) {
            let f = case.ours.eval(*wo, *wi);
            let ours = [f.x, f.y, f.z, case.ours.pdf(*wo, *wi)].map(f64::from);
            for (a, b) in ours.iter().zip(theirs) {
                let difference = (a - b).abs() / b.abs().max(FLOOR);
                if difference > worst.0 {
                    worst = (
                        difference,
                        format!("{wo} -> {wi}: ours {ours:?}, Mitsuba {theirs:?}"),
                    );
                }
            }
        }
        eprintln!(
            "{}: largest relative difference {:.2e} at {}",
            case.name, worst.0, worst.1
        );
        if worst.0 > TOLERANCE {
            failures.push(format!("{}: {:.2e} at {}", case.name, worst.0, worst.1));
        }
        for (wo, theirs) in albedo_from(case.both_sides).iter().zip(&answer.albedo) {
            let ours = ours_albedo(case, *wo);
            for c in 0..3 {
                // Five standard errors, and Beckmann's approximate `G1` (0.35 %), which
                // Mitsuba's weights use but its exact visible-normal sampler does not.
                let allowed = 5.0 * theirs[3 + c] + 4e-3 * ours[c] + 1e-4;
                let off = (ours[c] - theirs[c]).abs();
                eprintln!(
                    "  albedo from {wo}: ours {:.4}, Mitsuba {:.4} ± {:.4}",
                    ours[c],
                    theirs[c],
                    theirs[3 + c]
                );
                if off > allowed {
                    failures.push(format!(
                        "{} from {wo}: albedo {:.4} but Mitsuba samples {:.4} ± {:.4}",
                        case.name,
                        ours[c],
                        theirs[c],
                        theirs[3 + c]
                    ));
                }
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
