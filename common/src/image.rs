//! A linear RGB image in memory.

use glam::Vec3;

/// Linear (not sRGB-encoded) RGB radiance, `width * height` pixels, top row first, each row
/// left to right: the order of Mitsuba's films and of PNG files.
#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    /// Pixels across.
    pub width: u32,
    /// Pixels down.
    pub height: u32,
    /// Row-major pixels, top row first.
    pub pixels: Vec<Vec3>,
}

impl Image {
    /// A black image.
    pub fn new(width: u32, height: u32) -> Self {
        Self::filled(width, height, Vec3::ZERO)
    }

    /// An image of one colour.
    pub fn filled(width: u32, height: u32, colour: Vec3) -> Self {
        Self {
            width,
            height,
            pixels: vec![colour; width as usize * height as usize],
        }
    }

    /// Pixel `(x, y)`, `y` counted from the top.
    pub fn get(&self, x: u32, y: u32) -> Vec3 {
        self.pixels[self.index(x, y)]
    }

    /// Sets pixel `(x, y)`.
    pub fn set(&mut self, x: u32, y: u32, colour: Vec3) {
        let i = self.index(x, y);
        self.pixels[i] = colour;
    }

    fn index(&self, x: u32, y: u32) -> usize {
        assert!(
            x < self.width && y < self.height,
            "pixel ({x}, {y}) outside the image"
        );
        y as usize * self.width as usize + x as usize
    }
}
