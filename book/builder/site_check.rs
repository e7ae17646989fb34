//! `check-site`: the built site, opened page by page in a real browser.
//!
//! The builder already fails on what it can see while building (a formula KaTeX cannot typeset,
//! an include that does not exist, a stylesheet from the network). What it cannot see is what a
//! reader sees: whether every figure actually loads, whether a link lands on a page and a
//! heading that exist, whether the pages' scripts run without errors, whether search finds
//! anything. Those only show in a browser, so this module opens every page of the site in
//! headless Chromium, from disk (`file://` URLs, as students open the book) and with no network,
//! and lists every problem it finds with the page and the element. It also writes a screenshot
//! of every page, for a person to look at.
//!
//! The browser is driven through the DevTools protocol by the `headless_chrome` crate, built
//! with its default `offline` feature: it never downloads a browser, it uses the Chromium
//! installed from the operating system's packages.

use std::collections::{BTreeMap, HashMap, HashSet};
use std::ffi::{OsStr, OsString};
use std::path::{Component, Path, PathBuf};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use anyhow::{Context, Result, anyhow, bail};
use base64::Engine;
use base64::prelude::BASE64_STANDARD;
use headless_chrome::protocol::cdp::types::Event;
use headless_chrome::protocol::cdp::{Log, Network, Page, Runtime};
use headless_chrome::{Browser, LaunchOptions, Tab};
use serde::Deserialize;

/// The programs tried, in this order, after `$CHROMIUM`.
const BROWSER_NAMES: &[&str] = &["chromium", "chromium-browser", "google-chrome"];

/// The width and height of the browser window, in CSS pixels: a laptop screen.
const WINDOW: (u32, u32) = (1280, 900);

/// Screenshots stop at this height: Chromium cannot draw one image much taller than 16384 px.
const MAX_SCREENSHOT_HEIGHT: f64 = 16_000.0;

/// How long one page may take to load, and search to answer.
const TIMEOUT: Duration = Duration::from_secs(30);

/// What to check, and where.
pub struct Options {
    /// The built site: the directory with `index.html`.
    pub site: PathBuf,
    /// Where to write one PNG per page.
    pub screenshots: PathBuf,
    /// Whether an image without alt text is a problem (`false`: only a note).
    pub alt_check: bool,
    /// A word to type into the search box of `index.html`, which must then show results; `None`
    /// for a site without mdBook's search.
    pub search_word: Option<String>,
    /// Whether a demo stopped by an exercise not written yet is only a note (the student's own
    /// site, which runs the student's code) rather than a problem (the workbook's).
    pub demos_may_wait: bool,
}

/// One thing wrong, on one page.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct Problem {
    /// The page, relative to the site (`ch01-whitted.html`), or `search` for the search check.
    pub page: String,
    /// The element or event, and what is wrong with it.
    pub what: String,
}

impl std::fmt::Display for Problem {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {}", self.page, self.what)
    }
}

/// What one run found.
pub struct Outcome {
    /// The pages opened, relative to the site.
    pub pages: Vec<String>,
    /// Pages not opened, with the reason.
    pub skipped: Vec<Skipped>,
    /// Everything that fails the check.
    pub problems: Vec<Problem>,
    /// Images without alt text when the alt check is off: reported, but not failures.
    pub notes: Vec<Problem>,
    /// How many results the search showed, when it was checked.
    pub search_results: Option<usize>,
}

/// A page not opened, and why.
#[derive(Debug, PartialEq, Eq)]
pub struct Skipped {
    pub page: String,
    pub why: &'static str,
}

/// Pages of an mdBook site that are not opened, and why.
///
/// `404.html` is meant to be served by a web server at any depth: mdBook gives it a
/// `<base href="/">` (from `site-url`), so opened from disk it looks for its stylesheets and
/// scripts at the root of the file system. Every other page, `print.html` included, is opened.
const SKIPPED: &[(&str, &str)] = &[(
    "404.html",
    "mdBook's not-found page is for a web server: its <base href=\"/\"> points at the file \
     system's root when opened from disk",
)];

/// Finds the browser: `$CHROMIUM` if set, else the first of [`BROWSER_NAMES`] on `PATH`.
pub fn find_chromium() -> Result<PathBuf> {
    find_chromium_in(std::env::var_os("CHROMIUM"), std::env::var_os("PATH"))
}

/// [`find_chromium`], with the values of `$CHROMIUM` and `$PATH` given.
fn find_chromium_in(chromium: Option<OsString>, path: Option<OsString>) -> Result<PathBuf> {
    let on_path = |name: &Path| {
        let path = path.as_ref()?;
        std::env::split_paths(path)
            .map(|dir| dir.join(name))
            .find(|candidate| is_executable(candidate))
    };
    if let Some(chromium) = chromium.filter(|c| !c.is_empty()) {
        let chromium = PathBuf::from(chromium);
        let found = if chromium.components().count() > 1 {
            Some(chromium.clone()).filter(|c| is_executable(c))
        } else {
            on_path(&chromium)
        };
        return found.ok_or_else(|| {
            anyhow!(
                "$CHROMIUM is set to {}, which is not a program that can be run",
                chromium.display()
            )
        });
    }
    BROWSER_NAMES
        .iter()
        .find_map(|name| on_path(Path::new(name)))
        .ok_or_else(|| {
            anyhow!(
                "check-site needs Chromium and found none (looked at $CHROMIUM, then for {} on \
                 PATH): install it with `apt-get install chromium` (as root, on Debian or \
                 Ubuntu), or set $CHROMIUM to a Chromium or Chrome program",
                BROWSER_NAMES.join(", ")
            )
        })
}

fn is_executable(path: &Path) -> bool {
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        path.metadata()
            .is_ok_and(|m| m.is_file() && m.permissions().mode() & 0o111 != 0)
    }
    #[cfg(not(unix))]
    {
        path.is_file()
    }
}

/// Every HTML page of `site`, relative to it and sorted, and the pages skipped (see
/// [`SKIPPED`]).
pub fn pages(site: &Path) -> Result<(Vec<String>, Vec<Skipped>)> {
    let mut all: Vec<String> = crate::workspace::files_under(site)?
        .into_iter()
        .filter(|path| path.extension() == Some(OsStr::new("html")))
        .map(|path| slashed(path.strip_prefix(site).unwrap_or(&path)))
        .collect();
    all.sort();
    let mut pages = Vec::new();
    let mut skipped = Vec::new();
    for page in all {
        match SKIPPED.iter().find(|(name, _)| *name == page) {
            Some((_, why)) => skipped.push(Skipped { page, why }),
            None => pages.push(page),
        }
    }
    Ok((pages, skipped))
}

/// A relative path with `/` between its parts, whatever the platform.
fn slashed(path: &Path) -> String {
    path.components()
        .map(|c| c.as_os_str().to_string_lossy())
        .collect::<Vec<_>>()
        .join("/")
}

/// Where a link goes.
#[derive(Debug, PartialEq, Eq)]
pub enum LinkTarget {
    /// Another website, an e-mail address, a script: not followed.
    Elsewhere,
    /// A file of the site (relative to its root, `/`-separated), and the fragment after `#`
    /// (percent-decoded), if any.
    Local {
        file: String,
        fragment: Option<String>,
    },
    /// A relative path that climbs out of the site.
    OutsideSite,
}

