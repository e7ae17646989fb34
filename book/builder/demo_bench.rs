//! `bench-demos`: how fast each live demo answers, measured in headless Chromium on the built
//! site, offline. Not a test: it asserts nothing, it reports.
//!
//! For a render demo it restarts the demo three times and takes the median of: the time to its
//! first frame (the first slice of tracing drawn), to its first complete pass (one sample in
//! every pixel) and to its target (every pixel refined to the samples it asks for). For the
//! demos that draw at once (chapter 02's), the time from moving a control to the new drawing.
//! The page runs the module on its one main thread; pin the browser to one core with
//! `taskset -c 0` to measure as on one core of a small machine.

use std::path::Path;
use std::time::Duration;

use anyhow::{Context, Result, bail};
use serde::Deserialize;

use crate::site_check;

/// One demo's times, in milliseconds.
#[derive(Debug, Deserialize)]
pub struct DemoTimes {
    /// The page it is on.
    #[serde(default)]
    pub page: String,
    /// Its name (`data-demo`).
    pub name: String,
    /// Its picture's size, `width x height` (empty for the demos that draw at once).
    pub size: String,
    /// The samples per pixel it refines to (0 for the demos that draw at once).
    pub spp: u32,
    /// Time to the first frame drawn.
    pub first_frame: f64,
    /// Time to one sample in every pixel.
    pub first_pass: f64,
    /// Time to the target.
    pub done: f64,
    /// What went wrong, if anything did.
    pub problem: Option<String>,
}

/// Measures every demo of the site at `site`.
pub fn run(site: &Path) -> Result<Vec<DemoTimes>> {
    if !site.join("index.html").is_file() {
        bail!(
            "{} has no index.html: build the site first (`cargo run -p book -- --quick`)",
            site.display()
        );
    }
    let site = site
        .canonicalize()
        .with_context(|| format!("cannot find {}", site.display()))?;
    let chromium = site_check::find_chromium()?;
    let profile = tempfile::Builder::new()
        .prefix("bench-demos-profile")
        .tempdir()
        .context("cannot create a temporary browser profile")?;
    let browser = site_check::launch(&chromium, profile.path())?;
    let tab = browser.new_tab().context("the browser opened no tab")?;
    tab.set_default_timeout(Duration::from_secs(300));
    let (pages, _) = site_check::pages(&site)?;
    let mut times = Vec::new();
    for page in pages.iter().filter(|p| p.starts_with("ch")) {
        let html = std::fs::read_to_string(site.join(page))
            .with_context(|| format!("cannot read {page}"))?;
        if !html.contains("class=\"demo\"") {
            continue;
        }
        tab.navigate_to(&site_check::file_url(&site.join(page)))?
            .wait_until_navigated()?;
        let result = tab
            .evaluate(PROBE, true)
            .with_context(|| format!("the benchmark did not run on {page}"))?;
        let Some(serde_json::Value::String(json)) = result.value else {
            bail!("the benchmark returned nothing on {page}");
        };
        let mut found: Vec<DemoTimes> = serde_json::from_str(&json)
            .with_context(|| format!("the benchmark's report from {page} cannot be read"))?;
        for demo in &mut found {
            demo.page = page.clone();
        }
        times.extend(found);
    }
    Ok(times)
}

/// The times as a Markdown table.
pub fn table(times: &[DemoTimes]) -> String {
    let mut out = String::from(
        "| page | demo | picture | spp | first frame (ms) | first pass (ms) | to the target (ms) |\n\
         |---|---|---|---:|---:|---:|---:|\n",
    );
    for t in times {
        let problem = t
            .problem
            .as_deref()
            .map(|p| format!(" ({p})"))
            .unwrap_or_default();
        out.push_str(&format!(
            "| {} | {}{problem} | {} | {} | {:.0} | {:.0} | {:.0} |\n",
            t.page, t.name, t.size, t.spp, t.first_frame, t.first_pass, t.done
        ));
    }
    out
}

/// Runs in the page: measures each demo as the module says above.
const PROBE: &str = r#"(async () => {
  const sleep = ms => new Promise(done => setTimeout(done, ms));
  const median = values => values.slice().sort((a, b) => a - b)[Math.floor(values.length / 2)];
  const results = [];
  for (const root of document.querySelectorAll('div.demo')) {
    const result = { name: root.dataset.demo || '', size: '', spp: 0, first_frame: 0, first_pass: 0, done: 0, problem: null };
    results.push(result);
    root.scrollIntoView();
    const started = Date.now();
    while (!root.dataset.ready && Date.now() - started < 20000) await sleep(10);
    const canvas = root.querySelector('canvas');
    if (root.dataset.ready !== 'yes' || (canvas && canvas.dataset.failure)) {
      result.problem = (canvas && canvas.dataset.failure) || 'it did not start';
      continue;
    }
    if (root.dataset.progressive === 'yes') {
      const runs = [];
      for (let run = 0; run < 3; run++) {
        root.demoRestart();
        const waited = Date.now();
        while (root.dataset.done !== 'yes' && !canvas.dataset.failure && Date.now() - waited < 120000) await sleep(5);
        if (root.dataset.done !== 'yes') { result.problem = canvas.dataset.failure || 'it did not finish in 120 s'; break; }
        runs.push([Number(root.dataset.firstFrameMs), Number(root.dataset.firstPassMs), Number(root.dataset.doneMs)]);
      }
      if (runs.length === 0) continue;
      result.first_frame = median(runs.map(r => r[0]));
      result.first_pass = median(runs.map(r => r[1]));
      result.done = median(runs.map(r => r[2]));
      result.spp = Number(root.dataset.spp);
      result.size = root.dataset.size || '';
    } else {
      const control = root.querySelector('[data-control]');
      const runs = [];
      for (let run = 0; run < 3; run++) {
        const frames = root.dataset.frames;
        const t0 = performance.now();
        control.dispatchEvent(new Event('input', { bubbles: true }));
        while (root.dataset.frames === frames && Date.now() - started < 60000) await sleep(1);
        runs.push(performance.now() - t0);
      }
      result.first_frame = result.first_pass = result.done = median(runs);
    }
  }
  return JSON.stringify(results);
})()"#;
