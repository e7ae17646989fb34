//! The live demos, played in the browser: `check-site` starts every demo of a page, moves each
//! of its controls, and asks the demo's own check whether it shows what its controls promise
//! (the naive disc failing the chi-square test, the polar disc passing it).
//!
//! A demo is a `<div class="demo">` that `book/theme/demos.js` fills; it marks itself
//! `data-ready="yes"` (or `"failed"`), counts its drawn frames in `data-frames`, and writes what
//! stopped it (a panic in the chapter's code, such as an exercise not written yet) into its
//! canvas's `data-failure`. A demo may hang a function `demoCheck` on its element: it moves what
//! the generic pass cannot judge and answers a list of problems.

use anyhow::{Context, Result, bail};
use headless_chrome::Tab;
use serde::Deserialize;

/// What [`PROBE`] reports of one demo.
#[derive(Debug, Deserialize)]
pub struct DemoReport {
    /// The demo's name (`data-demo`).
    pub name: String,
    /// What is wrong with it.
    pub problems: Vec<String>,
    /// The message of an exercise not written yet that stopped it, if one did.
    pub waiting: Option<String>,
    /// How many controls were moved.
    pub controls: usize,
    /// Where it is on the page, in CSS pixels, for its screenshot.
    pub rect: Option<Rect>,
}

/// A rectangle of the page.
#[derive(Debug, Deserialize, Clone, Copy)]
pub struct Rect {
    pub x: f64,
    pub y: f64,
    pub width: f64,
    pub height: f64,
}

/// Plays every demo of the page open in `tab`: moves every control and runs each demo's own
/// check when `thorough`, or only sees each start and draw its first frame (the print page,
/// which shows again the demos already played on their own pages).
pub fn play(tab: &Tab, thorough: bool) -> Result<Vec<DemoReport>> {
    let probe = PROBE.replace("THOROUGH", if thorough { "true" } else { "false" });
    let result = tab
        .evaluate(&probe, true)
        .context("the demos' probe did not run")?;
    match result.value {
        Some(serde_json::Value::String(json)) => {
            serde_json::from_str(&json).context("the demos' probe answered something unreadable")
        }
        _ => bail!("the demos' probe returned no report: {result:?}"),
    }
}

/// Runs in the page: for each demo, waits up to 20 s for it to be ready, then moves each visible
/// control in turn (a select to its next option, a slider to its other end, a number up by one,
/// a checkbox over), waits for the demo to draw again, and checks that the canvas changed; then
/// runs the demo's own check. A render demo (`data-progressive`) refines its picture over many
/// frames, and its first frames after a move may show only rows that did not change (the sky):
/// it is compared once it has finished (`data-done`), before and after each move, refined to two
/// samples per pixel only (`demoCap`). A failure whose message is an exercise's stub ("(not written
/// yet)") is reported apart, as `waiting`: the student's own site shows it on purpose.
const PROBE: &str = r#"(async (thorough) => {
  const sleep = ms => new Promise(done => setTimeout(done, ms));
  const reports = [];
  for (const root of document.querySelectorAll('div.demo')) {
    const report = { name: root.dataset.demo || '', problems: [], waiting: null, controls: 0, rect: null };
    reports.push(report);
    const started = Date.now();
    while (!root.dataset.ready && Date.now() - started < 20000) await sleep(20);
    root.scrollIntoView();
    const box = root.getBoundingClientRect();
    report.rect = { x: box.left + window.scrollX, y: box.top + window.scrollY, width: box.width, height: box.height };
    const canvas = root.querySelector('canvas');
    const failure = () => canvas ? canvas.dataset.failure : 'the demo has no canvas';
    const stopped = what => {
      const message = failure() || 'no message';
      if (message.includes('(not written yet)')) report.waiting = message;
      else report.problems.push(`${what}: ${message}`);
    };
    if (root.dataset.ready !== 'yes') {
      if (failure()) stopped('it did not start');
      else report.problems.push('it did not start within 20 s');
      continue;
    }
    const progressive = root.dataset.progressive === 'yes';
    const finished = async () => {
      const waited = Date.now();
      while (progressive && root.dataset.done !== 'yes' && !failure() && Date.now() - waited < 30000) await sleep(20);
      if (progressive && root.dataset.done !== 'yes' && !failure()) {
        report.problems.push('it did not finish its picture within 30 s');
      }
    };
    const settle = async frames => {
      const waited = Date.now();
      while (root.dataset.frames === frames && !failure() && Date.now() - waited < 10000) await sleep(10);
      if (root.dataset.frames !== frames) await finished();
    };
    if (!failure() && progressive) {
      const waited = Date.now();
      while (!root.dataset.frames && !failure() && Date.now() - waited < 10000) await sleep(10);
    }
    if (failure()) { stopped('its first frame failed'); continue; }
    if (!thorough) continue;
    // Two samples per pixel show what a control changes, at an eighth of the usual time.
    if (typeof root.demoCap === 'function') root.demoCap(2);
    for (const control of root.querySelectorAll('[data-control]')) {
      if (control.offsetParent === null) continue;
      report.controls++;
      await finished();
      const before = canvas.toDataURL();
      const frames = root.dataset.frames;
      if (control.tagName === 'SELECT') {
        control.selectedIndex = (control.selectedIndex + 1) % control.options.length;
      } else if (control.type === 'range') {
        control.value = control.value === control.max ? control.min : control.max;
      } else if (control.type === 'checkbox') {
        control.checked = !control.checked;
      } else {
        control.value = String(Number(control.value) + 1);
      }
      control.dispatchEvent(new Event('input', { bubbles: true }));
      control.dispatchEvent(new Event('change', { bubbles: true }));
      await settle(frames);
      if (failure()) { stopped(`moving its ${control.dataset.control}`); break; }
      if (root.dataset.frames === frames) {
        report.problems.push(`moving its ${control.dataset.control} drew nothing within 10 s`);
      } else if (canvas.toDataURL() === before) {
        report.problems.push(`moving its ${control.dataset.control} left the canvas as it was`);
      }
    }
    if (!failure() && typeof root.demoCheck === 'function') {
      try {
        report.problems.push(...await root.demoCheck());
      } catch (error) {
        report.problems.push(`its own check threw: ${error}`);
      }
      if (failure()) stopped('its own check');
    }
  }
  // Back to the top, so that mdBook's bar, fixed at the top of the window, does not cover the
  // demos in their screenshots.
  window.scrollTo(0, 0);
  return JSON.stringify(reports);
})(THOROUGH)"#;
