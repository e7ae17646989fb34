//! The render demos' exports: find a demo by name, describe its controls, start its views with
//! the page's values, refine them a slice at a time, hand out their pixels, check its claims.
//!
//! Every demo of the book is listed in [`DEMOS`]. A session ([`Session`]) is one view being
//! refined; it lives in a numbered slot the page chooses (a page may show several demos, the
//! print page all of them), and a new start in a slot replaces it.

use std::cell::RefCell;

use crate::demo::{ControlKind, Demo, Values};
use crate::progressive::Session;
use crate::{buffers, outcome};

/// Every render demo, one or more per chapter.
pub static DEMOS: &[&dyn Demo] = &[
    &crate::whitted::WhittedDemo,
    &crate::anti_aliasing::AntiAliasingDemo,
    &crate::depth_of_field::DepthOfFieldDemo,
    &crate::motion_blur::MotionBlurDemo,
    &crate::fuzzy::FuzzyDemo,
    &crate::soft_shadows::SoftShadowsDemo,
    &crate::path_tracing::PathTracingDemo,
    &crate::materials::MaterialsDemo,
    &crate::optimal_mis::OptimalMisDemo,
    &crate::path_guiding::PathGuidingDemo,
];

/// The most sessions a page may run at once.
const MOST_SLOTS: u32 = 256;

thread_local! {
    static SESSIONS: RefCell<Vec<Option<Session>>> = const { RefCell::new(Vec::new()) };
}

/// Refuses a call: the message goes to the text buffer, and the page reads `u32::MAX`.
fn refuse(message: impl Into<String>) -> u32 {
    buffers::set_text(message);
    u32::MAX
}

fn demo(index: u32) -> Option<&'static dyn Demo> {
    DEMOS.get(index as usize).copied()
}

/// The index of the demo named by the text the page wrote ([`buffers::input_text_ptr`]), or
/// `u32::MAX` with a message if there is none.
#[unsafe(no_mangle)]
pub extern "C" fn demo_find() -> u32 {
    let name = buffers::input_text();
    match DEMOS.iter().position(|d| d.name() == name) {
        Some(index) => index as u32,
        None => refuse(format!("no demo called {name}")),
    }
}

/// Puts the description of demo `index` in the text buffer, as JSON: its name, views, the
/// size of its picture, whether it zooms, its controls (name, label, a range's `min`, `max`,
/// `step` or a choice's `options`, the starting `value`, and `when` another control's value
/// shows it) and its claims' words. Gives the text's length.
#[unsafe(no_mangle)]
pub extern "C" fn demo_spec(index: u32) -> u32 {
    let Some(demo) = demo(index) else {
        return refuse("no such demo");
    };
    buffers::set_text(spec_json(demo))
}

/// The JSON [`demo_spec`] gives.
fn spec_json(demo: &dyn Demo) -> String {
    let quote = |s: &str| {
        let mut out = String::from("\"");
        for c in s.chars() {
            match c {
                '"' => out.push_str("\\\""),
                '\\' => out.push_str("\\\\"),
                c if (c as u32) < 0x20 => out.push_str(&format!("\\u{:04x}", c as u32)),
                c => out.push(c),
            }
        }
        out.push('"');
        out
    };
    let list = |items: Vec<String>| format!("[{}]", items.join(","));
    let controls = demo
        .controls()
        .iter()
        .map(|c| {
            let kind = match c.kind {
                ControlKind::Range { min, max, step } => {
                    format!("\"min\":{min},\"max\":{max},\"step\":{step}")
                }
                ControlKind::Choice(options) => format!(
                    "\"options\":{}",
                    list(options.iter().map(|o| quote(o)).collect())
                ),
            };
            let when = match c.shown_when {
                Some((name, value)) => {
                    format!(",\"when\":{{\"name\":{},\"value\":{value}}}", quote(name))
                }
                None => String::new(),
            };
            format!(
                "{{\"name\":{},\"label\":{},{kind},\"value\":{}{when}}}",
                quote(c.name),
                quote(c.label),
                c.value
            )
        })
        .collect();
    let (width, height) = demo.size();
    format!(
        "{{\"name\":{},\"views\":{},\"width\":{width},\"height\":{height},\
         \"zoom\":{},\"controls\":{},\"claims\":{}}}",
        quote(demo.name()),
        list(demo.views().iter().map(|v| quote(v)).collect()),
        demo.zoom(),
        list(controls),
        list(demo.claims().iter().map(|c| quote(c.says)).collect()),
    )
}

