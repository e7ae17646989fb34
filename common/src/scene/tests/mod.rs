//! Tests of the scene loader.

mod cornell;
