//! mdBook's messages, shown and counted.
//!
//! mdBook reports trouble while building, such as an `{{#include}}` whose file or anchor does not
//! exist, through the `tracing` crate, and then carries on, leaving the raw text in the page;
//! mdbook-katex does the same with a formula it cannot typeset. The builder prints those
//! messages and counts the serious ones, so that a broken page fails the build instead of
//! reaching readers.

use std::io::IsTerminal;
use std::sync::atomic::{AtomicUsize, Ordering};

use tracing::{Event, Level, Metadata, Subscriber};
use tracing_subscriber::filter::{EnvFilter, filter_fn};
use tracing_subscriber::layer::{Context, SubscriberExt};
use tracing_subscriber::util::SubscriberInitExt;
use tracing_subscriber::{Layer, fmt};

static PROBLEMS: AtomicUsize = AtomicUsize::new(0);

/// Counts every event it is shown.
struct ProblemCounter;

impl<S: Subscriber> Layer<S> for ProblemCounter {
    fn on_event(&self, _event: &Event<'_>, _context: Context<'_, S>) {
        PROBLEMS.fetch_add(1, Ordering::Relaxed);
    }
}

/// Whether an event means a page is broken: any error, and any warning from KaTeX (which warns
/// when it leaves a formula it cannot typeset as raw TeX on the page).
fn breaks_a_page(metadata: &Metadata<'_>) -> bool {
    match *metadata.level() {
        Level::ERROR => true,
        Level::WARN => metadata.target().starts_with("mdbook_katex"),
        _ => false,
    }
}

/// Prints warnings and errors on stderr (set `RUST_LOG=info` to see more) and counts the
/// problems that break a page.
pub fn install() {
    let shown = EnvFilter::try_from_default_env().unwrap_or_else(|_| EnvFilter::new("warn"));
    let printer = fmt::layer()
        .with_writer(std::io::stderr)
        .with_ansi(std::io::stderr().is_terminal())
        .without_time();
    // Another subscriber already installed (only possible in tests) is fine: keep it.
    let _ = tracing_subscriber::registry()
        .with(printer.with_filter(shown))
        .with(ProblemCounter.with_filter(filter_fn(breaks_a_page)))
        .try_init();
}

/// How many page-breaking problems mdBook and its preprocessors have reported since
/// [`install`].
pub fn problems_so_far() -> usize {
    PROBLEMS.load(Ordering::Relaxed)
}
