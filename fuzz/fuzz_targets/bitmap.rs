//! Any bytes given to the image reader of bitmap textures and envmaps (PNG, JPEG, EXR,
//! Radiance HDR): an error or an image with one finite-or-not pixel per place, never a panic.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|bytes: &[u8]| {
    for raw in [false, true] {
        if let Ok(image) = workbench::scene_file::parse_bitmap(bytes, raw) {
            assert_eq!(image.pixels.len(), (image.width * image.height) as usize);
        }
    }
});
