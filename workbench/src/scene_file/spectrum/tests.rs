//! The conversion checked against Mitsuba 3.9.1's `scalar_rgb` variant, and the parser's
//! errors.
//!
//! The expected colours were printed once by Mitsuba's Python bindings: each spectrum loaded
//! in a `diffuse` BSDF's `reflectance` or an `area` emitter's `radiance` with
//! `mi.load_string`, then read with `mi.traverse` (`...reflectance.value`,
//! `...radiance.value`). They are single-precision numbers printed to nine digits.

// Mitsuba's colours are written to nine digits, as its Python bindings print them.
#![allow(clippy::excessive_precision)]

use glam::Vec3;
use proptest::prelude::*;

use super::{
    MAX_VALUE, MAX_WAVELENGTH, SampledSpectrum, Spectrum, SpectrumRole, parse_spd, parse_spectrum,
};

// The measured reflectances and light of the Cornell box (Cornell University Program of
// Computer Graphics), as Mitsuba's documentation scene `variants_cbox_rgb.xml` writes them.
const WHITE: &str = "400:0.343, 404:0.445, 408:0.551, 412:0.624, 416:0.665, 420:0.687, 424:0.708, 428:0.723, 432:0.715,
     436:0.71, 440:0.745, 444:0.758, 448:0.739, 452:0.767, 456:0.777, 460:0.765, 464:0.751, 468:0.745,
     472:0.748, 476:0.729, 480:0.745, 484:0.757, 488:0.753, 492:0.75, 496:0.746, 500:0.747, 504:0.735,
     508:0.732, 512:0.739, 516:0.734, 520:0.725, 524:0.721, 528:0.733, 532:0.725, 536:0.732, 540:0.743,
     544:0.744, 548:0.748, 552:0.728, 556:0.716, 560:0.733, 564:0.726, 568:0.713, 572:0.74, 576:0.754,
     580:0.764, 584:0.752, 588:0.736, 592:0.734, 596:0.741, 600:0.74, 604:0.732, 608:0.745, 612:0.755,
     616:0.751, 620:0.744, 624:0.731, 628:0.733, 632:0.744, 636:0.731, 640:0.712, 644:0.708, 648:0.729,
     652:0.73, 656:0.727, 660:0.707, 664:0.703, 668:0.729, 672:0.75, 676:0.76, 680:0.751, 684:0.739,
     688:0.724, 692:0.73, 696:0.74, 700:0.737";
const RED: &str = "400:0.04, 404:0.046, 408:0.048, 412:0.053, 416:0.049, 420:0.05, 424:0.053, 428:0.055, 432:0.057,
     436:0.056, 440:0.059, 444:0.057, 448:0.061, 452:0.061, 456:0.06, 460:0.062, 464:0.062, 468:0.062,
     472:0.061, 476:0.062, 480:0.06, 484:0.059, 488:0.057, 492:0.058, 496:0.058, 500:0.058, 504:0.056,
     508:0.055, 512:0.056, 516:0.059, 520:0.057, 524:0.055, 528:0.059, 532:0.059, 536:0.058, 540:0.059,
     544:0.061, 548:0.061, 552:0.063, 556:0.063, 560:0.067, 564:0.068, 568:0.072, 572:0.08, 576:0.09,
     580:0.099, 584:0.124, 588:0.154, 592:0.192, 596:0.255, 600:0.287, 604:0.349, 608:0.402, 612:0.443,
     616:0.487, 620:0.513, 624:0.558, 628:0.584, 632:0.62, 636:0.606, 640:0.609, 644:0.651, 648:0.612,
     652:0.61, 656:0.65, 660:0.638, 664:0.627, 668:0.62, 672:0.63, 676:0.628, 680:0.642, 684:0.639,
     688:0.657, 692:0.639, 696:0.635, 700:0.642";
