//! What a render demo is: a chapter's scene and tracer behind a few controls, rendered
//! progressively, with the claims its controls make.
//!
//! A demo describes its controls ([`Control`]); the page builds them, and hands their values
//! back ([`Values`]) whenever one moves; the demo then makes a [`Picture`] of them, which the
//! page refines one sample per pixel at a time ([`crate::progressive`]). A demo with two
//! views (chapter 08's path beside Cook's tree) makes one picture per view, and the page
//! gives both the same time.
//!
//! A demo's claims ([`Claim`]) are what its controls promise ("a wider aperture blurs what is
//! off the focal plane"), checked on small renders by the crate's tests natively and by the
//! site check in the browser, through the same code.

use common::film::{Filter, PixelBoxFilter};
use common::render::trace_pixel_sample;
use common::sampler::Sampler;
use glam::{UVec2, Vec2, Vec3};

/// One control of a demo, as the page shows it.
#[derive(Clone, Debug)]
pub struct Control {
    /// The name the values are looked up by, and the page's `data-control`.
    pub name: &'static str,
    /// What the page writes beside it.
    pub label: &'static str,
    /// A slider or a choice.
    pub kind: ControlKind,
    /// Its value when the demo starts (an option's index for a choice).
    pub value: f64,
    /// Shown only while another control has one value (`(name, value)`): a polygon's blades
    /// only while the aperture is a polygon. A hidden control keeps its value.
    pub shown_when: Option<(&'static str, f64)>,
}

/// A slider or a list of choices.
#[derive(Clone, Debug)]
pub enum ControlKind {
    /// A slider from `min` to `max` in steps of `step`.
    Range { min: f64, max: f64, step: f64 },
    /// A choice among these options; its value is the option's index.
    Choice(&'static [&'static str]),
}

impl Control {
    /// A slider.
    pub const fn range(
        name: &'static str,
        label: &'static str,
        min: f64,
        max: f64,
        step: f64,
        value: f64,
    ) -> Self {
        Self {
            name,
            label,
            kind: ControlKind::Range { min, max, step },
            value,
            shown_when: None,
        }
    }

    /// A choice among `options`, starting at option `value`.
    pub const fn choice(
        name: &'static str,
        label: &'static str,
        options: &'static [&'static str],
        value: usize,
    ) -> Self {
        Self {
            name,
            label,
            kind: ControlKind::Choice(options),
            value: value as f64,
            shown_when: None,
        }
    }

    /// This control, shown only while control `name` has value `value` (an option's index for
    /// a choice).
    pub const fn when(mut self, name: &'static str, value: f64) -> Self {
        self.shown_when = Some((name, value));
        self
    }

    /// Whether `value` is one this control can take.
    pub(crate) fn allows(&self, value: f64) -> bool {
        match self.kind {
            ControlKind::Range { min, max, .. } => (min..=max).contains(&value),
            ControlKind::Choice(options) => {
                value.fract() == 0.0 && (0.0..options.len() as f64).contains(&value)
            }
        }
    }
}

/// The values of a demo's controls, by name.
#[derive(Clone, Debug)]
pub struct Values {
    pairs: Vec<(&'static str, f64)>,
}

impl Values {
    /// Every control at its starting value.
    pub fn defaults(controls: &[Control]) -> Self {
        Self {
            pairs: controls.iter().map(|c| (c.name, c.value)).collect(),
        }
    }

    /// The values the page sent, in the order of `controls`; refused with a message if there
    /// are not as many or one is out of its control's range.
    pub fn from_page(controls: &[Control], values: &[f64]) -> Result<Self, String> {
        if values.len() != controls.len() {
            return Err(format!(
                "the page sent {} values for {} controls",
                values.len(),
                controls.len()
            ));
        }
        for (control, &value) in controls.iter().zip(values) {
            if !control.allows(value) {
                return Err(format!("{value} is not a value of {}", control.label));
            }
        }
        Ok(Self {
            pairs: controls
                .iter()
                .map(|c| c.name)
                .zip(values.iter().copied())
                .collect(),
        })
    }

    /// These values with control `name` set to `value` (for claims).
    pub fn with(mut self, name: &str, value: f64) -> Self {
        let pair = self.pairs.iter_mut().find(|(n, _)| *n == name);
        pair.unwrap_or_else(|| panic!("the demo has no control called {name}"))
            .1 = value;
        self
    }

    /// The value of control `name`.
    ///
    /// # Panics
    /// If the demo has no such control: a demo asks only for its own.
    pub fn get(&self, name: &str) -> f64 {
        self.pairs
            .iter()
            .find(|(n, _)| *n == name)
            .unwrap_or_else(|| panic!("the demo has no control called {name}"))
            .1
    }

    /// The value of control `name` as a float.
    pub fn f32(&self, name: &str) -> f32 {
        self.get(name) as f32
    }

    /// The value of control `name` as a whole number (an option's index, a count).
    pub fn index(&self, name: &str) -> usize {
        self.get(name).round().max(0.0) as usize
    }
}

/// What a demo renders: the radiance of sample `index` of a pixel, from the chapter's own
/// camera and tracer, and the filter that puts samples into pixels.
pub trait Picture {
    /// How samples are weighted into pixels (chapter 03's filters; the pixel box elsewhere).
    fn filter(&self) -> &dyn Filter {
        &PixelBoxFilter
    }

    /// Traces sample `index` of every pixel in `pixels`, handing each sample's film position
    /// and radiance to `add`.
    fn trace(&self, pixels: &[UVec2], index: u64, add: &mut dyn FnMut(Vec2, Vec3));
}

/// Traces sample `index` of each of `pixels` as the render loop does
/// ([`trace_pixel_sample`]).
pub fn trace_each<S: Sampler>(
    sampler: &S,
    pixels: &[UVec2],
    index: u64,
    add: &mut dyn FnMut(Vec2, Vec3),
    radiance: impl Fn(Vec2, &mut S) -> Vec3,
) {
    let mut sampler = sampler.clone();
    for &pixel in pixels {
        let (p_film, l) = trace_pixel_sample(&mut sampler, pixel, index, &radiance);
        add(p_film, l);
    }
}

/// What one of a demo's controls promises, and how to see it.
pub struct Claim {
    /// The promise, in words ("a wider aperture blurs the far spheres").
    pub says: &'static str,
    /// Renders what it takes and says what is wrong, if anything.
    pub check: fn(&dyn Demo) -> Result<(), String>,
}

/// A live demo of a chapter.
pub trait Demo: Sync {
    /// The name a page asks for (`data-demo`).
    fn name(&self) -> &'static str;

    /// Its controls, in the order the page shows them.
    fn controls(&self) -> Vec<Control>;

    /// The views rendered side by side at equal time; one unnamed view by default.
    fn views(&self) -> &'static [&'static str] {
        &[""]
    }

    /// The samples per pixel the page refines to, unless a control says otherwise.
    fn target_spp(&self, values: &Values) -> u64 {
        let _ = values;
        16
    }

    /// The size of its picture in pixels (the page draws it twice as large); the benchmark's
    /// 128 x 128 unless the chapter's scene has another shape.
    fn size(&self) -> (u32, u32) {
        (128, 128)
    }

    /// Whether the page may zoom in on the pixels.
    fn zoom(&self) -> bool {
        false
    }

    /// The picture of view `view` with these values at `width x height` pixels, or why not.
    fn picture(
        &self,
        values: &Values,
        view: usize,
        width: u32,
        height: u32,
    ) -> Result<Box<dyn Picture>, String>;

    /// What its controls promise.
    fn claims(&self) -> Vec<Claim>;
}