/// Starts view `view` of demo `index` in slot `slot` at `width x height` with the values the
/// page wrote ([`buffers::input_numbers_ptr`], one per control in order). Gives the samples per
/// pixel it will refine to, or `u32::MAX` with the reason (values out of range, or a panic in
/// the chapter's code: an exercise not written yet).
#[unsafe(no_mangle)]
pub extern "C" fn demo_start(index: u32, view: u32, slot: u32, width: u32, height: u32) -> u32 {
    outcome::run(|| {
        let Some(demo) = demo(index) else {
            return refuse("no such demo");
        };
        if view as usize >= demo.views().len() {
            return refuse(format!("{} has no view {view}", demo.name()));
        }
        if slot >= MOST_SLOTS {
            return refuse(format!("a page may run {MOST_SLOTS} demos' views at most"));
        }
        if !(1..=1024).contains(&width) || !(1..=1024).contains(&height) {
            return refuse(format!("{width} x {height} is no size for a demo"));
        }
        let values = match Values::from_page(&demo.controls(), &buffers::input_numbers()) {
            Ok(values) => values,
            Err(message) => return refuse(message),
        };
        let picture = match demo.picture(&values, view as usize, width, height) {
            Ok(picture) => picture,
            Err(message) => return refuse(message),
        };
        let target = demo.target_spp(&values);
        let session = Session::new(picture, width, height, target);
        SESSIONS.with(|cell| {
            let mut sessions = cell.borrow_mut();
            if sessions.len() <= slot as usize {
                sessions.resize_with(slot as usize + 1, || None);
            }
            sessions[slot as usize] = Some(session);
        });
        target.min(u64::from(u32::MAX - 1)) as u32
    })
}

/// Traces up to `budget` more samples of the session in `slot` (whole rows, at least one).
/// Gives the samples traced (0 once done), or `u32::MAX` with the reason.
#[unsafe(no_mangle)]
pub extern "C" fn demo_advance(slot: u32, budget: u32) -> u32 {
    outcome::run(|| {
        with_session(slot, |session| {
            session
                .advance(u64::from(budget))
                .min(u64::from(u32::MAX - 1)) as u32
        })
    })
}

/// The samples every pixel of the session in `slot` has.
#[unsafe(no_mangle)]
pub extern "C" fn demo_spp(slot: u32) -> u32 {
    with_session(slot, |session| session.spp() as u32)
}

/// Puts the image of the session in `slot` in the byte buffer (sRGB, RGBA, rows from the
/// top); gives its length.
#[unsafe(no_mangle)]
pub extern "C" fn demo_image(slot: u32) -> u32 {
    with_session(slot, |session| buffers::set_bytes(session.rgba()))
}

fn with_session(slot: u32, work: impl FnOnce(&mut Session) -> u32) -> u32 {
    SESSIONS.with(|cell| {
        let mut sessions = cell.borrow_mut();
        match sessions.get_mut(slot as usize).and_then(Option::as_mut) {
            Some(session) => work(session),
            None => refuse(format!("slot {slot} has no session started")),
        }
    })
}

