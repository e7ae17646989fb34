//! The chapter's workbench, apart from its lecture: the figures the book shows and the scenes
//! on which the chapter is checked against Mitsuba 3. Built with the `lab` feature (on by
//! default); the library without it is the lecture alone.

pub mod agreement;
pub mod figures;