/// Resolves the `href` of a link on `page` (both relative to the site's root) the way a
/// browser does for a page opened from disk.
pub fn resolve_link(page: &str, href: &str) -> LinkTarget {
    let href = href.trim();
    let has_scheme = href
        .split_once(':')
        .is_some_and(|(scheme, _)| !scheme.is_empty() && !scheme.contains(['/', '?', '#']));
    if has_scheme || href.starts_with("//") {
        return LinkTarget::Elsewhere;
    }
    let (before_fragment, fragment) = match href.split_once('#') {
        Some((before, fragment)) => (before, Some(percent_decode(fragment))),
        None => (href, None),
    };
    let path = before_fragment
        .split_once('?')
        .map_or(before_fragment, |(path, _query)| path);
    if path.is_empty() {
        return LinkTarget::Local {
            file: page.to_owned(),
            fragment,
        };
    }
    // An absolute path from a page opened from disk means the file system's root.
    if path.starts_with('/') {
        return LinkTarget::OutsideSite;
    }
    let mut parts: Vec<String> = page.split('/').map(str::to_owned).collect();
    parts.pop(); // the page's own name
    for part in percent_decode(path).split('/') {
        match part {
            "" | "." => {}
            ".." => {
                if parts.pop().is_none() {
                    return LinkTarget::OutsideSite;
                }
            }
            name => parts.push(name.to_owned()),
        }
    }
    if path.ends_with('/') {
        parts.push(String::new());
    }
    LinkTarget::Local {
        file: parts.join("/"),
        fragment,
    }
}

/// Decodes `%xx` escapes (as UTF-8); anything malformed is kept as it is.
fn percent_decode(text: &str) -> String {
    let bytes = text.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        let hex = |b: u8| (b as char).to_digit(16);
        if bytes[i] == b'%'
            && i + 2 < bytes.len()
            && let (Some(high), Some(low)) = (hex(bytes[i + 1]), hex(bytes[i + 2]))
        {
            out.push((high * 16 + low) as u8);
            i += 3;
        } else {
            out.push(bytes[i]);
            i += 1;
        }
    }
    String::from_utf8_lossy(&out).into_owned()
}

/// The name of a page's screenshot: its path with `/` as `__`, and `.png` for `.html`.
pub fn screenshot_name(page: &str) -> String {
    let stem = page.strip_suffix(".html").unwrap_or(page);
    format!("{}.png", stem.replace('/', "__"))
}

/// The `id`s (and `<a name>`s) in an HTML file, read from its text: for link targets that were
/// not opened in the browser (a skipped page).
fn ids_in_html(html: &str) -> HashSet<String> {
    let mut ids = HashSet::new();
    for attribute in [" id=", " name="] {
        for (start, _) in html.match_indices(attribute) {
            let rest = &html[start + attribute.len()..];
            let Some(quote) = rest.chars().next().filter(|c| *c == '"' || *c == '\'') else {
                continue;
            };
            if let Some(end) = rest[1..].find(quote) {
                ids.insert(rest[1..1 + end].to_owned());
            }
        }
    }
    ids
}

/// What the probe (below) reports from one page.
#[derive(Debug, Deserialize)]
#[serde(rename_all = "camelCase")]
struct PageFacts {
    images: Vec<ImageFacts>,
    links: Vec<LinkFacts>,
    ids: Vec<String>,
    katex_errors: Vec<KatexError>,
    raw_tex: Vec<String>,
    /// The size of the whole page, in CSS pixels, for its screenshot.
    size: PageSize,
}

#[derive(Debug, Deserialize, Clone, Copy)]
struct PageSize {
    width: f64,
    height: f64,
}

#[derive(Debug, Deserialize)]
struct ImageFacts {
    src: String,
    alt: Option<String>,
    loaded: bool,
}

#[derive(Debug, Deserialize)]
struct LinkFacts {
    href: String,
    text: String,
}

#[derive(Debug, Deserialize)]
struct KatexError {
    source: String,
    message: String,
}

/// Runs in the page just opened. It first waits for the page to have loaded: the document that
/// was open before carries a mark, and the new one must report `complete` (its stylesheets and
/// scripts loaded or failed). While the old document is still there, or the new one is still
/// loading after a quarter of a second, it answers an empty string and [`open`] asks again;
/// an answer that is cut short because the old document goes away is asked again too. Then it
/// waits for every image to finish loading or fail, and reports the images, links, ids, KaTeX
/// errors, left-over TeX and the page's size, as JSON. One call does all of it because each
/// call to the browser costs the driver about a tenth of a second.
///
/// A formula KaTeX could not typeset shows in one of two ways: with mdbook-katex's default
/// `throw_on_error`, the formula stays in the page as its source, `$...$` with the dollars
/// (the builder also fails on the warning it logs); without it, KaTeX draws an element of
/// class `katex-error`. Left-over TeX is looked for in the text of each paragraph, list item,
/// cell or heading, outside code, scripts and typeset formulas.
const PROBE: &str = r#"(async () => {
  const ready = () => window.checkSiteLeaving === undefined && document.readyState === 'complete';
  if (!ready()) {
    await new Promise(done => {
      window.addEventListener('load', done, { once: true });
      setTimeout(done, 250);
    });
    if (!ready()) return '';
  }
  const images = Array.from(document.images);
  for (const img of images) { if (img.loading === 'lazy') img.loading = 'eager'; }
  await Promise.all(images.map(img => img.complete ? null : new Promise(done => {
    img.addEventListener('load', done, { once: true });
    img.addEventListener('error', done, { once: true });
    setTimeout(done, 10000);
  })));
  const skip = '.katex, .katex-display, pre, code, script, style, textarea, kbd, samp, noscript';
  const block = 'p, li, td, th, h1, h2, h3, h4, h5, h6, dt, dd, figcaption, summary, blockquote, div, body';
  const texts = new Map();
  const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
  for (let node = walker.nextNode(); node; node = walker.nextNode()) {
    const parent = node.parentElement;
    if (!parent || parent.closest(skip)) continue;
    const owner = parent.closest(block);
    texts.set(owner, (texts.get(owner) || '') + node.data);
  }
  const rawTex = [];
  for (const text of texts.values()) {
    for (const found of text.matchAll(/\$\$[\s\S]*?\$\$|\$[^$]+\$|\$\$/g)) {
      rawTex.push(found[0].replace(/\s+/g, ' ').slice(0, 100));
    }
  }
  return JSON.stringify({
    images: images.map(img => ({
      src: img.getAttribute('src') || '',
      alt: img.getAttribute('alt'),
      loaded: img.complete && img.naturalWidth > 0,
    })),
    links: Array.from(document.querySelectorAll('a[href]'), a => ({
      href: a.getAttribute('href'),
      text: a.textContent.replace(/\s+/g, ' ').trim().slice(0, 60),
    })),
    ids: Array.from(document.querySelectorAll('[id]'), el => el.id)
      .concat(Array.from(document.querySelectorAll('a[name]'), a => a.getAttribute('name'))),
    katexErrors: Array.from(document.querySelectorAll('.katex-error'), el => ({
      source: el.textContent.replace(/\s+/g, ' ').slice(0, 100),
      message: el.getAttribute('title') || '',
    })),
    rawTex,
    size: {
      width: document.documentElement.scrollWidth,
      height: document.documentElement.scrollHeight,
    },
  });
})()"#;

