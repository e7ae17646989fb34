//! Diagrams of geometry, drawn from the numbers the chapters compute.
//!
//! A renders or a plot shows what the code produced; a diagram shows the geometry the page
//! explains: a lens and the rays through it, a lobe around a mirror direction, a cone of
//! directions. Drawn by hand they drift from the code; drawn here, every point is one the
//! chapter's own functions returned (the refracted direction from the chapter's `refract`, the
//! focal plane from its thin lens), so a diagram is as exact as the code and changes with it.
//!
//! A [`Diagram`] is a page in *world* units with `y` up, kept at one scale on both axes so
//! that angles and circles come out true. Marks are added in world units, with an [`Ink`] that
//! says what the mark is (a ray, a surface, a normal, ...) rather than a colour, so that every
//! diagram of the book uses one visual language. [`Diagram::save`] writes an SVG file (through
//! plotters' SVG backend), whole or not at all, with the diagram's description as its
//! `<title>`, the text a screen reader speaks.

use std::path::Path;

use plotters::element::{Circle, DashedPathElement, PathElement, Polygon, Text};
use plotters::prelude::{DrawingArea, IntoDrawingArea, SVGBackend};
use plotters::style::text_anchor::{HPos, Pos, VPos};
use plotters::style::{Color, FontFamily, IntoFont, RGBColor, ShapeStyle, WHITE};

use crate::output::{OutputError, write_text};

/// What a mark depicts; each kind has one colour and line in every diagram.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Ink {
    /// A ray or a path segment (blue).
    Ray,
    /// A second family of rays, told apart from the first (vermillion).
    OtherRay,
    /// A surface, a lens or an object's outline (black).
    Surface,
    /// A normal or another direction of reference (bluish green).
    Normal,
    /// A light source or what it emits (orange).
    Light,
    /// Construction lines: axes, planes, extensions of rays (grey, dashed).
    Guide,
    /// Something wrong or lost: a sample below the surface, a rejected case (reddish purple).
    Warning,
}

impl Ink {
    fn colour(self) -> RGBColor {
        match self {
            Ink::Ray => RGBColor(0, 114, 178),
            Ink::OtherRay => RGBColor(213, 94, 0),
            Ink::Surface => RGBColor(0, 0, 0),
            Ink::Normal => RGBColor(0, 158, 115),
            Ink::Light => RGBColor(230, 159, 0),
            Ink::Guide => RGBColor(120, 120, 120),
            Ink::Warning => RGBColor(204, 121, 167),
        }
    }

    fn width(self) -> u32 {
        match self {
            Ink::Surface => 3,
            Ink::Guide => 1,
            _ => 2,
        }
    }

    fn dashed(self) -> bool {
        self == Ink::Guide
    }
}

/// Where a label sits relative to its anchor point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Anchor {
    /// The label's centre is on the point.
    Centre,
    /// The label starts at the point and runs right.
    Left,
    /// The label ends at the point.
    Right,
    /// The label sits above the point, centred.
    Below,
    /// The label hangs below the point, centred.
    Above,
}

/// A point in the diagram's world units.
pub type Point = (f64, f64);

/// One thing drawn, in world units.
#[derive(Clone, Debug)]
enum Mark {
    Line {
        points: Vec<Point>,
        ink: Ink,
    },
    Arrow {
        from: Point,
        to: Point,
        ink: Ink,
    },
    Area {
        points: Vec<Point>,
        ink: Ink,
        opacity: f64,
    },
    Dot {
        at: Point,
        ink: Ink,
    },
    Label {
        at: Point,
        text: String,
        anchor: Anchor,
        ink: Ink,
    },
}

/// A diagram under construction: a window onto world space and the marks in it.
#[derive(Clone, Debug)]
pub struct Diagram {
    description: String,
    x: (f64, f64),
    y: (f64, f64),
    width: u32,
    marks: Vec<Mark>,
}

/// The pixel size of labels; large enough to read when the page shrinks the diagram.
const LABEL_SIZE: f64 = 21.0;
/// The length of an arrow's head, in pixels.
const ARROW_HEAD: f64 = 11.0;

