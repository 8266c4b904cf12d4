//! The turtle: the depth-first walk of a derivation that yields the drawn segments one at a
//! time, and the pictures and bounds made from it.

use super::compile::{Cmd, Compiled, Counts, NO_RULE, Str};
use super::system::{DEFAULT_COLOR, MAX_STACK};
use crate::explore::{Bounds, ExploreError, P2, raster};

impl Compiled {
    /// The turtle's segments after `order` steps, one at a time.
    pub fn segments(&self, order: u32) -> Result<Segments<'_>, ExploreError> {
        let counts = self.check_order(order)?;
        Ok(Segments {
            sys: self,
            frames: vec![Frame {
                s: &self.axiom,
                pos: 0,
                depth: order,
            }],
            turtle: Turtle {
                pos: [0.0, 0.0],
                heading: 0.0,
                degrees: 0.0,
                step: 1.0,
                color: DEFAULT_COLOR,
                reversed: self.system.swap_signs,
            },
            saved: Vec::new(),
            drawn: 0,
            counts,
            error: None,
        })
    }

    /// Bounds of the drawn segments and their number (one full walk).
    pub fn extent(&self, order: u32) -> Result<(Bounds, u64), ExploreError> {
        let mut segs = self.segments(order)?;
        let mut b = Bounds::EMPTY;
        for s in segs.by_ref() {
            b.add(s.a);
            b.add(s.b);
        }
        if let Some(e) = segs.error() {
            return Err(e.clone());
        }
        Ok((b, segs.drawn()))
    }

    /// Draw the system at `order` into a width×height image on `background`, framed to fit
    /// with a small margin, each segment in its turtle colour (`raster::palette_color`).
    pub fn render(
        &self,
        order: u32,
        width: u32,
        height: u32,
        background: [u8; 3],
    ) -> Result<image::RgbImage, ExploreError> {
        raster::check_size(width, height)?;
        let (b, _) = self.extent(order)?;
        let margin = 2.0 + 0.03 * width.min(height) as f64;
        let f = raster::Framing::fit(b, width, height, margin);
        let mut c = raster::Canvas::new(width, height, background)?;
        let mut segs = self.segments(order)?;
        for s in segs.by_ref() {
            c.line(
                f.pixel_from_world(s.a),
                f.pixel_from_world(s.b),
                raster::palette_color(s.color),
            );
        }
        if let Some(e) = segs.error() {
            return Err(e.clone());
        }
        Ok(c.image)
    }
}

/// One drawn segment with its colour index.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Segment {
    /// Start point.
    pub a: P2,
    /// End point.
    pub b: P2,
    /// Colour index (set by `c`, `<` and `>`).
    pub color: i64,
}

#[derive(Clone, Copy, Debug, PartialEq)]
struct Turtle {
    pos: P2,
    /// Heading in units of δ (for `F`, `G`).
    heading: f64,
    /// Heading in degrees (for `D`, `M`).
    degrees: f64,
    step: f64,
    color: i64,
    reversed: bool,
}

#[derive(Clone, Debug)]
struct Frame<'a> {
    s: &'a Str,
    pos: usize,
    depth: u32,
}

/// The depth-first walk of a derivation: yields the segments the turtle draws. The memory is
/// one frame per order plus the saved turtles of open `[`.
#[derive(Clone, Debug)]
pub struct Segments<'a> {
    sys: &'a Compiled,
    frames: Vec<Frame<'a>>,
    turtle: Turtle,
    saved: Vec<Turtle>,
    drawn: u64,
    counts: Counts,
    error: Option<ExploreError>,
}