const GREEN: &str = "400:0.092, 404:0.096, 408:0.098, 412:0.097, 416:0.098, 420:0.095, 424:0.095, 428:0.097, 432:0.095,
     436:0.094, 440:0.097, 444:0.098, 448:0.096, 452:0.101, 456:0.103, 460:0.104, 464:0.107, 468:0.109,
     472:0.112, 476:0.115, 480:0.125, 484:0.14, 488:0.16, 492:0.187, 496:0.229, 500:0.285, 504:0.343,
     508:0.39, 512:0.435, 516:0.464, 520:0.472, 524:0.476, 528:0.481, 532:0.462, 536:0.447, 540:0.441,
     544:0.426, 548:0.406, 552:0.373, 556:0.347, 560:0.337, 564:0.314, 568:0.285, 572:0.277, 576:0.266,
     580:0.25, 584:0.23, 588:0.207, 592:0.186, 596:0.171, 600:0.16, 604:0.148, 608:0.141, 612:0.136,
     616:0.13, 620:0.126, 624:0.123, 628:0.121, 632:0.122, 636:0.119, 640:0.114, 644:0.115, 648:0.117,
     652:0.117, 656:0.118, 660:0.12, 664:0.122, 668:0.128, 672:0.132, 676:0.139, 680:0.144, 684:0.146,
     688:0.15, 692:0.152, 696:0.157, 700:0.159";
const LIGHT_BSDF: &str = "400:0.78, 500:0.78, 600:0.78, 700:0.78";
const LIGHT_RADIANCE: &str = "400:0, 500:8, 600:15.6, 700:18.4";

/// Our arithmetic is Mitsuba's, in the same order and precisions, and every colour below is
/// today the same `f32` as Mitsuba's (a zero tolerance passes). The bound, far below the 1e-4
/// asked of the loader, leaves room for a fused multiply-add done or not on another machine.
const RELATIVE_TOLERANCE: f32 = 1e-6;

/// `text` in `role` converts to Mitsuba's `expected`.
#[track_caller]
fn assert_converts(text: &str, role: SpectrumRole, expected: [f32; 3]) {
    let spectrum = parse_spectrum(text).expect("a valid spectrum");
    let rgb = spectrum.to_linear_srgb(role).rgb;
    assert_close(rgb, expected);
}

#[track_caller]
fn assert_close(rgb: Vec3, expected: [f32; 3]) {
    for (channel, (&got, want)) in rgb.as_ref().iter().zip(expected).enumerate() {
        let error = (got - want).abs();
        assert!(
            error <= RELATIVE_TOLERANCE * want.abs().max(1e-3),
            "channel {channel}: got {got:e}, Mitsuba gives {want:e} (all: {rgb})"
        );
    }
}

#[test]
fn cornell_box_reflectances_match_mitsuba() {
    let white = [0.735013008, 0.735624611, 0.736264348];
    assert_converts(WHITE, SpectrumRole::Reflectance, white);
    assert_converts(
        RED,
        SpectrumRole::Reflectance,
        [0.491320044, 0.0492281057, 0.0509218983],
    );
    assert_converts(
        GREEN,
        SpectrumRole::Reflectance,
        [0.0682825372, 0.397760183, 0.0862908736],
    );
    assert_converts(
        LIGHT_BSDF,
        SpectrumRole::Reflectance,
        [0.77636677, 0.779810011, 0.77602911],
    );
}

#[test]
fn cornell_box_light_matches_mitsuba() {
    let radiance = [20.7108364, 10.8546343, 2.77115202];
    assert_converts(LIGHT_RADIANCE, SpectrumRole::Emission, radiance);
}

#[test]
fn a_flat_reflectance_over_the_whole_range_is_white() {
    // D65 weighting makes a unit reflectance white, up to the Riemann sum's error.
    let expected = [0.998985291, 0.998873711, 0.998801589];
    assert_converts("360:1, 830:1", SpectrumRole::Reflectance, expected);
    // Beyond 360–830 nm the matching functions are zero: the same colour.
    assert_converts("300:1, 900:1", SpectrumRole::Reflectance, expected);
}

#[test]
fn a_flat_spectrum_over_part_of_the_range_is_zero_outside_it() {
    let reflectance = [0.497671008, 0.499878198, 0.497454554];
    assert_converts("400:0.5 700:0.5", SpectrumRole::Reflectance, reflectance);
    assert_converts(
        "400:1, 700:1",
        SpectrumRole::Emission,
        [1.19969356, 0.94952035, 0.903443336],
    );
}

#[test]
fn an_equal_energy_emitter_is_purple_not_white() {
    let expected = [1.20488369, 0.94822818, 0.909266829];
    assert_converts("360:1, 830:1", SpectrumRole::Emission, expected);
}

