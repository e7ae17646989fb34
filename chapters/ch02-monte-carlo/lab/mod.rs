//! The chapter's workbench, apart from its lecture: the figures the book shows, and the plots
//! and table of a convergence experiment. Built with the `lab` feature (on by default); the
//! library without it is the lecture alone.

pub mod diagrams;
pub mod figures;
pub mod plots;