impl Segments<'_> {
    /// Segments drawn so far.
    pub fn drawn(&self) -> u64 {
        self.drawn
    }

    /// The predicted size of the whole walk.
    pub fn counts(&self) -> &Counts {
        &self.counts
    }

    /// Why the walk stopped early (too deeply nested `[`), if it did.
    pub fn error(&self) -> Option<&ExploreError> {
        self.error.as_ref()
    }

    #[inline]
    fn direction(&self) -> P2 {
        let t = &self.turtle;
        match &self.sys.table {
            Some(tab) if t.heading.fract() == 0.0 => {
                let n = tab.len() as i64;
                tab[(t.heading as i64).rem_euclid(n) as usize]
            }
            _ => {
                let a = self.sys.system.start_heading.to_radians() + t.heading * self.sys.delta;
                let (s, c) = a.sin_cos();
                [c, s]
            }
        }
    }

    #[inline]
    fn degree_direction(&self) -> P2 {
        let a = (self.sys.system.start_heading + self.turtle.degrees).to_radians();
        let (s, c) = a.sin_cos();
        [c, s]
    }

    fn forward(&mut self, dir: P2, draw: bool) -> Option<Segment> {
        let t = &mut self.turtle;
        let a = t.pos;
        t.pos = [a[0] + dir[0] * t.step, a[1] + dir[1] * t.step];
        if draw {
            self.drawn += 1;
            Some(Segment {
                a,
                b: t.pos,
                color: t.color,
            })
        } else {
            None
        }
    }

    fn turn(&mut self, units: f64) {
        let sign = if self.turtle.reversed { -1.0 } else { 1.0 };
        let h = self.turtle.heading + sign * units;
        // Keep whole-δ headings small and exact.
        self.turtle.heading = match &self.sys.table {
            Some(t) if h.fract() == 0.0 => h.rem_euclid(t.len() as f64),
            _ => h,
        };
    }
}

