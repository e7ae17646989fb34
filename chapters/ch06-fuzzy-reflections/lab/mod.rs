//! The chapter's workbench, apart from its lecture: the options of a fuzzy render, which later
//! chapters flatten into theirs (`cli`), the book's figures, and the scenes on which the
//! chapter is checked against Mitsuba 3. Built with the `lab` feature (on by default); the
//! library without it is the lecture alone.

pub mod agreement;
pub mod cli;
pub mod figures;
