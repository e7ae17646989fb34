//! The grid of bins the samples are counted in.

use std::f64::consts::TAU;

use glam::DVec2;

use crate::warps::sphere::spherical_direction;
use crate::warps::{Domain, WarpPoint};

/// A direction is accepted as a unit vector when its length is within this of 1.
const UNIT_LENGTH_TOLERANCE: f64 = 1e-3;

/// The grid of bins over a domain, in coordinates `(x, y)` where the domain's measure is
/// `dx dy`: the plane's own coordinates, or `(φ, cos θ)` on the sphere.
pub(super) struct BinGrid {
    domain: Domain,
    columns: usize,
    rows: usize,
    min: DVec2,
    max: DVec2,
}

impl BinGrid {
    /// `resolution = (columns, rows)` bins over `domain`'s rectangle in grid coordinates.
    pub(super) fn new(domain: Domain, (columns, rows): (usize, usize)) -> Self {
        assert!(columns > 0 && rows > 0, "the grid needs at least one bin");
        let (min, max) = match domain {
            Domain::Plane { min, max } => (min.as_dvec2(), max.as_dvec2()),
            Domain::Sphere => (DVec2::new(0.0, -1.0), DVec2::new(TAU, 1.0)),
        };
        Self {
            domain,
            columns,
            rows,
            min,
            max,
        }
    }

    /// The number of bins.
    pub(super) fn len(&self) -> usize {
        self.columns * self.rows
    }

    /// The grid coordinates of `point`, or `None` if it cannot belong to the domain: not
    /// finite, of the wrong kind, or a direction that is not of unit length.
    fn coordinates(&self, point: WarpPoint) -> Option<DVec2> {
        let xy = match (self.domain, point) {
            (Domain::Plane { .. }, WarpPoint::Plane(p)) => p.as_dvec2(),
            (Domain::Sphere, WarpPoint::Direction(d)) => {
                let d = d.as_dvec3();
                let length = d.length();
                if (length - 1.0).abs() > UNIT_LENGTH_TOLERANCE {
                    return None;
                }
                let phi = d.y.atan2(d.x);
                let phi = if phi < 0.0 { phi + TAU } else { phi };
                DVec2::new(phi, (d.z / length).clamp(-1.0, 1.0))
            }
            _ => return None,
        };
        xy.is_finite().then_some(xy)
    }

    /// The index of the bin holding `point`, or `None` if it lies outside the grid. Points on
    /// the grid's upper edges belong to the last bin.
    pub(super) fn bin_of(&self, point: WarpPoint) -> Option<usize> {
        let xy = self.coordinates(point)?;
        if xy.cmplt(self.min).any() || xy.cmpgt(self.max).any() {
            return None;
        }
        let cell = (xy - self.min) / (self.max - self.min);
        let column = ((cell.x * self.columns as f64) as usize).min(self.columns - 1);
        let row = ((cell.y * self.rows as f64) as usize).min(self.rows - 1);
        Some(row * self.columns + column)
    }

    /// The lower and upper corners of bin `index` in grid coordinates.
    pub(super) fn bin_bounds(&self, index: usize) -> (DVec2, DVec2) {
        let (column, row) = (index % self.columns, index / self.columns);
        let size = (self.max - self.min) / DVec2::new(self.columns as f64, self.rows as f64);
        let lower = self.min + size * DVec2::new(column as f64, row as f64);
        (lower, lower + size)
    }

    /// The point of the domain at grid coordinates `xy`.
    pub(super) fn point_at(&self, xy: DVec2) -> WarpPoint {
        match self.domain {
            Domain::Plane { .. } => WarpPoint::Plane(xy.as_vec2()),
            Domain::Sphere => {
                let (phi, cos_theta) = (xy.x, xy.y);
                let sin_theta = ((1.0 - cos_theta) * (1.0 + cos_theta)).max(0.0).sqrt();
                WarpPoint::Direction(spherical_direction(
                    sin_theta as f32,
                    cos_theta as f32,
                    phi as f32,
                ))
            }
        }
    }
}
