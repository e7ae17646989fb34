//! The book's live demos: the chapters' own code behind a few functions that a page's
//! JavaScript calls in a WebAssembly module.
//!
//! The interface is raw exports (`extern "C"` functions of numbers) and buffers the page reads
//! out of the module's memory, with no binding generator: a demo asks for numbers and gets
//! numbers, and the page's glue (`book/theme/demos.js`) is a few lines per call. Every export
//! returns at once (a demo asks for a slice of work per animation frame), runs on one thread,
//! and never unwinds into JavaScript: a panic, such as an exercise not written yet, is caught
//! by [`outcome::run`], kept as text for the page to show, and reported as a failure.
//!
//! Chapter 02's warp explorer and generators have exports of their own ([`warps`],
//! [`generators`]); every other demo renders,
//! and is a [`demo::Demo`] listed in [`renders::DEMOS`]: a chapter's scene, camera and tracer
//! behind controls, refined a slice at a time ([`progressive`]).

pub mod anti_aliasing;
pub mod buffers;
pub mod contrast;
pub mod demo;
pub mod depth_of_field;
pub mod fuzzy;
pub mod generators;
pub mod materials;
pub mod motion_blur;
pub mod optimal_mis;
pub mod outcome;
pub mod path_guiding;
pub mod path_tracing;
pub mod progressive;
pub mod renders;
pub mod soft_shadows;
pub mod warps;
pub mod whitted;