impl Iterator for Segments<'_> {
    type Item = Segment;

    fn next(&mut self) -> Option<Segment> {
        loop {
            let frame = self.frames.last_mut()?;
            let Some(tok) = frame.s.tokens.get(frame.pos) else {
                self.frames.pop();
                continue;
            };
            frame.pos += 1;
            let depth = frame.depth;
            if depth > 0 && tok.rule != NO_RULE {
                self.frames.push(Frame {
                    s: &self.sys.rules[tok.rule as usize],
                    pos: 0,
                    depth: depth - 1,
                });
                continue;
            }
            match tok.cmd {
                Cmd::Draw => {
                    let d = self.direction();
                    return self.forward(d, true);
                }
                Cmd::Move => {
                    let d = self.direction();
                    self.forward(d, false);
                }
                Cmd::DrawDeg => {
                    let d = self.degree_direction();
                    return self.forward(d, true);
                }
                Cmd::MoveDeg => {
                    let d = self.degree_direction();
                    self.forward(d, false);
                }
                Cmd::Turn(u) => self.turn(u),
                Cmd::Reverse => {
                    // A half turn is the same either way round.
                    let h = self.sys.half_turn;
                    let r = self.turtle.reversed;
                    self.turtle.reversed = false;
                    self.turn(h);
                    self.turtle.reversed = r;
                }
                Cmd::DegTurn(v) => {
                    let sign = if self.turtle.reversed { -1.0 } else { 1.0 };
                    self.turtle.degrees = (self.turtle.degrees + sign * v).rem_euclid(360.0);
                }
                Cmd::SetColor(c) => self.turtle.color = c,
                Cmd::AddColor(c) => self.turtle.color = self.turtle.color.saturating_add(c),
                Cmd::Swap => self.turtle.reversed = !self.turtle.reversed,
                Cmd::Scale(f) => self.turtle.step *= f,
                Cmd::Push => {
                    if self.saved.len() >= MAX_STACK {
                        self.error = Some(ExploreError::TooLarge {
                            what: format!("'{}': nesting of '['", self.sys.system.name),
                            count: self.saved.len() as f64 + 1.0,
                            limit: MAX_STACK as f64,
                            hint: "; lower the order".into(),
                        });
                        self.frames.clear();
                        return None;
                    }
                    self.saved.push(self.turtle);
                    if self.sys.system.bracket_turn {
                        self.turn(1.0);
                    }
                }
                Cmd::Pop => {
                    // A `]` without its `[` is ignored.
                    if let Some(t) = self.saved.pop() {
                        self.turtle = t;
                    }
                }
                Cmd::Nop => {}
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::presets::*;
    use super::super::{Angle, LSystem};
    use super::*;

    fn polygon_area(segs: &[Segment]) -> f64 {
        segs.iter()
            .map(|s| s.a[0] * s.b[1] - s.b[0] * s.a[1])
            .sum::<f64>()
            / 2.0
    }

    #[test]
    fn turtle_geometry() {
        // The snowflake is a closed curve whose area is 8/5·(1 − …) of the triangle: with
        // + = left, F++F++F runs counter-clockwise and the bumps point outwards.
        let c = koch_snowflake().system.compile().unwrap();
        for n in 0..4 {
            let segs: Vec<Segment> = c.segments(n).unwrap().collect();
            let last = segs.last().unwrap().b;
            assert!(last[0].abs() < 1e-9 && last[1].abs() < 1e-9);
            let side = 3f64.powi(n as i32);
            let want = crate::explore::classic::Construction::KochSnowflake
                .stats(n)
                .unwrap()
                .area
                .unwrap()
                * side
                * side;
            assert!((polygon_area(&segs) - want).abs() < 1e-9 * want, "n={n}");
        }
        // The Koch curve of order 10: 4¹⁰ segments, from (0, 0) to (3¹⁰, 0).
        let c = koch_curve().system.compile().unwrap();
        let mut segs = c.segments(10).unwrap();
        let mut last = [0.0, 0.0];
        let mut n = 0u64;
        for s in segs.by_ref() {
            assert_eq!(s.a, last);
            last = s.b;
            n += 1;
        }
        assert_eq!(n, 1_048_576);
        assert_eq!(segs.drawn(), 1_048_576);
        assert!((last[0] - 59049.0).abs() < 1e-6 && last[1].abs() < 1e-6);
        // + turns left (counter-clockwise), − right; ! swaps them; | turns around.
        let one = |axiom: &str, n: u32| {
            let s = LSystem::new("t", axiom, &[], Angle::Divisions(n));
            let c = s.compile().unwrap();
            c.segments(0).unwrap().last().unwrap()
        };
        let s = one("+F", 4);
        assert!((s.b[1] - 1.0).abs() < 1e-15 && s.b[0].abs() < 1e-15);
        let s = one("-F", 4);
        assert!((s.b[1] + 1.0).abs() < 1e-15);
        let s = one("!+F", 4);
        assert!((s.b[1] + 1.0).abs() < 1e-15);
        let s = one("|F", 4);
        assert!((s.b[0] + 1.0).abs() < 1e-15);
        // Odd n: | turns by the largest multiple of δ below 180° (2·72° = 144°).
        let s = one("|F", 5);
        let a = 144f64.to_radians();
        assert!((s.b[0] - a.cos()).abs() < 1e-15 && (s.b[1] - a.sin()).abs() < 1e-15);
        // @ scales the step; @IQ2 divides it by √2; [ ] restore the turtle.
        let s = one("@3F", 4);
        assert!((s.b[0] - 3.0).abs() < 1e-15);
        let s = one("@IQ2F", 4);
        assert!((s.b[0] - 0.5f64.sqrt()).abs() < 1e-15);
        let s = one("F[+F@2F]F", 4);
        assert_eq!((s.a, s.b), ([1.0, 0.0], [2.0, 0.0]));
        // D and M follow the degree heading turned by \ and /.
        let s = one("\\30D", 4);
        let a = 30f64.to_radians();
        assert!((s.b[0] - a.cos()).abs() < 1e-15 && (s.b[1] - a.sin()).abs() < 1e-15);
        let s = one("/45.5M\\45.5D+D", 4);
        let a = (-45.5f64).to_radians();
        assert!((s.b[0] - a.cos() - 2.0).abs() < 1e-12 && (s.b[1] - a.sin()).abs() < 1e-12);
        assert!((s.b[0] - s.a[0] - 1.0).abs() < 1e-12);
        // Colours: C sets, < adds, > subtracts.
        let s = one("C10F<3F", 4);
        assert_eq!(s.color, 13);
        let s = one("C10>4F", 4);
        assert_eq!(s.color, 6);
        assert_eq!(one("F", 4).color, DEFAULT_COLOR);
    }

    #[test]
    fn plants_grow_upwards_with_swap() {
        // The Kovács plant with − = left leans like the book's figure; with the swap flag
        // cleared it is the mirror image.
        let p = plant_kovacs();
        let c = p.system.compile().unwrap();
        let b = c.extent(4).unwrap().0;
        let mut m = p.system.clone();
        m.swap_signs = false;
        let bm = m.compile().unwrap().extent(4).unwrap().0;
        assert!(b.max[1] > 10.0 && b.min[1] >= -1e-9);
        assert!((b.min[0] + bm.max[0]).abs() < 1e-9 && (b.max[0] + bm.min[0]).abs() < 1e-9);
    }
}
