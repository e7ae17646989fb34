//! The chapter's figures.

use common::cli::prepare_output_dir;
use std::path::Path;

/// Writes every figure of the chapter into `out`.
pub fn write_all(out: &Path, _quick: bool) -> anyhow::Result<()> {
    prepare_output_dir(out)?;
    Ok(())
}