/// What the browser reported while a page was open: console errors, uncaught exceptions,
/// error log entries and failed loads, as sentences.
#[derive(Default)]
struct Events {
    messages: Vec<String>,
    /// Request ids and their URLs, to name the file when a load fails.
    requests: HashMap<String, String>,
}

impl Events {
    fn record(&mut self, event: &Event) {
        match event {
            Event::RuntimeConsoleAPICalled(call) => {
                use Runtime::ConsoleAPICalledEventTypeOption as Kind;
                if matches!(call.params.Type, Kind::Error | Kind::Assert) {
                    let text: Vec<String> = call.params.args.iter().map(describe).collect();
                    self.messages
                        .push(format!("console error: {}", text.join(" ")));
                }
            }
            Event::RuntimeExceptionThrown(thrown) => {
                let details = &thrown.params.exception_details;
                let what = details
                    .exception
                    .as_ref()
                    .map(describe)
                    .unwrap_or_else(|| details.text.clone());
                let place = details
                    .url
                    .as_deref()
                    .map(|url| format!(" (at {url}:{})", details.line_number + 1))
                    .unwrap_or_default();
                self.messages
                    .push(format!("uncaught exception: {what}{place}"));
            }
            Event::LogEntryAdded(added) => {
                let entry = &added.params.entry;
                // A failed load is reported below, with its URL, from the network's events.
                if entry.level == Log::LogEntryLevel::Error
                    && entry.source != Log::LogEntrySource::Network
                {
                    let url = entry
                        .url
                        .as_deref()
                        .map(|url| format!(" ({url})"))
                        .unwrap_or_default();
                    self.messages
                        .push(format!("browser error: {}{url}", entry.text));
                }
            }
            Event::NetworkRequestWillBeSent(sent) => {
                self.requests.insert(
                    sent.params.request_id.clone(),
                    sent.params.request.url.clone(),
                );
            }
            // A load cancelled because the page went on to the next one is no fault of the page.
            Event::NetworkLoadingFailed(failed) if failed.params.canceled != Some(true) => {
                let url = self
                    .requests
                    .get(&failed.params.request_id)
                    .map_or("a resource", String::as_str);
                self.messages.push(format!(
                    "failed to load {url}: {}",
                    failed.params.error_text
                ));
            }
            _ => {}
        }
    }
}

/// A console argument or an exception, as the console would print it.
fn describe(object: &Runtime::RemoteObject) -> String {
    match &object.value {
        Some(serde_json::Value::String(text)) => text.clone(),
        Some(value) => value.to_string(),
        None => object
            .description
            .clone()
            .unwrap_or_else(|| format!("{:?}", object.Type)),
    }
}

/// Opens every page of the site in headless Chromium, offline, and reports what is wrong.
///
/// Fails (an `Err`) only when it cannot check: no browser, no site, a browser that stops
/// answering. What is wrong with the pages is in [`Outcome::problems`].
pub fn run(options: &Options) -> Result<Outcome> {
    if !options.site.join("index.html").is_file() {
        bail!(
            "{} has no index.html: build the site first (`cargo run -p book -- --quick`)",
            options.site.display()
        );
    }
    let site = options
        .site
        .canonicalize()
        .with_context(|| format!("cannot find {}", options.site.display()))?;
    let chromium = find_chromium()?;
    let (pages, skipped) = pages(&site)?;
    std::fs::create_dir_all(&options.screenshots)
        .with_context(|| format!("cannot create {}", options.screenshots.display()))?;

    let profile = tempfile::Builder::new()
        .prefix("check-site-profile")
        .tempdir()
        .context("cannot create a temporary browser profile")?;
    let browser = launch(&chromium, profile.path())?;
    let tab = browser.new_tab().context("the browser opened no tab")?;
    tab.set_default_timeout(TIMEOUT);
    let events = Arc::new(Mutex::new(Events::default()));
    let recorder = Arc::clone(&events);
    tab.add_event_listener(Arc::new(move |event: &Event| {
        recorder.lock().expect("events lock").record(event);
    }))?;
    tab.call_method(Runtime::Enable(None))?;
    tab.call_method(Log::Enable(None))?;
    tab.call_method(Network::Enable {
        max_total_buffer_size: None,
        max_resource_buffer_size: None,
        max_post_data_size: None,
        report_direct_socket_traffic: None,
        enable_durable_messages: None,
    })?;

    let mut problems = Vec::new();
    let mut notes = Vec::new();
    let mut facts = BTreeMap::new();
    for page in &pages {
        *events.lock().expect("events lock") = Events::default();
        let url = file_url(&site.join(page));
        let page_started = Instant::now();
        let page_facts = open(&tab, &url).with_context(|| format!("cannot check {page}"))?;
        let shot = options.screenshots.join(screenshot_name(page));
        screenshot(&tab, &shot, page_facts.size)
            .with_context(|| format!("cannot take a screenshot of {page}"))?;
        // Events arrive on another thread. Those of the page's loading came before the
        // probe's answer, and the screenshot's round trip since has given them time to be
        // recorded.
        let messages = std::mem::take(&mut events.lock().expect("events lock").messages);
        let problem = |what: String| Problem {
            page: page.clone(),
            what,
        };
        problems.extend(messages.into_iter().map(problem));
        for image in &page_facts.images {
            let element = format!("<img src=\"{}\">", image.src);
            if !image.loaded {
                problems.push(problem(format!("{element}: the image did not load")));
            }
            if image.alt.as_deref().is_none_or(|alt| alt.trim().is_empty()) {
                let missing = problem(format!(
                    "{element}: no alt text (a reader who cannot see the figure learns \
                     nothing of it)"
                ));
                if options.alt_check {
                    problems.push(missing);
                } else {
                    notes.push(missing);
                }
            }
        }
        let demos = crate::demo_check::play(&tab, page != "print.html")
            .with_context(|| format!("cannot play the demos of {page}"))?;
        for (index, demo) in demos.iter().enumerate() {
            let name = format!("demo `{}`", demo.name);
            for what in &demo.problems {
                problems.push(problem(format!("{name}: {what}")));
            }
            if let Some(waiting) = &demo.waiting {
                let stopped = problem(format!("{name} stopped: {waiting}"));
                if options.demos_may_wait {
                    notes.push(stopped);
                } else {
                    problems.push(stopped);
                }
            }
            if let Some(rect) = demo.rect {
                let shot = options.screenshots.join(format!(
                    "demo-{index}-{}-{}",
                    demo.name,
                    screenshot_name(page)
                ));
                let clip = Page::Viewport {
                    x: rect.x,
                    y: rect.y,
                    width: rect.width.max(1.0),
                    height: rect.height.max(1.0),
                    scale: 1.0,
                };
                capture(&tab, &shot, clip)
                    .with_context(|| format!("cannot take a screenshot of {name} on {page}"))?;
            }
        }
        // The demos' console errors and exceptions too.
        std::thread::sleep(Duration::from_millis(50));
        let messages = std::mem::take(&mut events.lock().expect("events lock").messages);
        problems.extend(messages.into_iter().map(problem));
        for error in &page_facts.katex_errors {
            problems.push(problem(format!(
                "<span class=\"katex-error\">: KaTeX could not typeset `{}`: {}",
                error.source, error.message
            )));
        }
        for tex in &page_facts.raw_tex {
            problems.push(problem(format!(
                "a formula left as TeX source (KaTeX could not typeset it): {tex}"
            )));
        }
        let played = if demos.is_empty() {
            String::new()
        } else {
            let controls: usize = demos.iter().map(|demo| demo.controls).sum();
            format!(
                ", {} demo(s) played ({controls} control(s) moved)",
                demos.len()
            )
        };
        println!(
            "  {page}: {} image(s), {} link(s), {} id(s){played}, in {:.1} s with its screenshot",
            page_facts.images.len(),
            page_facts.links.len(),
            page_facts.ids.len(),
            page_started.elapsed().as_secs_f64()
        );
        facts.insert(page.clone(), page_facts);
    }

    problems.extend(broken_links(&site, &facts)?);

    let mut search_results = None;
    if let Some(word) = &options.search_word {
        *events.lock().expect("events lock") = Events::default();
        let shot = options.screenshots.join("search.png");
        match search(&tab, &file_url(&site.join("index.html")), word, &shot) {
            Ok(count) => {
                search_results = Some(count);
            }
            Err(error) => problems.push(Problem {
                page: "search".to_owned(),
                what: format!("{error:#}"),
            }),
        }
        std::thread::sleep(Duration::from_millis(100));
        let messages = std::mem::take(&mut events.lock().expect("events lock").messages);
        problems.extend(messages.into_iter().map(|what| Problem {
            page: "search".to_owned(),
            what,
        }));
    }

    Ok(Outcome {
        pages,
        skipped,
        problems: without_repeats(problems),
        notes: without_repeats(notes),
        search_results,
    })
}