/// Checks claim `claim` of demo `index`: 0 when it holds, `u32::MAX` with what is wrong in
/// the text buffer when it does not (or the chapter's code stopped).
#[unsafe(no_mangle)]
pub extern "C" fn demo_claim(index: u32, claim: u32) -> u32 {
    outcome::run(|| {
        let Some(demo) = demo(index) else {
            return refuse("no such demo");
        };
        let claims = demo.claims();
        let Some(claim) = claims.get(claim as usize) else {
            return refuse(format!("{} has no claim {claim}", demo.name()));
        };
        match (claim.check)(demo) {
            Ok(()) => 0,
            Err(problem) => refuse(format!("{}: {problem}", claim.says)),
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_demo_is_found_by_name_and_describes_itself() {
        for (index, demo) in DEMOS.iter().enumerate() {
            buffers::give_text(demo.name());
            assert_eq!(demo_find(), index as u32);
            let length = demo_spec(index as u32);
            let spec = buffers::text();
            assert_eq!(length as usize, spec.len());
            assert!(spec.starts_with('{') && spec.ends_with('}'), "{spec}");
            assert!(spec.contains(&format!("\"name\":\"{}\"", demo.name())));
            let controls = demo.controls();
            for control in &controls {
                assert!(spec.contains(&format!("\"name\":\"{}\"", control.name)));
                if let Some((name, value)) = control.shown_when {
                    let other = controls
                        .iter()
                        .find(|c| c.name == name && c.name != control.name);
                    assert!(
                        other.is_some_and(|other| other.allows(value)),
                        "{}: {} is shown when {name} is {value}, which no other control can be",
                        demo.name(),
                        control.name
                    );
                }
            }
        }
        buffers::give_text("no-such-demo");
        assert_eq!(demo_find(), u32::MAX);
        assert!(buffers::text().contains("no demo called no-such-demo"));
    }

    #[test]
    fn every_view_of_every_demo_starts_refines_and_shows() {
        for (index, demo) in DEMOS.iter().enumerate() {
            let values: Vec<f64> = demo.controls().iter().map(|c| c.value).collect();
            for view in 0..demo.views().len() as u32 {
                buffers::give_numbers(&values);
                let slot = 2 * index as u32 + view;
                let target = demo_start(index as u32, view, slot, 12, 8);
                assert_ne!(target, u32::MAX, "{}: {}", demo.name(), buffers::text());
                assert_eq!(demo_advance(slot, 12 * 8), 12 * 8);
                assert_eq!(demo_spp(slot), 1);
                assert_eq!(demo_image(slot), 12 * 8 * 4);
            }
        }
    }

    #[test]
    fn values_out_of_range_and_unknown_views_are_refused() {
        let demo = DEMOS[0];
        let mut values: Vec<f64> = demo.controls().iter().map(|c| c.value).collect();
        buffers::give_numbers(&values[1..]);
        assert_eq!(demo_start(0, 0, 0, 8, 8), u32::MAX);
        assert!(
            buffers::text().contains("values for"),
            "{}",
            buffers::text()
        );
        values[0] = 1e9;
        buffers::give_numbers(&values);
        assert_eq!(demo_start(0, 0, 0, 8, 8), u32::MAX);
        assert!(buffers::text().contains("is not a value of"));
        assert_eq!(demo_start(0, 9, 0, 8, 8), u32::MAX);
        assert_eq!(demo_start(0, 0, MOST_SLOTS, 8, 8), u32::MAX);
        assert_eq!(demo_start(0, 0, 0, 0, 8), u32::MAX);
        assert_eq!(demo_advance(MOST_SLOTS - 1, 10), u32::MAX);
        assert!(buffers::text().contains("no session"));
    }

    #[test]
    fn every_claim_of_every_demo_holds() {
        for (index, demo) in DEMOS.iter().enumerate() {
            for (i, claim) in demo.claims().iter().enumerate() {
                assert_eq!(
                    demo_claim(index as u32, i as u32),
                    0,
                    "{}: {} does not hold: {}",
                    demo.name(),
                    claim.says,
                    buffers::text()
                );
            }
        }
    }
}