#[test]
fn ramps_interpolate_linearly() {
    let reflectance = [0.804148197, 0.476455539, 0.136042044];
    assert_converts("400:0, 700:1", SpectrumRole::Reflectance, reflectance);
    let emission = [9.40306759, 4.54720545, 1.13696337];
    assert_converts("400:0, 700:10", SpectrumRole::Emission, emission);
}

#[test]
fn a_single_value_is_grey_for_a_reflectance_and_purple_for_an_emitter() {
    assert_converts("0.5", SpectrumRole::Reflectance, [0.5, 0.5, 0.5]);
    assert_converts(
        "2",
        SpectrumRole::Emission,
        [2.40958786, 1.89658201, 1.81783211],
    );
    let converted = parse_spectrum("0.5")
        .unwrap()
        .to_linear_srgb(SpectrumRole::Reflectance);
    assert_eq!(converted.clamped_from, None);
}

#[test]
fn out_of_gamut_colours_are_clamped_as_mitsuba_clamps_them() {
    // A narrow band of green: red is negative in sRGB; Mitsuba clamps it to 0 for both roles.
    let narrow = parse_spectrum("500:1, 510:1").unwrap();
    let reflectance = narrow.to_linear_srgb(SpectrumRole::Reflectance);
    assert_close(reflectance.rgb, [0.0, 0.0781108215, 0.0146231772]);
    let before = reflectance.clamped_from.expect("clamping is reported");
    assert!((before.x - -0.0729662).abs() < 1e-6, "{before}");
    let emission = narrow.to_linear_srgb(SpectrumRole::Emission);
    assert_close(emission.rgb, [0.0, 0.0712440982, 0.0133142322]);
    // A reflectance above 1 is clamped to 1; an emitter is not bounded above.
    let bright = parse_spectrum("400:3, 700:3").unwrap();
    let clamped = bright.to_linear_srgb(SpectrumRole::Reflectance);
    assert_eq!(clamped.rgb, Vec3::ONE);
    assert!(clamped.clamped_from.unwrap().min_element() > 2.98);
    let emitted = bright.to_linear_srgb(SpectrumRole::Emission);
    assert_eq!(emitted.clamped_from, None);
    assert!(emitted.rgb.min_element() > 2.0);
}

#[test]
fn spd_text_gives_the_same_colour_as_mitsuba() {
    let text = "# comment\n400 0.2\n500 0.6\n\n600 0.9\n700 0.4\n";
    let spectrum = parse_spd(text).unwrap();
    let rgb = spectrum.to_linear_srgb(SpectrumRole::Reflectance).rgb;
    assert_close(rgb, [0.85172081, 0.745245039, 0.371197373]);
    let comment_after = parse_spd("400 0.2 # start\r\n700 0.4\r\n").unwrap();
    let pairs = parse_spectrum("400:0.2, 700:0.4").unwrap();
    assert_eq!(comment_after, pairs);
}

#[test]
fn pairs_are_read_with_commas_or_whitespace() {
    let expected = SampledSpectrum::new(&[(400.0, 0.5), (550.0, 0.25), (700.0, 1.0)]).unwrap();
    for text in [
        "400:0.5, 550:0.25, 700:1",
        "400:0.5 550:0.25\n\t700:1",
        " 400:0.5,550:0.25,700:1 ",
    ] {
        assert_eq!(
            parse_spectrum(text),
            Ok(Spectrum::Sampled(expected.clone())),
            "{text:?}"
        );
    }
}

/// `text` is refused with a message containing `fragment`.
#[track_caller]
fn assert_refused(text: &str, fragment: &str) {
    match parse_spectrum(text) {
        Ok(spectrum) => panic!("{text:?} was accepted as {spectrum:?}"),
        Err(message) => assert!(message.contains(fragment), "{text:?}: {message}"),
    }
}

#[test]
fn malformed_values_are_refused_with_the_problem_named() {
    assert_refused("", "found nothing");
    assert_refused(" , ", "found nothing");
    assert_refused("abc", "must be a finite number, found \"abc\"");
    assert_refused("inf", "finite");
    assert_refused("400:0.5", "at least two wavelength:value pairs, found 1");
    assert_refused(
        "400:0.5, 700",
        "\"700\" is not a wavelength:value pair (no colon)",
    );
    assert_refused("400:0.5, 700:1:2", "more than one colon");
    assert_refused("400:0.5, 700:x", "found \"x\"");
    assert_refused(
        "400:0.5, :1",
        "a wavelength must be a finite number, found \"\"",
    );
    assert_refused("500:0.5, 400:1", "400 nm comes after 500 nm");
    assert_refused("500:0.5, 500:1", "500 nm comes after 500 nm");
    assert_refused("-400:0.5, 700:1", "wavelength -400 is not a positive");
    assert_refused("0:0.5, 700:1", "wavelength 0 is not a positive");
    assert_refused("400:0.5, 700:NaN", "finite");
    assert_refused(
        "400:0.5, 2e6:1",
        "wavelength 2000000 is not a positive number",
    );
    assert_refused(
        "400:0.5, 700:-1e31",
        "not a number of magnitude at most 1e30",
    );
    assert_refused("1e31", "at most 1e30 in magnitude");
}

