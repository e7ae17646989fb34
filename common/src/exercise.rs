//! What stands in an exercise's place in the student edition, until the student writes it.
//!
//! `book student` replaces each exercise's solution by a call to [`todo`] with the exercise's
//! name and first hint. It diverges like `todo!()`, but says what a student needs to read: not
//! "not yet implemented" from deep inside a render, but which exercise the check (or program)
//! needs that is still to write.
//!
//! A stub reached by a render is reached once per pixel, on every thread of the pool. Threads
//! that libtest does not capture would print the same panic thousands of times, so a
//! nameless thread (a pool's worker) reports each exercise once per process and then unwinds
//! quietly; the panic still travels to the thread that started the work, which fails as
//! before. A named thread (the test's own, whose output libtest shows under the test's name, or
//! a program's `main`) always reports it.

use std::collections::HashSet;
use std::sync::Mutex;

/// The exercises a nameless thread has reported in this process.
static REPORTED: Mutex<Option<HashSet<String>>> = Mutex::new(None);

/// Stands in for the solution of an exercise not written yet. `message` is the exercise's
/// name, a colon and its first hint: `"ch01-reflect: Which part of d does a mirror change?"`.
#[track_caller]
pub fn todo(message: &str) -> ! {
    let text = not_written(message, in_a_test());
    let named = std::thread::current().name().is_some();
    if !named && !first_report(message) {
        std::panic::resume_unwind(Box::new(text));
    }
    panic!("{text}")
}

/// Whether a panic's `message` is a stub's: a check that catches the student's panics to say
/// what an edge case needs passes a stub's on as it is, since the student has nothing to fix
/// in the code it called, only an exercise to write.
pub fn is_not_written(message: &str) -> bool {
    message.contains(NOT_WRITTEN)
}

/// What every stub's words hold.
const NOT_WRITTEN: &str = " (not written yet)";

/// Passes a caught panic on unless it is a stub's: for a check that catches the student's
/// panics with `catch_unwind`, so that a stub reached on the way still fails the check in its
/// own words.
pub fn resume_if_not_written(
    payload: Box<dyn std::any::Any + Send>,
) -> Box<dyn std::any::Any + Send> {
    let message = payload
        .downcast_ref::<String>()
        .map(String::as_str)
        .or_else(|| payload.downcast_ref::<&str>().copied());
    if message.is_some_and(is_not_written) {
        std::panic::resume_unwind(payload);
    }
    payload
}

/// The words a stub says: which exercise is missing, for whom, and its hint.
fn not_written(message: &str, in_a_test: bool) -> String {
    let (name, hint) = match message.split_once(':') {
        Some((name, hint)) => (name.trim(), hint.trim()),
        None => (message.trim(), ""),
    };
    let who = if in_a_test {
        "this check"
    } else {
        "this program"
    };
    let mut text = format!("{who} needs {name}{NOT_WRITTEN}");
    if !hint.is_empty() {
        text.push_str(&format!("; a hint for it: {hint}"));
    }
    text.push_str(&format!(
        "\n  Write it, or put the reference one in with `cargo run -p book -- checkpoint {name} \
         --from <the workbook>`; `cargo run -p book -- exercises` lists what each check needs."
    ));
    text
}

/// Whether this process is a test binary: cargo builds those into `deps/`, and programs one
/// folder up.
fn in_a_test() -> bool {
    std::env::current_exe().is_ok_and(|exe| {
        exe.parent()
            .and_then(|dir| dir.file_name())
            .is_some_and(|dir| dir == "deps")
    })
}

/// Whether this is the first report of `message`'s exercise from a nameless thread.
fn first_report(message: &str) -> bool {
    let name = message.split(':').next().unwrap_or(message).to_owned();
    let mut reported = REPORTED
        .lock()
        .unwrap_or_else(|poisoned| poisoned.into_inner());
    reported.get_or_insert_with(HashSet::new).insert(name)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_stub_names_the_exercise_it_stands_for_and_its_hint() {
        let text = not_written(
            "ch03-jittered: Where in the pixel does a sample land?",
            true,
        );
        assert!(
            text.starts_with(
                "this check needs ch03-jittered (not written yet); a hint for it: Where in the \
                 pixel does a sample land?"
            ),
            "{text}"
        );
        assert!(text.contains("checkpoint ch03-jittered --from"), "{text}");
        let program = not_written("ch01-reflect", false);
        assert!(
            program.starts_with("this program needs ch01-reflect (not written yet)\n"),
            "{program}"
        );
    }

    #[test]
    fn a_caught_stub_is_passed_on_and_any_other_panic_kept() {
        let stub = std::panic::catch_unwind(|| todo("ch01-reflect: hint")).unwrap_err();
        let passed_on =
            std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| resume_if_not_written(stub)))
                .unwrap_err();
        let text = passed_on.downcast_ref::<String>().unwrap();
        assert!(is_not_written(text), "{text}");
        let other = std::panic::catch_unwind(|| panic!("index out of bounds")).unwrap_err();
        let kept = resume_if_not_written(other);
        assert_eq!(kept.downcast_ref::<&str>(), Some(&"index out of bounds"));
    }

    #[test]
    fn the_stub_panics_with_its_words_on_a_named_thread() {
        let payload = std::thread::Builder::new()
            .name("a test".into())
            .spawn(|| todo("ch01-reflect: Which part changes?"))
            .unwrap()
            .join()
            .unwrap_err();
        let text = payload.downcast_ref::<String>().unwrap();
        assert!(
            text.contains("needs ch01-reflect (not written yet)"),
            "{text}"
        );
    }

    #[test]
    fn a_nameless_thread_reports_an_exercise_once_and_then_unwinds_quietly() {
        let message = "ch99-only-in-this-test: hint";
        let run = || {
            std::thread::spawn(move || todo(message))
                .join()
                .unwrap_err()
        };
        // Both unwind with the words; only the first went through the panic hook.
        for payload in [run(), run()] {
            let text = payload.downcast_ref::<String>().unwrap();
            assert!(text.contains("needs ch99-only-in-this-test"), "{text}");
        }
        assert!(!first_report(message), "the first run recorded its report");
    }
}