/// The problems with each named once per page: mdBook puts every image in twice (the second
/// copy is the enlarged one that a click shows), and a page may link to one place twice.
fn without_repeats(problems: Vec<Problem>) -> Vec<Problem> {
    let mut seen = HashSet::new();
    problems
        .into_iter()
        .filter(|problem| seen.insert(problem.clone()))
        .collect()
}

/// Starts headless Chromium with a fresh profile and everything that would reach the network
/// turned off.
pub(crate) fn launch(chromium: &Path, profile: &Path) -> Result<Browser> {
    let args: Vec<&OsStr> = [
        "--disable-quic",
        "--no-first-run",
        "--disable-background-networking",
        "--disable-component-update",
        "--disable-sync",
        "--disable-default-apps",
        "--disable-domain-reliability",
        "--hide-scrollbars",
    ]
    .iter()
    .map(OsStr::new)
    .collect();
    let options = LaunchOptions {
        headless: true,
        sandbox: false,
        enable_gpu: false,
        window_size: Some(WINDOW),
        path: Some(chromium.to_path_buf()),
        user_data_dir: Some(profile.to_path_buf()),
        args,
        idle_browser_timeout: Duration::from_secs(120),
        ..LaunchOptions::default()
    };
    Browser::new(options).with_context(|| format!("cannot start {}", chromium.display()))
}

/// A `file://` URL for an absolute path, with the characters URLs cannot hold escaped.
pub(crate) fn file_url(path: &Path) -> String {
    let mut url = String::from("file://");
    for component in path.components() {
        match component {
            Component::RootDir => {}
            Component::Normal(name) => {
                url.push('/');
                for byte in name.to_string_lossy().bytes() {
                    if byte.is_ascii_alphanumeric() || b"-._~!$&'()*+,;=:@".contains(&byte) {
                        url.push(byte as char);
                    } else {
                        url.push_str(&format!("%{byte:02X}"));
                    }
                }
            }
            _ => {}
        }
    }
    url
}

/// Loads a page and runs the probe on it, once the page has loaded (the probe says when).
fn open(tab: &Tab, url: &str) -> Result<PageFacts> {
    tab.evaluate("window.checkSiteLeaving = true", false)?;
    tab.navigate_to(url)?;
    let started = Instant::now();
    loop {
        // While the new page replaces the old one, evaluating may fail: that is "not yet".
        if let Ok(result) = tab.evaluate(PROBE, true) {
            match result.value {
                Some(serde_json::Value::String(json)) if json.is_empty() => {}
                Some(serde_json::Value::String(json)) => {
                    return serde_json::from_str(&json)
                        .context("the page's probe returned a report that cannot be read");
                }
                _ => bail!("the page's probe returned no report: {result:?}"),
            }
        }
        if started.elapsed() > TIMEOUT {
            bail!("the page did not finish loading in {} s", TIMEOUT.as_secs());
        }
    }
}

/// A PNG of the whole page (up to [`MAX_SCREENSHOT_HEIGHT`]), of `size` in CSS pixels, written
/// to `file`.
fn screenshot(tab: &Tab, file: &Path, size: PageSize) -> Result<()> {
    let clip = Page::Viewport {
        x: 0.0,
        y: 0.0,
        width: size.width.max(f64::from(WINDOW.0)),
        height: size.height.clamp(1.0, MAX_SCREENSHOT_HEIGHT),
        scale: 1.0,
    };
    capture(tab, file, clip)
}

/// A PNG of the part `clip` of the page, written to `file`.
fn capture(tab: &Tab, file: &Path, clip: Page::Viewport) -> Result<()> {
    let png = tab
        .call_method(Page::CaptureScreenshot {
            format: Some(Page::CaptureScreenshotFormatOption::Png),
            quality: None,
            clip: Some(clip),
            from_surface: Some(true),
            capture_beyond_viewport: Some(true),
            // Encoded fast rather than small: the shots are looked through, not kept.
            optimize_for_speed: Some(true),
        })?
        .data;
    let bytes = BASE64_STANDARD
        .decode(png)
        .context("the browser sent a screenshot that is not base64")?;
    std::fs::write(file, bytes).with_context(|| format!("cannot write {}", file.display()))
}

