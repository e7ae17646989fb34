//! Where results wait for the page: one buffer of numbers and one of text, overwritten by each
//! call, read by the page through their address and length in the module's memory.

use std::cell::RefCell;

thread_local! {
    static NUMBERS: RefCell<Vec<f64>> = const { RefCell::new(Vec::new()) };
    static TEXT: RefCell<String> = const { RefCell::new(String::new()) };
    pub(crate) static PANIC: RefCell<String> = const { RefCell::new(String::new()) };
}

/// Keeps the message of the last panic for the page. It has a buffer of its own: an exercise's
/// stub reports itself once per process and then unwinds without calling the panic hook again,
/// so its message must outlive the calls that write text in between.
pub fn set_panic(message: &str) {
    PANIC.with(|cell| *cell.borrow_mut() = message.to_owned());
}

/// The address of the last panic's message, UTF-8 in the module's memory.
#[unsafe(no_mangle)]
pub extern "C" fn panic_ptr() -> *const u8 {
    PANIC.with(|cell| cell.borrow().as_ptr())
}

/// How many bytes the last panic's message has.
#[unsafe(no_mangle)]
pub extern "C" fn panic_len() -> u32 {
    PANIC.with(|cell| cell.borrow().len() as u32)
}

/// Replaces the numbers the page reads next; gives how many there are.
pub fn set_numbers(numbers: Vec<f64>) -> u32 {
    NUMBERS.with(|cell| {
        *cell.borrow_mut() = numbers;
        cell.borrow().len() as u32
    })
}

/// A copy of the numbers waiting for the page (for native tests).
pub fn numbers() -> Vec<f64> {
    NUMBERS.with(|cell| cell.borrow().clone())
}

/// Replaces the text the page reads next; gives its length in bytes.
pub fn set_text(text: impl Into<String>) -> u32 {
    TEXT.with(|cell| {
        *cell.borrow_mut() = text.into();
        cell.borrow().len() as u32
    })
}

/// A copy of the text waiting for the page (for native tests).
pub fn text() -> String {
    TEXT.with(|cell| cell.borrow().clone())
}

/// The address of the numbers, `f64`s in the module's memory.
#[unsafe(no_mangle)]
pub extern "C" fn numbers_ptr() -> *const f64 {
    NUMBERS.with(|cell| cell.borrow().as_ptr())
}

/// The address of the text, UTF-8 in the module's memory.
#[unsafe(no_mangle)]
pub extern "C" fn text_ptr() -> *const u8 {
    TEXT.with(|cell| cell.borrow().as_ptr())
}

/// How many numbers wait for the page.
#[unsafe(no_mangle)]
pub extern "C" fn numbers_len() -> u32 {
    NUMBERS.with(|cell| cell.borrow().len() as u32)
}

/// How many bytes of text wait for the page.
#[unsafe(no_mangle)]
pub extern "C" fn text_len() -> u32 {
    TEXT.with(|cell| cell.borrow().len() as u32)
}
