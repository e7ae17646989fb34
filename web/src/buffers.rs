//! Where results wait for the page: one buffer of numbers, one of text and one of bytes (an
//! image's pixels), overwritten by each call, read by the page through their address and
//! length in the module's memory. And where the page leaves what a call reads: numbers (a
//! demo's values) and text (a demo's name), written into space the module reserves for them.

use std::cell::RefCell;

thread_local! {
    static NUMBERS: RefCell<Vec<f64>> = const { RefCell::new(Vec::new()) };
    static TEXT: RefCell<String> = const { RefCell::new(String::new()) };
    pub(crate) static PANIC: RefCell<String> = const { RefCell::new(String::new()) };
    static BYTES: RefCell<Vec<u8>> = const { RefCell::new(Vec::new()) };
    static INPUT_NUMBERS: RefCell<Vec<f64>> = const { RefCell::new(Vec::new()) };
    static INPUT_TEXT: RefCell<Vec<u8>> = const { RefCell::new(Vec::new()) };
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

/// Replaces the bytes the page reads next; gives how many there are.
pub fn set_bytes(bytes: Vec<u8>) -> u32 {
    BYTES.with(|cell| {
        *cell.borrow_mut() = bytes;
        cell.borrow().len() as u32
    })
}

/// The address of the bytes in the module's memory.
#[unsafe(no_mangle)]
pub extern "C" fn bytes_ptr() -> *const u8 {
    BYTES.with(|cell| cell.borrow().as_ptr())
}

/// Makes room for `count` numbers from the page and gives their address; the page writes them
/// there before the call that reads them ([`input_numbers`]).
#[unsafe(no_mangle)]
pub extern "C" fn input_numbers_ptr(count: u32) -> *mut f64 {
    INPUT_NUMBERS.with(|cell| {
        let mut numbers = cell.borrow_mut();
        *numbers = vec![0.0; count as usize];
        numbers.as_mut_ptr()
    })
}

/// Makes room for `length` bytes of UTF-8 text from the page and gives their address.
#[unsafe(no_mangle)]
pub extern "C" fn input_text_ptr(length: u32) -> *mut u8 {
    INPUT_TEXT.with(|cell| {
        let mut text = cell.borrow_mut();
        *text = vec![0; length as usize];
        text.as_mut_ptr()
    })
}

/// The numbers the page wrote last.
pub fn input_numbers() -> Vec<f64> {
    INPUT_NUMBERS.with(|cell| cell.borrow().clone())
}

/// The text the page wrote last (invalid UTF-8 reads as empty).
pub fn input_text() -> String {
    INPUT_TEXT.with(|cell| String::from_utf8(cell.borrow().clone()).unwrap_or_default())
}

/// Leaves `numbers` as if the page had written them (for native tests).
pub fn give_numbers(numbers: &[f64]) {
    INPUT_NUMBERS.with(|cell| *cell.borrow_mut() = numbers.to_vec());
}

/// Leaves `text` as if the page had written it (for native tests).
pub fn give_text(text: &str) {
    INPUT_TEXT.with(|cell| *cell.borrow_mut() = text.as_bytes().to_vec());
}
