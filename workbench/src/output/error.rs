//! Everything that can go wrong while writing or reading a file, said so a student can fix it.

use std::io;
use std::path::PathBuf;

/// Why an image, figure or text file could not be written or read.
///
/// Every message names the file, because "No such file or directory" alone leaves a student
/// guessing which of the dozen files a chapter writes was meant.
#[derive(Debug, thiserror::Error)]
pub enum OutputError {
    /// The extension does not name a format this writer knows; nothing was written.
    #[error("`{path}`: cannot tell the file format from the extension; use {expected}")]
    UnknownExtension {
        /// The file that was asked for.
        path: PathBuf,
        /// The extensions this writer understands, for the message.
        expected: &'static str,
    },

    /// The directory the file should go into does not exist. We do not create it on the quiet:
    /// a typo in a directory name should fail loudly instead of scattering files.
    #[error("cannot write `{path}`: the directory `{directory}` does not exist (create it first)")]
    MissingDirectory {
        /// The file that was asked for.
        path: PathBuf,
        /// Its missing parent directory.
        directory: PathBuf,
    },

    /// The operating system refused to create, write or rename the file.
    #[error("cannot write `{path}`: {source}")]
    Write {
        /// The file that was asked for.
        path: PathBuf,
        /// What the operating system said.
        source: io::Error,
    },

    /// The operating system refused to open or read the file.
    #[error("cannot read `{path}`: {source}")]
    Read {
        /// The file that was asked for.
        path: PathBuf,
        /// What the operating system said.
        source: io::Error,
    },

    /// The image could not be encoded (for example, it has no pixels); nothing was written.
    #[error("cannot encode `{path}`: {source}")]
    Encode {
        /// The file that was asked for.
        path: PathBuf,
        /// What the encoder said.
        source: image::ImageError,
    },

    /// The file was read but its contents are not what its extension promises.
    #[error("`{path}` is malformed: expected {expected}")]
    Malformed {
        /// The file that was read.
        path: PathBuf,
        /// What the reader expected to find, and where it stopped.
        expected: String,
    },

    /// A figure could not be drawn: its input is empty or unusable, or the plotting library
    /// failed. Nothing was written.
    #[error("cannot draw the figure `{path}`: {problem}")]
    Figure {
        /// The figure that was asked for.
        path: PathBuf,
        /// What is wrong with the input, or what the plotting library said.
        problem: String,
    },
}