#[test]
fn malformed_spd_files_are_refused_with_the_line() {
    let refused = |text: &str, fragment: &str| {
        let message = parse_spd(text).expect_err(text);
        assert!(message.contains(fragment), "{text:?}: {message}");
    };
    refused("", "found 0");
    refused("# only a comment\n400 0.5\n", "found 1");
    refused(
        "400 0.5\n500\n",
        "line 2: expected \"wavelength value\", found \"500\"",
    );
    refused("400 0.5\n500 0.5 7\n", "line 2");
    refused(
        "400 0.5\n500 x\n",
        "line 2: a spectrum's value must be a finite number, found \"x\"",
    );
    refused("500 0.5\n400 0.5\n", "400 nm comes after 500 nm");
}

#[test]
fn a_missing_spd_file_is_an_error_naming_it() {
    let message = super::read_spd_file(std::path::Path::new("/no/such/dir/x.spd")).unwrap_err();
    assert!(message.contains("/no/such/dir/x.spd"), "{message}");
}

/// Two to forty pairs at increasing wavelengths (any gaps, down to a millionth of a nanometre,
/// across the whole allowed range) with values anywhere in the allowed range.
fn valid_pairs() -> impl Strategy<Value = Vec<(f64, f64)>> {
    let gap = prop_oneof![1e-6..1.0, 1.0..50.0, 50.0..MAX_WAVELENGTH / 40.0];
    let value = prop_oneof![-1.0..2.0, -MAX_VALUE..MAX_VALUE, Just(0.0), Just(MAX_VALUE)];
    (1e-3..900.0, prop::collection::vec((gap, value), 2..40)).prop_map(
        |(start, steps): (f64, _)| {
            let mut wavelength = start;
            steps
                .into_iter()
                .map(|(gap, value)| {
                    wavelength += gap;
                    (wavelength.min(MAX_WAVELENGTH), value)
                })
                .collect()
        },
    )
}

proptest! {
    #[test]
    fn valid_spectra_give_finite_colours(pairs in valid_pairs()) {
        // Clamping to the largest wavelength may repeat it: such lists are refused, not kept.
        if let Ok(sampled) = SampledSpectrum::new(&pairs) {
            let spectrum = Spectrum::Sampled(sampled);
            for role in [SpectrumRole::Reflectance, SpectrumRole::Emission] {
                let converted = spectrum.to_linear_srgb(role);
                prop_assert!(converted.rgb.is_finite(), "{role:?}: {converted:?}");
                prop_assert!(converted.rgb.min_element() >= 0.0, "{role:?}: {converted:?}");
                if role == SpectrumRole::Reflectance {
                    prop_assert!(converted.rgb.max_element() <= 1.0, "{converted:?}");
                }
            }
        }
    }

    #[test]
    fn written_pairs_read_back(pairs in valid_pairs()) {
        let text: Vec<String> = pairs.iter().map(|(w, v)| format!("{w}:{v}")).collect();
        let read = parse_spectrum(&text.join(", "));
        let built = SampledSpectrum::new(&pairs).map(Spectrum::Sampled);
        prop_assert_eq!(read, built);
    }

    #[test]
    fn any_text_is_read_or_refused_without_panicking(text in "[0-9:.,eE+ #\n-]{0,60}|\\PC{0,60}") {
        let read = [parse_spectrum(&text), parse_spd(&text)];
        for spectrum in read.into_iter().flatten() {
            for role in [SpectrumRole::Reflectance, SpectrumRole::Emission] {
                let rgb = spectrum.to_linear_srgb(role).rgb;
                prop_assert!(rgb.is_finite(), "{text:?} {role:?}: {rgb}");
            }
        }
    }
}