impl Diagram {
    /// A diagram showing world `x` in `x.0..x.1` and `y` in `y.0..y.1` (`y` up), `width` pixels
    /// wide and as tall as one scale on both axes makes it. `description` says in words what
    /// the diagram shows: it becomes the SVG's title, and the page's alt text says the same.
    ///
    /// # Panics
    /// If a range is empty or not finite, or `width` is 0: the diagrams are the book's own, and
    /// such a window is a bug in the code that draws them.
    pub fn new(description: &str, x: (f64, f64), y: (f64, f64), width: u32) -> Self {
        let proper = |(low, high): (f64, f64)| low.is_finite() && high.is_finite() && low < high;
        assert!(
            proper(x) && proper(y) && width > 0,
            "a diagram needs a window"
        );
        Self {
            description: description.to_owned(),
            x,
            y,
            width,
            marks: Vec::new(),
        }
    }

    /// The height in pixels that keeps one scale on both axes.
    pub fn height(&self) -> u32 {
        (self.scale() * (self.y.1 - self.y.0)).round().max(1.0) as u32
    }

    /// Pixels per world unit.
    fn scale(&self) -> f64 {
        f64::from(self.width) / (self.x.1 - self.x.0)
    }

    /// A straight segment from `a` to `b`.
    pub fn line(&mut self, a: Point, b: Point, ink: Ink) -> &mut Self {
        self.polyline(vec![a, b], ink)
    }

    /// Segments joining `points` in order.
    pub fn polyline(&mut self, points: Vec<Point>, ink: Ink) -> &mut Self {
        self.marks.push(Mark::Line { points, ink });
        self
    }

    /// A segment from `from` to `to` with an arrowhead at `to`: a direction, or a ray's way.
    pub fn arrow(&mut self, from: Point, to: Point, ink: Ink) -> &mut Self {
        self.marks.push(Mark::Arrow { from, to, ink });
        self
    }

    /// A filled polygon, `opacity` from 0 (invisible) to 1 (solid).
    pub fn area(&mut self, points: Vec<Point>, ink: Ink, opacity: f64) -> &mut Self {
        self.marks.push(Mark::Area {
            points,
            ink,
            opacity,
        });
        self
    }

    /// A circle's outline, as a polygon of many sides.
    pub fn circle(&mut self, centre: Point, radius: f64, ink: Ink) -> &mut Self {
        let outline = arc_points(centre, radius, 0.0, std::f64::consts::TAU);
        self.polyline(outline, ink)
    }

    /// A circular arc from angle `from` to `to` (radians, counter-clockwise from `+x`): how an
    /// angle is marked, or part of a lens's outline.
    pub fn arc(&mut self, centre: Point, radius: f64, from: f64, to: f64, ink: Ink) -> &mut Self {
        let points = arc_points(centre, radius, from, to);
        self.polyline(points, ink)
    }

    /// A small filled dot: a sample, a vertex, a point of focus.
    pub fn dot(&mut self, at: Point, ink: Ink) -> &mut Self {
        self.marks.push(Mark::Dot { at, ink });
        self
    }

    /// Text at `at`, placed by `anchor`.
    pub fn label(&mut self, at: Point, text: &str, anchor: Anchor, ink: Ink) -> &mut Self {
        self.marks.push(Mark::Label {
            at,
            text: text.to_owned(),
            anchor,
            ink,
        });
        self
    }

    /// The diagram as an SVG document.
    ///
    /// # Panics
    /// If plotters fails to draw into a string, which only a bug in plotters can cause.
    pub fn to_svg(&self) -> String {
        let mut svg = String::new();
        {
            let size = (self.width, self.height());
            let area = SVGBackend::with_string(&mut svg, size).into_drawing_area();
            self.draw(&area).expect("drawing into a string cannot fail");
            area.present().expect("drawing into a string cannot fail");
        }
        with_title(&svg, &self.description)
    }

    /// Writes the diagram to `path` as SVG, atomically.
    pub fn save(&self, path: &Path) -> Result<(), OutputError> {
        write_text(path, &self.to_svg())
    }