/// Searches from the page at `url` as a reader does, in the page itself: clicks the search
/// button, puts `word` in the search box, lets go of its last key (mdBook searches on `keyup`),
/// and waits for the line mdBook writes above the results ("3 search results for ...", or "No
/// search results for ..."), which stays empty until the search index has loaded. Answers, as
/// JSON, what is missing or how many results there are and the page's size. One call to the
/// browser does all of it, because each call costs the driver about a tenth of a second.
const SEARCH: &str = r#"(async (word, timeout) => {
  const toggle = document.getElementById('mdbook-search-toggle');
  if (!toggle) return JSON.stringify({ missing: 'button' });
  toggle.click();
  const bar = document.getElementById('mdbook-searchbar');
  if (!bar || bar.offsetParent === null) return JSON.stringify({ missing: 'box' });
  bar.focus();
  bar.value = word;
  bar.dispatchEvent(new KeyboardEvent('keyup', { key: word.slice(-1), bubbles: true }));
  const header = () => document.getElementById('mdbook-searchresults-header')?.textContent ?? '';
  const started = Date.now();
  while (header() === '') {
    if (Date.now() - started > timeout) return JSON.stringify({ missing: 'header' });
    await new Promise(done => setTimeout(done, 20));
  }
  return JSON.stringify({
    said: header(),
    count: document.querySelectorAll('#mdbook-searchresults > li').length,
    size: {
      width: document.documentElement.scrollWidth,
      height: document.documentElement.scrollHeight,
    },
  });
})"#;

/// What [`SEARCH`] answers.
#[derive(Deserialize)]
struct SearchAnswer {
    /// What the page lacks: the search `button`, the search `box`, or the `header` line of
    /// results within the time allowed.
    missing: Option<String>,
    said: Option<String>,
    count: Option<usize>,
    size: Option<PageSize>,
}

/// Opens the page at `url`, searches it for `word` ([`SEARCH`]) and returns how many results
/// there are, with a screenshot of them written to `shot`.
fn search(tab: &Tab, url: &str, word: &str, shot: &Path) -> Result<usize> {
    open(tab, url)?;
    let call = format!(
        "{SEARCH}({}, {})",
        serde_json::to_string(word)?,
        TIMEOUT.as_millis()
    );
    let answer = tab.evaluate(&call, true)?;
    let Some(serde_json::Value::String(answer)) = answer.value else {
        bail!("the search of index.html returned no answer: {answer:?}");
    };
    let answer: SearchAnswer = serde_json::from_str(&answer)
        .context("the search returned an answer that cannot be read")?;
    match answer.missing.as_deref() {
        Some("button") => bail!(
            "index.html has no search button (#mdbook-search-toggle): is search turned on in \
             book.toml ([output.html.search]) and mdbook-driver built with its `search` feature?"
        ),
        Some("box") => bail!("the search button of index.html opened no search box"),
        Some(_) => bail!(
            "typing \"{word}\" into the search box of index.html showed no results within {} s: \
             did searchindex.js load?",
            TIMEOUT.as_secs()
        ),
        None => {}
    }
    let count = answer.count.unwrap_or(0);
    if count == 0 {
        bail!(
            "typing \"{word}\" into the search box of index.html showed no results; the page \
             says \"{}\"",
            answer.said.unwrap_or_default()
        );
    }
    let size = answer
        .size
        .context("the search of index.html did not report the page's size")?;
    screenshot(tab, shot, size)?;
    Ok(count)
}

/// Every link, on every page opened, to a file that does not exist or to a fragment that is
/// not an id on its page.
fn broken_links(site: &Path, facts: &BTreeMap<String, PageFacts>) -> Result<Vec<Problem>> {
    let mut problems = Vec::new();
    let mut read_ids: HashMap<String, HashSet<String>> = HashMap::new();
    for (page, page_facts) in facts {
        for link in &page_facts.links {
            let element = format!("<a href=\"{}\">{}</a>", link.href, link.text);
            let problem = |what: String| Problem {
                page: page.clone(),
                what: format!("{element}: {what}"),
            };
            let (file, fragment) = match resolve_link(page, &link.href) {
                LinkTarget::Elsewhere => continue,
                LinkTarget::OutsideSite => {
                    problems.push(problem("leads out of the site".to_owned()));
                    continue;
                }
                LinkTarget::Local { file, fragment } => (file, fragment),
            };
            let path = site.join(&file);
            if file.ends_with('/') || path.is_dir() {
                problems.push(problem(format!(
                    "{file} is a directory: opened from disk, a reader sees a file listing"
                )));
                continue;
            }
            if !path.is_file() {
                problems.push(problem(format!("no such file in the site: {file}")));
                continue;
            }
            let Some(fragment) = fragment.filter(|f| !f.is_empty()) else {
                continue;
            };
            let ids = match facts.get(&file) {
                Some(target) => target.ids.iter().cloned().collect(),
                None if file.ends_with(".html") => match read_ids.get(&file) {
                    Some(ids) => ids.clone(),
                    None => {
                        let text = std::fs::read_to_string(&path)
                            .with_context(|| format!("cannot read {}", path.display()))?;
                        let ids = ids_in_html(&text);
                        read_ids.insert(file.clone(), ids.clone());
                        ids
                    }
                },
                // A fragment of an image or a stylesheet: nothing to check.
                None => continue,
            };
            if !ids.contains(&fragment) {
                problems.push(problem(format!(
                    "{file} has no element with id \"{fragment}\""
                )));
            }
        }
    }
    Ok(problems)
}

#[cfg(test)]
mod tests {
    use std::io::Write;

    use super::*;

    #[test]
    fn links_resolve_like_a_browser_from_disk() {
        let local = |file: &str, fragment: Option<&str>| LinkTarget::Local {
            file: file.to_owned(),
            fragment: fragment.map(str::to_owned),
        };
        assert_eq!(
            resolve_link("ch01.html", "ch02.html"),
            local("ch02.html", None)
        );
        assert_eq!(
            resolve_link("ch01.html", "#mirrors"),
            local("ch01.html", Some("mirrors"))
        );
        assert_eq!(
            resolve_link("ch01.html", "ch02.html#a%C3%A9?"),
            local("ch02.html", Some("aé?"))
        );
        assert_eq!(
            resolve_link("ch01.html", "ch02.html?search=x#top"),
            local("ch02.html", Some("top"))
        );
        assert_eq!(
            resolve_link("part/page.html", "../figures/a%20b.png"),
            local("figures/a b.png", None)
        );
        assert_eq!(
            resolve_link("part/page.html", "./other.html"),
            local("part/other.html", None)
        );
        assert_eq!(
            resolve_link("page.html", "figures/"),
            local("figures/", None)
        );
        assert_eq!(resolve_link("page.html", ""), local("page.html", None));
        assert_eq!(
            resolve_link("page.html", "../up.html"),
            LinkTarget::OutsideSite
        );
        assert_eq!(
            resolve_link("page.html", "/etc/passwd"),
            LinkTarget::OutsideSite
        );
        for elsewhere in [
            "https://doi.org/10.1145/964965.808590",
            "http://example.com/a.html",
            "//cdn.example.com/katex.css",
            "mailto:someone@example.com",
            "javascript:void(0)",
        ] {
            assert_eq!(
                resolve_link("page.html", elsewhere),
                LinkTarget::Elsewhere,
                "{elsewhere}"
            );
        }
    }

    #[test]
    fn percent_decoding_keeps_what_is_malformed() {
        assert_eq!(percent_decode("a%20b%2Fc"), "a b/c");
        assert_eq!(percent_decode("100%"), "100%");
        assert_eq!(percent_decode("%zz%4"), "%zz%4");
    }

    #[test]
    fn screenshots_are_named_after_their_page() {
        assert_eq!(screenshot_name("ch01-whitted.html"), "ch01-whitted.png");
        assert_eq!(screenshot_name("part/intro.html"), "part__intro.png");
    }

