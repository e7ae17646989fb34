//! Panics become messages: a demo that reaches an exercise not written yet (its stub panics
//! with "not written yet") or a bug shows the message on its canvas instead of breaking the
//! page.
//!
//! WebAssembly built for `wasm32-unknown-unknown` aborts on a panic, it cannot unwind; the
//! panic hook runs first, though. So the hook keeps the message in a buffer of its own, and the
//! page, which catches the abort as a JavaScript exception, reads it from there.

use std::sync::Once;

use crate::buffers;

/// Installs the hook that keeps a panic's message for the page. Called by every export; only
/// the first call does anything.
pub fn install_hook() {
    static HOOK: Once = Once::new();
    HOOK.call_once(|| {
        // The default hook still runs after: natively it prints (tests); in a page it has
        // nowhere to print.
        let default = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            let message = info
                .payload()
                .downcast_ref::<String>()
                .map(String::as_str)
                .or_else(|| info.payload().downcast_ref::<&str>().copied())
                .unwrap_or("a panic without a message");
            buffers::set_panic(message);
            default(info);
        }));
    });
}

/// Runs `work` with the hook installed.
pub fn run<T>(work: impl FnOnce() -> T) -> T {
    install_hook();
    work()
}

/// Gets the hook ready before any demo runs, so that even a first call that panics leaves its
/// message.
#[unsafe(no_mangle)]
pub extern "C" fn init() {
    install_hook();
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_panic_leaves_its_message_for_the_page() {
        let caught = std::panic::catch_unwind(|| run(|| panic!("ch02-disc-polar stopped")));
        assert!(caught.is_err());
        let message = crate::buffers::PANIC.with(|cell| cell.borrow().clone());
        assert_eq!(message, "ch02-disc-polar stopped");
    }
}
