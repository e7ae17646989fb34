//! Reading the files a scene names, within bounds: only regular files, and no further than a
//! stated size, so that a file naming `/dev/zero` as a mesh, or a named pipe, or a file that
//! keeps growing, is refused with its name instead of eating memory until the process dies.

use std::io::Read;
use std::path::Path;

/// The largest scene file or included file, in bytes: a scene's XML with its meshes in other
/// files is kilobytes; inline data can make it megabytes.
pub const SCENE_FILE_LIMIT: u64 = 256 << 20;
/// The largest mesh file (OBJ, PLY, `.serialized`): tens of millions of triangles.
pub const MESH_FILE_LIMIT: u64 = 2 << 30;
/// The largest image file (textures, environment maps), before decoding; the decoded size has
/// its own limit.
pub const IMAGE_FILE_LIMIT: u64 = 1 << 30;
/// The largest spectrum file (`.spd`), a table of a few hundred lines.
pub const SPECTRUM_FILE_LIMIT: u64 = 16 << 20;

/// The bytes of the `what` at `path` (a mesh, an image...), if it is a regular file of at most
/// `limit` bytes; else a message naming it and what is wrong.
pub fn read_bytes(path: &Path, what: &str, limit: u64) -> Result<Vec<u8>, String> {
    let shown = path.display();
    let metadata = std::fs::metadata(path)
        .map_err(|error| format!("cannot read the {what} {shown}: {error}"))?;
    if !metadata.is_file() {
        return Err(format!(
            "the {what} {shown} is not a regular file (a folder, a device or a pipe); only files \
             are read"
        ));
    }
    let too_large = || {
        format!(
            "the {what} {shown} is larger than the {} MiB the reader allows for it",
            limit >> 20
        )
    };
    if metadata.len() > limit {
        return Err(too_large());
    }
    let file = std::fs::File::open(path)
        .map_err(|error| format!("cannot read the {what} {shown}: {error}"))?;
    let mut bytes = Vec::with_capacity(metadata.len() as usize);
    // One byte past the limit tells a file that grew while it was read.
    file.take(limit + 1)
        .read_to_end(&mut bytes)
        .map_err(|error| format!("cannot read the {what} {shown}: {error}"))?;
    if bytes.len() as u64 > limit {
        return Err(too_large());
    }
    Ok(bytes)
}

/// The text of the `what` at `path`, read as [`read_bytes`] reads, which must be UTF-8.
pub fn read_text(path: &Path, what: &str, limit: u64) -> Result<String, String> {
    let bytes = read_bytes(path, what, limit)?;
    String::from_utf8(bytes).map_err(|_| format!("the {what} {} is not UTF-8 text", path.display()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_device_a_folder_and_a_file_too_large_are_refused_by_name() {
        let folder = tempfile::tempdir().expect("a temporary folder");
        let error = read_bytes(folder.path(), "mesh", MESH_FILE_LIMIT).expect_err("a folder");
        assert!(error.contains("not a regular file"), "{error}");
        if Path::new("/dev/zero").exists() {
            // Read without a bound, /dev/zero fills memory until the process is killed.
            let error =
                read_bytes(Path::new("/dev/zero"), "mesh", MESH_FILE_LIMIT).expect_err("a device");
            assert!(error.contains("/dev/zero is not a regular file"), "{error}");
        }
        let file = folder.path().join("large.obj");
        std::fs::write(&file, vec![b'#'; 2048]).expect("a file");
        let error = read_bytes(&file, "mesh", 1024).expect_err("too large");
        assert!(error.contains("larger than"), "{error}");
        assert_eq!(
            read_bytes(&file, "mesh", 2048).expect("at the limit").len(),
            2048
        );
        std::fs::write(&file, [0xff, 0xfe]).expect("a file");
        let error = read_text(&file, "scene file", 1024).expect_err("not UTF-8");
        assert!(error.contains("not UTF-8"), "{error}");
    }
}
