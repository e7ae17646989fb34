//! What can go wrong while reading a scene file, and the warnings that are not worth stopping for.

use std::fmt;
use std::path::{Path, PathBuf};

pub use common::scene::TextPosition;

/// The scene file cannot be turned into a scene description.
///
/// Every error names the file, the line and the column, and says what was expected there, so a
/// student can fix the file without reading the parser. `line` and `column` are 0 when the
/// error concerns the file as a whole (it cannot be read, or it lacks a `<sensor>`).
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub struct SceneError {
    /// The scene file, as the caller named it, or the included file the problem is in.
    pub file: PathBuf,
    /// The line of the offending element, counted from 1 (0: the whole file).
    pub line: u32,
    /// The column of the offending element, counted from 1 (0: the whole file).
    pub column: u32,
    /// What is wrong and what was expected instead.
    pub message: String,
}

impl SceneError {
    /// An error at `position`, which is in the scene file `scene_file` unless it names an
    /// included file.
    pub fn at(scene_file: &Path, position: &TextPosition, message: impl Into<String>) -> Self {
        SceneError {
            file: position.file.as_deref().unwrap_or(scene_file).to_path_buf(),
            line: position.line,
            column: position.column,
            message: message.into(),
        }
    }
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.line == 0 {
            write!(f, "{}: {}", self.file.display(), self.message)
        } else {
            let (file, line, column) = (self.file.display(), self.line, self.column);
            write!(f, "{file}:{line}:{column}: {}", self.message)
        }
    }
}

/// Something in the scene file that the loader ignored, such as a property name that the plugin
/// does not know. The library collects warnings instead of printing them; the caller decides.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SceneWarning {
    /// The scene file.
    pub file: PathBuf,
    /// The line of the element the warning is about, counted from 1.
    pub line: u32,
    /// The column of the element the warning is about, counted from 1.
    pub column: u32,
    /// What was ignored, and why.
    pub message: String,
}

impl fmt::Display for SceneWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (file, line, column) = (self.file.display(), self.line, self.column);
        write!(f, "{file}:{line}:{column}: warning: {}", self.message)
    }
}