    #[test]
    fn ids_are_read_from_html_text() {
        let ids = ids_in_html(r#"<h2 id="mirrors">M</h2><a name='old'></a><p data-id="no">"#);
        let expected: HashSet<String> = ["mirrors", "old"].map(str::to_owned).into();
        assert_eq!(ids, expected);
    }

    #[test]
    fn file_urls_escape_what_urls_cannot_hold() {
        assert_eq!(
            file_url(Path::new("/work/my site/a#b.html")),
            "file:///work/my%20site/a%23b.html"
        );
    }

    #[test]
    fn every_html_page_is_found_but_the_not_found_page() {
        let site = tempfile::tempdir().unwrap();
        for file in ["index.html", "404.html", "part/a.html", "style.css"] {
            let path = site.path().join(file);
            std::fs::create_dir_all(path.parent().unwrap()).unwrap();
            std::fs::write(path, "").unwrap();
        }
        let (pages, skipped) = pages(site.path()).unwrap();
        assert_eq!(pages, ["index.html", "part/a.html"]);
        assert_eq!(skipped.len(), 1);
        assert_eq!(skipped[0].page, "404.html");
    }

    #[test]
    fn repeated_problems_are_named_once_per_page() {
        let problem = |page: &str| Problem {
            page: page.to_owned(),
            what: "<img src=\"a.png\">: no alt text".to_owned(),
        };
        let kept = without_repeats(vec![
            problem("a.html"),
            problem("a.html"),
            problem("b.html"),
        ]);
        assert_eq!(kept, [problem("a.html"), problem("b.html")]);
    }

    #[test]
    fn broken_links_and_anchors_are_found_from_the_pages_facts() {
        let site = tempfile::tempdir().unwrap();
        std::fs::write(site.path().join("a.html"), "").unwrap();
        std::fs::write(site.path().join("skipped.html"), r#"<h1 id="kept">"#).unwrap();
        std::fs::create_dir(site.path().join("figures")).unwrap();
        let link = |href: &str| LinkFacts {
            href: href.to_owned(),
            text: "text".to_owned(),
        };
        let facts = PageFacts {
            images: Vec::new(),
            links: [
                "#here",
                "a.html#here",
                "skipped.html#kept",
                "https://example.com/#nothing",
                "#gone",
                "missing.html",
                "skipped.html#lost",
                "figures/",
                "../out.html",
            ]
            .map(link)
            .into(),
            ids: vec!["here".to_owned()],
            katex_errors: Vec::new(),
            raw_tex: Vec::new(),
            size: PageSize {
                width: 1280.0,
                height: 900.0,
            },
        };
        let problems = broken_links(site.path(), &BTreeMap::from([("a.html".to_owned(), facts)]))
            .unwrap()
            .into_iter()
            .map(|p| p.what)
            .collect::<Vec<_>>();
        assert_eq!(
            problems,
            [
                "<a href=\"#gone\">text</a>: a.html has no element with id \"gone\"",
                "<a href=\"missing.html\">text</a>: no such file in the site: missing.html",
                "<a href=\"skipped.html#lost\">text</a>: skipped.html has no element with id \
                 \"lost\"",
                "<a href=\"figures/\">text</a>: figures/ is a directory: opened from disk, a \
                 reader sees a file listing",
                "<a href=\"../out.html\">text</a>: leads out of the site",
            ]
        );
    }

    #[test]
    fn a_missing_browser_is_named_with_how_to_install_it() {
        let empty = tempfile::tempdir().unwrap();
        let error = find_chromium_in(None, Some(empty.path().into())).unwrap_err();
        assert!(
            error.to_string().contains("apt-get install chromium"),
            "{error}"
        );
        let error = find_chromium_in(Some("/no/such/chromium".into()), None).unwrap_err();
        assert!(error.to_string().contains("$CHROMIUM"), "{error}");
    }

    #[cfg(unix)]
    #[test]
    fn the_browser_is_looked_for_on_the_path_in_order() {
        use std::os::unix::fs::PermissionsExt;
        let dir = tempfile::tempdir().unwrap();
        for name in ["google-chrome", "chromium-browser", "not-executable"] {
            let program = dir.path().join(name);
            std::fs::write(&program, "#!/bin/sh\n").unwrap();
            let mode = if name == "not-executable" {
                0o644
            } else {
                0o755
            };
            std::fs::set_permissions(&program, std::fs::Permissions::from_mode(mode)).unwrap();
        }
        let path = Some(dir.path().as_os_str().to_owned());
        assert_eq!(
            find_chromium_in(None, path.clone()).unwrap(),
            dir.path().join("chromium-browser")
        );
        assert_eq!(
            find_chromium_in(Some("google-chrome".into()), path.clone()).unwrap(),
            dir.path().join("google-chrome")
        );
        assert!(find_chromium_in(Some("not-executable".into()), path).is_err());
    }

    /// Whether Chromium is here to run a browser test. Without it the test is skipped, saying
    /// so on the terminal (past the test harness's capture), unless `WORKBOOK_REQUIRE_BROWSER`
    /// is set (CI sets it), when a missing browser fails the test.
    fn browser_is_here(test: &str) -> bool {
        match find_chromium() {
            Ok(_) => true,
            Err(error) if std::env::var_os("WORKBOOK_REQUIRE_BROWSER").is_some() => {
                panic!("{test} needs Chromium, and WORKBOOK_REQUIRE_BROWSER is set: {error:#}")
            }
            Err(error) => {
                let _ = writeln!(std::io::stderr(), "skipped {test}: {error:#}");
                false
            }
        }
    }

    /// A valid 1 x 1 PNG: one black pixel.
    const DOT_PNG: &[u8] = &[
        0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44,
        0x52, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x01, 0x08, 0x00, 0x00, 0x00, 0x00, 0x3a,
        0x7e, 0x9b, 0x55, 0x00, 0x00, 0x00, 0x0a, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9c, 0x63, 0x60,
        0x00, 0x00, 0x00, 0x02, 0x00, 0x01, 0x48, 0xaf, 0xa4, 0x71, 0x00, 0x00, 0x00, 0x00, 0x49,
        0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82,
    ];

    fn page(title: &str, body: &str) -> String {
        format!(
            "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\
             <title>{title}</title></head>\n<body>\n<h1 id=\"top\">{title}</h1>\n{body}\n\
             </body></html>\n"
        )
    }

    /// Each page of a hand-made site has one problem (the good ones none), and the check names
    /// each on its own page.
    #[test]
    fn the_browser_check_finds_each_kind_of_problem_on_its_page() {
        if !browser_is_here("the_browser_check_finds_each_kind_of_problem_on_its_page") {
            return;
        }
        let site = tempfile::tempdir().unwrap();
        let shots = tempfile::tempdir().unwrap();
        std::fs::create_dir(site.path().join("figures")).unwrap();
        std::fs::write(site.path().join("figures/dot.png"), DOT_PNG).unwrap();
        let pages = [
            (
                "index.html",
                "<p><a href=\"good.html\">good</a> <a href=\"good.html#money\">money</a></p>",
            ),
            (
                "good.html",
                "<p id=\"money\">A dot <img src=\"figures/dot.png\" alt=\"A black dot\"> costs \
                 $5, a <a href=\"#top\">link</a> to the <a href=\"index.html#top\">top</a>, \
                 <a href=\"https://example.com/#x\">away</a>, <span class=\"katex\">x</span>.</p>\
                 <pre><code>echo $HOME $PATH</code></pre>\
                 <script>console.log('fine'); console.warn('only a warning');</script>",
            ),
            (
                "missing-image.html",
                "<p><img src=\"figures/missing.png\" alt=\"Not there\"></p>",
            ),
            (
                "no-alt.html",
                "<p><img src=\"figures/dot.png\"><img src=\"./figures/dot.png\" alt=\" \"></p>",
            ),
            (
                "katex-error.html",
                "<p><span class=\"katex-error\" title=\"ParseError: KaTeX parse error: \
                 Expected '}', got 'EOF' at end of input\">\\frac{1}{</span></p>",
            ),
            ("raw-tex.html", "<p>The sum $\\sum_{i=1^N$ of it.</p>"),
            (
                "console-error.html",
                "<script>console.error('boom from the page');</script>",
            ),
            ("throws.html", "<script>throw new Error('kaput');</script>"),
            (
                "broken-link.html",
                "<p><a href=\"nowhere.html\">gone</a></p>",
            ),
            (
                "broken-anchor.html",
                "<p><a href=\"good.html#nowhere\">gone</a></p>",
            ),
        ];
        for (name, body) in pages {
            std::fs::write(site.path().join(name), page(name, body)).unwrap();
        }

        let options = Options {
            site: site.path().to_owned(),
            screenshots: shots.path().to_owned(),
            alt_check: true,
            search_word: None,
            demos_may_wait: false,
        };
        let outcome = run(&options).unwrap();

        let on = |name: &str| -> Vec<String> {
            outcome
                .problems
                .iter()
                .filter(|p| p.page == name)
                .map(|p| p.what.clone())
                .collect()
        };
        let listing = outcome
            .problems
            .iter()
            .map(ToString::to_string)
            .collect::<Vec<_>>()
            .join("\n");
        let has = |name: &str, words: &[&str]| {
            assert!(
                on(name).iter().any(|p| words.iter().all(|w| p.contains(w))),
                "no problem on {name} with {words:?}; found:\n{listing}"
            );
        };
        assert_eq!(on("index.html"), Vec::<String>::new(), "{listing}");
        assert_eq!(on("good.html"), Vec::<String>::new(), "{listing}");
        has(
            "missing-image.html",
            &["<img src=\"figures/missing.png\">", "did not load"],
        );
        has("missing-image.html", &["failed to load", "missing.png"]);
        has(
            "no-alt.html",
            &["<img src=\"figures/dot.png\">", "no alt text"],
        );
        has(
            "no-alt.html",
            &["<img src=\"./figures/dot.png\">", "no alt text"],
        );
        assert_eq!(on("no-alt.html").len(), 2, "{listing}");
        has(
            "katex-error.html",
            &["katex-error", "\\frac{1}{", "ParseError"],
        );
        has("raw-tex.html", &["TeX source", "$\\sum_{i=1^N$"]);
        has(
            "console-error.html",
            &["console error", "boom from the page"],
        );
        has("throws.html", &["uncaught exception", "kaput"]);
        has(
            "broken-link.html",
            &["<a href=\"nowhere.html\">gone</a>", "no such file"],
        );
        has(
            "broken-anchor.html",
            &[
                "<a href=\"good.html#nowhere\">gone</a>",
                "no element with id \"nowhere\"",
            ],
        );
        assert_eq!(outcome.pages.len(), pages.len());
        for (name, _) in pages {
            let shot = shots.path().join(screenshot_name(name));
            let bytes = std::fs::read(&shot).unwrap();
            assert!(bytes.starts_with(b"\x89PNG"), "{}", shot.display());
        }

        // With the alt check off, images without alt text are notes, not problems; and a site
        // without mdBook's search box fails the search with a sentence that says so. (A site
        // of the pages that matter here: the others were checked above.)
        let small = tempfile::tempdir().unwrap();
        std::fs::create_dir(small.path().join("figures")).unwrap();
        std::fs::write(small.path().join("figures/dot.png"), DOT_PNG).unwrap();
        for (name, body) in pages
            .iter()
            .filter(|(name, _)| ["index.html", "good.html", "no-alt.html"].contains(name))
        {
            std::fs::write(small.path().join(name), page(name, body)).unwrap();
        }
        let lenient = run(&Options {
            site: small.path().to_owned(),
            alt_check: false,
            search_word: Some("dot".to_owned()),
            demos_may_wait: false,
            ..options
        })
        .unwrap();
        assert_eq!(lenient.pages.len(), 3);
        assert!(lenient.problems.iter().all(|p| p.page != "no-alt.html"));
        assert_eq!(lenient.notes.len(), 2);
        let search = lenient.problems.iter().find(|p| p.page == "search");
        assert!(
            search.is_some_and(|p| p.what.contains("no search button")),
            "{search:?}"
        );
    }

    /// A small book built by the builder itself: a formula mdbook-katex cannot typeset stays in
    /// the page as its TeX source, which the check finds, and search works from disk.
    /// A WebAssembly module in the demos' shape whose first call aborts, as a panic does,
    /// leaving `message` in its text buffer.
    fn panicking_module(message: &str) -> Vec<u8> {
        fn section(id: u8, content: &[u8]) -> Vec<u8> {
            [&[id, content.len() as u8][..], content].concat()
        }
        fn named(name: &str, kind: u8, index: u8) -> Vec<u8> {
            [&[name.len() as u8][..], name.as_bytes(), &[kind, index]].concat()
        }
        let message = message.as_bytes();
        assert!(message.len() < 100, "lengths are written as single bytes");
        let returns = |value: u8| vec![4u8, 0, 0x41, value, 0x0b];
        let exports = [
            named("memory", 2, 0),
            named("init", 0, 0),
            named("warp_count", 0, 1),
            named("panic_ptr", 0, 2),
            named("panic_len", 0, 3),
            named("numbers_ptr", 0, 4),
            named("numbers_len", 0, 5),
        ];
        let code = [
            vec![6u8],
            vec![2, 0, 0x0b],
            vec![3, 0, 0x00, 0x0b], // unreachable: the abort of a panic
            returns(16),
            returns(message.len() as u8),
            returns(0),
            returns(0),
        ]
        .concat();
        let data = [&[1u8, 0, 0x41, 16, 0x0b, message.len() as u8][..], message].concat();
        [
            &b"\0asm\x01\0\0\0"[..],
            &section(1, &[2, 0x60, 0, 0, 0x60, 0, 1, 0x7f]),
            &section(3, &[6, 0, 1, 1, 1, 1, 1]),
            &section(5, &[1, 0, 1]),
            &section(7, &[&[exports.len() as u8][..], &exports.concat()].concat()),
            &section(10, &code),
            &section(11, &data),
        ]
        .concat()
    }

    /// A demo whose module is missing or whose code panics fails the check, naming the demo
    /// and the panic's words; one stopped by an exercise not written yet fails the workbook's
    /// site but is only a note on a student's.
    #[test]
    fn a_demo_without_its_module_or_that_panics_is_a_problem() {
        if !browser_is_here("a_demo_without_its_module_or_that_panics_is_a_problem") {
            return;
        }
        let site = tempfile::tempdir().unwrap();
        std::fs::write(
            site.path().join("demos.js"),
            include_str!("../theme/demos.js"),
        )
        .unwrap();
        let with_module = |message: &str| {
            format!(
                "<div class=\"demo\" data-demo=\"warps\"></div>\
                 <script>window.BOOK_DEMOS_WASM = \"{}\";</script>\
                 <script src=\"demos.js\"></script>",
                BASE64_STANDARD.encode(panicking_module(message))
            )
        };
        let pages = [
            ("index.html", String::new()),
            (
                "no-module.html",
                "<div class=\"demo\" data-demo=\"warps\"></div><script src=\"demos.js\"></script>"
                    .to_owned(),
            ),
            ("panics.html", with_module("index out of bounds in warps")),
            (
                "waits.html",
                with_module("this demo needs ch02-disc-polar (not written yet)"),
            ),
        ];
        for (name, body) in &pages {
            std::fs::write(site.path().join(name), page(name, body)).unwrap();
        }
        let check = |demos_may_wait| {
            let shots = tempfile::tempdir().unwrap();
            run(&Options {
                site: site.path().to_owned(),
                screenshots: shots.path().to_owned(),
                alt_check: true,
                search_word: None,
                demos_may_wait,
            })
            .unwrap()
        };
        let outcome = check(false);
        let listing = outcome
            .problems
            .iter()
            .map(ToString::to_string)
            .collect::<Vec<_>>()
            .join("\n");
        for (page, words) in [
            ("no-module.html", "the demos' module is missing"),
            ("panics.html", "index out of bounds in warps"),
            ("waits.html", "ch02-disc-polar (not written yet)"),
        ] {
            assert!(
                outcome.problems.iter().any(|p| p.page == page
                    && p.what.contains("demo `warps`")
                    && p.what.contains(words)),
                "{page}: {listing}"
            );
        }
        assert_eq!(outcome.problems.len(), 3, "{listing}");

        // On the student's own site, the exercise not written yet is a note.
        let outcome = check(true);
        assert_eq!(outcome.problems.len(), 2, "{:?}", outcome.problems);
        assert!(
            outcome.notes.iter().any(|n| n.page == "waits.html"),
            "{:?}",
            outcome.notes
        );
    }

    #[test]
    fn a_real_book_with_a_broken_formula_fails_and_its_search_finds_words() {
        if !browser_is_here("a_real_book_with_a_broken_formula_fails_and_its_search_finds_words") {
            return;
        }
        let workspace = tempfile::tempdir().unwrap();
        let book = workspace.path().join("book");
        let theme = book.join(crate::katex_offline::KATEX_DIR);
        let our_theme = crate::workspace::root()
            .join("book")
            .join(crate::katex_offline::KATEX_DIR);
        std::fs::create_dir_all(theme.join("fonts")).unwrap();
        for entry in std::fs::read_dir(our_theme.join("fonts")).unwrap() {
            let font = entry.unwrap().path();
            std::fs::copy(&font, theme.join("fonts").join(font.file_name().unwrap())).unwrap();
        }
        for file in ["katex.min.css", "LICENSE"] {
            std::fs::copy(our_theme.join(file), theme.join(file)).unwrap();
        }
        let our_config =
            std::fs::read_to_string(crate::workspace::root().join("book/book.toml")).unwrap();
        std::fs::write(book.join("book.toml"), our_config).unwrap();
        // The other stylesheets and the script the configuration names.
        for file in ["lab-report.css", "demos.css", "demos.js"] {
            std::fs::copy(
                crate::workspace::root().join("book/theme").join(file),
                book.join("theme").join(file),
            )
            .unwrap();
        }
        // A workspace without chapters or exercises, for the exercise preprocessor.
        std::fs::write(book.join("exercises.toml"), "").unwrap();
        for dir in ["common", "workbench", "chapters"] {
            std::fs::create_dir(workspace.path().join(dir)).unwrap();
        }
        std::fs::create_dir(book.join("src")).unwrap();
        std::fs::write(
            book.join("src/SUMMARY.md"),
            "# Summary\n\n[Light](light.md)\n\n- [Glass](glass.md)\n",
        )
        .unwrap();
        std::fs::write(
            book.join("src/light.md"),
            "# Light\n\nThe Fresnel equations give the share $F(\\theta)$ reflected.\n\n\
             See [glass](glass.md#refraction).\n",
        )
        .unwrap();
        std::fs::write(
            book.join("src/glass.md"),
            "# Glass\n\n## Refraction\n\nSnell's law, $n_1 \\sin\\theta_1 = n_2 \\sin\\theta_2$, \
             and a broken one: $\\frac{1}{$ here.\n",
        )
        .unwrap();
        // The builder counts KaTeX's warning as a problem only when its log is installed (by
        // `main`, or by another test); either way the pages are written.
        if let Err(error) = crate::site::build(&book) {
            assert!(
                format!("{error:#}").contains("would leave broken pages"),
                "{error:#}"
            );
        }
        let site = book.join("site");
        let glass = std::fs::read_to_string(site.join("glass.html")).unwrap();
        assert!(glass.contains("$\\frac{1}{$"), "{glass}");

        let shots = tempfile::tempdir().unwrap();
        let outcome = run(&Options {
            site: site.clone(),
            screenshots: shots.path().to_owned(),
            alt_check: true,
            search_word: Some("Fresnel".to_owned()),
            demos_may_wait: false,
        })
        .unwrap();
        let listing = outcome
            .problems
            .iter()
            .map(ToString::to_string)
            .collect::<Vec<_>>()
            .join("\n");
        let broken: Vec<&str> = outcome.problems.iter().map(|p| p.page.as_str()).collect();
        assert_eq!(broken, ["glass.html", "print.html"], "{listing}");
        assert!(
            outcome.problems[0].what.contains("$\\frac{1}{$"),
            "{listing}"
        );
        assert!(outcome.search_results.is_some_and(|n| n > 0), "{listing}");
        assert!(shots.path().join("search.png").is_file());

        // A search for a word the book does not hold fails, with a sentence that says so (the
        // search alone: the pages were checked above).
        let profile = tempfile::tempdir().unwrap();
        let browser = launch(&find_chromium().unwrap(), profile.path()).unwrap();
        let tab = browser.new_tab().unwrap();
        tab.set_default_timeout(TIMEOUT);
        let index = file_url(&site.canonicalize().unwrap().join("index.html"));
        let nothing = search(
            &tab,
            &index,
            "Quaternion",
            &shots.path().join("nothing.png"),
        )
        .expect_err("a search that finds nothing is a problem");
        assert!(
            format!("{nothing:#}").contains("showed no results"),
            "{nothing:#}"
        );
    }
}