    /// World to pixel coordinates (pixel `y` grows downwards).
    fn pixel(&self, (x, y): Point) -> (i32, i32) {
        let scale = self.scale();
        let px = (x - self.x.0) * scale;
        let py = (self.y.1 - y) * scale;
        (px.round() as i32, py.round() as i32)
    }

    fn draw<DB: plotters::prelude::DrawingBackend>(
        &self,
        area: &DrawingArea<DB, plotters::coord::Shift>,
    ) -> Result<(), Box<dyn std::error::Error>>
    where
        DB::ErrorType: 'static,
    {
        area.fill(&WHITE)?;
        for mark in &self.marks {
            match mark {
                Mark::Line { points, ink } => {
                    let pixels: Vec<_> = points.iter().map(|&p| self.pixel(p)).collect();
                    let style = stroke(*ink);
                    if ink.dashed() {
                        area.draw(&DashedPathElement::new(pixels, 6, 4, style))?;
                    } else {
                        area.draw(&PathElement::new(pixels, style))?;
                    }
                }
                Mark::Arrow { from, to, ink } => {
                    let (a, b) = (self.pixel(*from), self.pixel(*to));
                    area.draw(&PathElement::new(vec![a, b], stroke(*ink)))?;
                    if let Some(head) = arrow_head(a, b) {
                        area.draw(&Polygon::new(head, ink.colour().filled()))?;
                    }
                }
                Mark::Area {
                    points,
                    ink,
                    opacity,
                } => {
                    let pixels: Vec<_> = points.iter().map(|&p| self.pixel(p)).collect();
                    let fill = ink.colour().mix(opacity.clamp(0.0, 1.0)).filled();
                    area.draw(&Polygon::new(pixels, fill))?;
                }
                Mark::Dot { at, ink } => {
                    area.draw(&Circle::new(self.pixel(*at), 4, ink.colour().filled()))?;
                }
                Mark::Label {
                    at,
                    text,
                    anchor,
                    ink,
                } => {
                    let (h, v) = match anchor {
                        Anchor::Centre => (HPos::Center, VPos::Center),
                        Anchor::Left => (HPos::Left, VPos::Center),
                        Anchor::Right => (HPos::Right, VPos::Center),
                        Anchor::Below => (HPos::Center, VPos::Bottom),
                        Anchor::Above => (HPos::Center, VPos::Top),
                    };
                    let font = (FontFamily::SansSerif, LABEL_SIZE)
                        .into_font()
                        .color(&ink.colour())
                        .pos(Pos::new(h, v));
                    area.draw(&Text::new(text.clone(), self.pixel(*at), font))?;
                }
            }
        }
        Ok(())
    }
}

/// The line style of `ink`.
fn stroke(ink: Ink) -> ShapeStyle {
    ink.colour().stroke_width(ink.width())
}

/// Points along a circular arc, close enough together to look round at any size we draw.
fn arc_points(centre: Point, radius: f64, from: f64, to: f64) -> Vec<Point> {
    let steps = ((to - from).abs() / std::f64::consts::TAU * 128.0)
        .ceil()
        .max(2.0) as usize;
    (0..=steps)
        .map(|i| {
            let angle = from + (to - from) * i as f64 / steps as f64;
            (
                centre.0 + radius * angle.cos(),
                centre.1 + radius * angle.sin(),
            )
        })
        .collect()
}

/// The triangle of an arrowhead whose tip is at `tip`, pointing along `tail -> tip`; `None`
/// when the two coincide (no direction to point in).
fn arrow_head(tail: (i32, i32), tip: (i32, i32)) -> Option<Vec<(i32, i32)>> {
    let (dx, dy) = (f64::from(tip.0 - tail.0), f64::from(tip.1 - tail.1));
    let length = dx.hypot(dy);
    if length == 0.0 {
        return None;
    }
    let (ux, uy) = (dx / length, dy / length);
    let back = (
        f64::from(tip.0) - ux * ARROW_HEAD,
        f64::from(tip.1) - uy * ARROW_HEAD,
    );
    let half = ARROW_HEAD * 0.4;
    let corner = |side: f64| {
        (
            (back.0 - uy * half * side).round() as i32,
            (back.1 + ux * half * side).round() as i32,
        )
    };
    Some(vec![tip, corner(1.0), corner(-1.0)])
}

