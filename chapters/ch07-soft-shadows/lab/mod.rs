//! The chapter's workbench, apart from its lecture: the light options of `render`, which
//! chapter 08 flattens into its own (`cli`), the book's figures, and the scenes on which the
//! chapter is checked against Mitsuba 3. Built with the `lab` feature (on by default); the
//! library without it is the lecture alone.

pub mod agreement;
pub mod cli;
pub mod figures;
