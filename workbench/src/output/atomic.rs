//! Writing a file whole or not at all.
//!
//! A render can take minutes, and a student may press Ctrl-C at any moment, or the disk may fill
//! up. If we wrote straight into `figure.png`, either event would leave half a PNG behind, and
//! the next run's comparison against it would fail in a baffling way. Instead we write into a
//! temporary file next to the target and, only once every byte is on disk, rename it over the
//! target. A rename within one directory is atomic: readers see the old file or the new one,
//! never a mixture. Should anything fail before the rename, the temporary file is deleted when
//! it is dropped, so nothing is left behind.

use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};

use super::OutputError;

/// Writes `path` through the closure `write`, atomically: the file is replaced whole, or left
/// as it was if anything fails, and no temporary file remains either way.
///
/// The closure receives a buffered writer; an error it returns aborts the write. Every image,
/// figure and text writer of this crate goes through this function.
pub fn write_atomic(
    path: &Path,
    write: impl FnOnce(&mut dyn Write) -> io::Result<()>,
) -> Result<(), OutputError> {
    let directory = parent_directory(path);
    if !directory.is_dir() {
        return Err(OutputError::MissingDirectory {
            path: path.to_owned(),
            directory,
        });
    }
    let write_error = |source| OutputError::Write {
        path: path.to_owned(),
        source,
    };

    // The temporary file lives in the target's own directory: a rename across file systems
    // (say from /tmp to the home directory) would not be atomic, or not possible at all.
    // Its name starts with the target's, so a leftover after a power cut is easy to recognise.
    let prefix = format!(".{}.", file_name(path));
    let mut builder = tempfile::Builder::new();
    builder.prefix(&prefix).suffix(".tmp");
    // Temporary files are private (0600) by default; the finished file should be readable
    // like any other the user creates, so ask for 0666 and let the umask trim it.
    #[cfg(unix)]
    builder.permissions(std::os::unix::fs::PermissionsExt::from_mode(0o666));
    let mut temporary = builder.tempfile_in(&directory).map_err(write_error)?;

    let mut buffered = BufWriter::new(temporary.as_file_mut());
    write(&mut buffered).map_err(write_error)?;
    buffered.flush().map_err(write_error)?;
    drop(buffered);
    // Make sure the bytes reached the disk before the rename makes them visible.
    temporary.as_file().sync_all().map_err(write_error)?;

    temporary
        .persist(path)
        .map_err(|persist_error| write_error(persist_error.error))?;
    Ok(())
}

/// Writes a text file (CSV, JSON) atomically.
pub fn write_text(path: &Path, text: &str) -> Result<(), OutputError> {
    write_atomic(path, |out| out.write_all(text.as_bytes()))
}

/// The directory `path` lives in; `"."` for a bare file name such as `out.png`.
fn parent_directory(path: &Path) -> PathBuf {
    match path.parent() {
        Some(parent) if !parent.as_os_str().is_empty() => parent.to_owned(),
        _ => PathBuf::from("."),
    }
}

fn file_name(path: &Path) -> String {
    path.file_name()
        .map(|name| name.to_string_lossy().into_owned())
        .unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::fs;

    fn entries(directory: &Path) -> Vec<String> {
        let mut names: Vec<String> = fs::read_dir(directory)
            .unwrap()
            .map(|entry| entry.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        names
    }

    #[test]
    fn writes_the_whole_file() {
        let directory = tempfile::tempdir().unwrap();
        let path = directory.path().join("notes.txt");
        write_text(&path, "first\n").unwrap();
        write_text(&path, "second\n").unwrap();
        assert_eq!(fs::read_to_string(&path).unwrap(), "second\n");
        assert_eq!(entries(directory.path()), ["notes.txt"]);
    }

    #[test]
    fn a_missing_directory_is_named_and_nothing_is_written() {
        let directory = tempfile::tempdir().unwrap();
        let missing = directory.path().join("no-such-directory");
        let path = missing.join("notes.txt");
        let error = write_text(&path, "text").unwrap_err();
        assert!(matches!(error, OutputError::MissingDirectory { .. }));
        let message = error.to_string();
        assert!(message.contains("notes.txt"), "{message}");
        assert!(message.contains("no-such-directory"), "{message}");
        assert!(entries(directory.path()).is_empty());
    }

    #[test]
    fn a_failing_writer_keeps_the_old_file_and_leaves_no_temporary() {
        let directory = tempfile::tempdir().unwrap();
        let path = directory.path().join("result.csv");
        write_text(&path, "old contents\n").unwrap();

        let error = write_atomic(&path, |out| {
            out.write_all(b"half of the new ")?;
            Err(io::Error::other("the renderer gave up"))
        })
        .unwrap_err();

        assert!(matches!(error, OutputError::Write { .. }));
        let message = error.to_string();
        assert!(message.contains("result.csv"), "{message}");
        assert!(message.contains("the renderer gave up"), "{message}");
        assert_eq!(fs::read_to_string(&path).unwrap(), "old contents\n");
        assert_eq!(entries(directory.path()), ["result.csv"]);
    }

    #[test]
    fn a_bare_file_name_lives_in_the_current_directory() {
        assert_eq!(parent_directory(Path::new("out.png")), Path::new("."));
        assert_eq!(parent_directory(Path::new("a/out.png")), Path::new("a"));
    }
}