/// `svg` with a `<title>` holding `description` as the first thing inside its root element.
fn with_title(svg: &str, description: &str) -> String {
    let escaped = description
        .replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;");
    match svg
        .find("<svg")
        .and_then(|start| svg[start..].find('>').map(|end| start + end + 1))
    {
        Some(end_of_root) => format!(
            "{}\n<title>{escaped}</title>{}",
            &svg[..end_of_root],
            &svg[end_of_root..]
        ),
        None => svg.to_owned(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample() -> Diagram {
        let mut diagram =
            Diagram::new("A ray <reflected> & a normal", (-1.0, 1.0), (0.0, 1.0), 400);
        diagram
            .line((-1.0, 0.0), (1.0, 0.0), Ink::Surface)
            .arrow((-0.5, 0.5), (0.0, 0.0), Ink::Ray)
            .arrow((0.0, 0.0), (0.0, 0.8), Ink::Normal)
            .arc((0.0, 0.0), 0.2, 0.0, 1.0, Ink::Guide)
            .area(vec![(0.0, 0.0), (0.5, 0.5), (0.6, 0.4)], Ink::Light, 0.3)
            .dot((0.0, 0.0), Ink::Surface)
            .label((0.0, 0.85), "n", Anchor::Below, Ink::Normal);
        diagram
    }

    #[test]
    fn one_scale_on_both_axes() {
        // Two units wide in 400 pixels, one unit tall: 200 pixels, or circles would be ovals.
        assert_eq!(sample().height(), 200);
        let diagram = sample();
        assert_eq!(diagram.pixel((-1.0, 1.0)), (0, 0));
        assert_eq!(diagram.pixel((1.0, 0.0)), (400, 200));
        assert_eq!(diagram.pixel((0.0, 0.5)), (200, 100));
    }

    #[test]
    fn the_svg_is_well_formed_and_carries_its_description() {
        let svg = sample().to_svg();
        let document = roxmltree::Document::parse(&svg).expect("the SVG parses as XML");
        let root = document.root_element();
        assert_eq!(root.tag_name().name(), "svg");
        assert_eq!(root.attribute("width"), Some("400"));
        assert_eq!(root.attribute("height"), Some("200"));
        let title = root
            .children()
            .find(|node| node.has_tag_name((root.tag_name().namespace().unwrap_or(""), "title")))
            .expect("a <title> right inside the root");
        assert_eq!(title.text(), Some("A ray <reflected> & a normal"));
        let texts: Vec<_> = document
            .descendants()
            .filter(|node| node.tag_name().name() == "text")
            .filter_map(|node| node.text())
            .map(str::trim)
            .collect();
        assert_eq!(texts, ["n"]);
        // The arrowheads are triangles: two polygons beside the filled area.
        let polygons = document
            .descendants()
            .filter(|node| node.tag_name().name() == "polygon")
            .count();
        assert_eq!(polygons, 3, "{svg}");
        if let Ok(path) = std::env::var("DIAGRAM_SAMPLE") {
            std::fs::write(path, &svg).unwrap();
        }
    }

    #[test]
    fn arrowheads_point_along_the_arrow() {
        let head = arrow_head((0, 0), (100, 0)).unwrap();
        assert_eq!(head[0], (100, 0));
        assert!(head[1..].iter().all(|&(x, _)| x < 100 && x > 80));
        assert_eq!(head[1].1, -head[2].1);
        assert_eq!(arrow_head((5, 5), (5, 5)), None);
    }

    #[test]
    #[should_panic(expected = "a diagram needs a window")]
    fn an_empty_window_is_refused() {
        let _ = Diagram::new("nothing", (1.0, 1.0), (0.0, 1.0), 100);
    }
}
