//! SVG export of line drawings (L-systems): segments framed into a width×height picture, runs
//! of connected segments of one colour joined into one path.

use std::io::Write;
use std::path::Path;

use crate::explore::lsystem::{Compiled, Segment};
use crate::explore::raster::{Framing, palette_color};
use crate::explore::{Bounds, ExploreError};
use crate::io::atomic::write_atomic_with;
use crate::io::error::WriteError;

/// Most segments written to one SVG file (about 15 bytes each).
pub const MAX_SEGMENTS: u64 = 5_000_000;

fn hex(c: [u8; 3]) -> String {
    format!("#{:02x}{:02x}{:02x}", c[0], c[1], c[2])
}

/// Escape text for XML content.
fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// Coordinates with two decimals, trailing zeros dropped.
fn num(v: f64) -> String {
    let s = format!("{:.2}", v);
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" || s.is_empty() {
        "0".into()
    } else {
        s.to_string()
    }
}

/// Write segments as SVG. `segments` is called twice (bounds, then drawing) and must give the
/// same segments both times.
pub fn write_segments<W: Write>(
    out: &mut W,
    title: &str,
    width: u32,
    height: u32,
    background: Option<[u8; 3]>,
    mut segments: impl FnMut(&mut dyn FnMut(Segment)),
) -> std::io::Result<()> {
    let mut b = Bounds::EMPTY;
    segments(&mut |s| {
        b.add(s.a);
        b.add(s.b);
    });
    let margin = 2.0 + 0.03 * width.min(height) as f64;
    let f = Framing::fit(b, width, height, margin);
    writeln!(out, r#"<?xml version="1.0" encoding="UTF-8"?>"#)?;
    writeln!(
        out,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" viewBox="0 0 {width} {height}">"#
    )?;
    writeln!(out, "<title>{}</title>", escape(title))?;
    if let Some(bg) = background {
        writeln!(
            out,
            r#"<rect width="{width}" height="{height}" fill="{}"/>"#,
            hex(bg)
        )?;
    }
    writeln!(
        out,
        r#"<g fill="none" stroke-width="1" stroke-linecap="round" stroke-linejoin="round">"#
    )?;
    // Pixel centres are at integers in the framing; SVG puts them at +0.5.
    let px = |p| {
        let q = f.pixel_from_world(p);
        (num(q[0] + 0.5), num(q[1] + 0.5))
    };
    let mut open: Option<(i64, [f64; 2])> = None;
    let mut path = String::new();
    let mut result = Ok(());
    segments(&mut |s| {
        if result.is_err() {
            return;
        }
        let joined = matches!(open, Some((c, end)) if c == s.color && end == s.a);
        if !joined {
            if open.is_some() {
                path.push_str("\"/>\n");
                result = out.write_all(path.as_bytes());
                path.clear();
            }
            let (x, y) = px(s.a);
            path.push_str(&format!(
                r#"<path stroke="{}" d="M{x} {y}"#,
                hex(palette_color(s.color))
            ));
        }
        let (x, y) = px(s.b);
        path.push_str(&format!("L{x} {y}"));
        open = Some((s.color, s.b));
        if path.len() > 1 << 16 {
            // Long runs are split so no line grows without bound.
            path.push_str("\"/>\n");
            result = out.write_all(path.as_bytes());
            path.clear();
            open = None;
        }
    });
    result?;
    if open.is_some() {
        path.push_str("\"/>\n");
        out.write_all(path.as_bytes())?;
    }
    writeln!(out, "</g>\n</svg>")
}

/// Save an L-system at `order` as SVG, atomically; refused beyond [`MAX_SEGMENTS`] segments.
pub fn save_lsystem(
    path: &Path,
    sys: &Compiled,
    order: u32,
    width: u32,
    height: u32,
    background: Option<[u8; 3]>,
) -> Result<(), WriteError> {
    crate::explore::raster::check_size(width, height)?;
    let segs = sys.counts(order).segments;
    if segs > MAX_SEGMENTS as f64 {
        return Err(ExploreError::TooLarge {
            what: format!("'{}' at order {order} as SVG", sys.system.name),
            count: segs,
            limit: MAX_SEGMENTS as f64,
            hint: " segments; lower the order or write a PNG".into(),
        }
        .into());
    }
    // Check the walk (order limit, nesting) before creating the file.
    sys.extent(order)?;
    let title = format!("{} (order {order})", sys.system.name);
    write_atomic_with(path, |file| {
        let mut w = std::io::BufWriter::new(file);
        write_segments(&mut w, &title, width, height, background, |sink| {
            if let Ok(it) = sys.segments(order) {
                for s in it {
                    sink(s);
                }
            }
        })?;
        w.flush()
    })
    .map_err(|source| WriteError::Io {
        path: path.to_path_buf(),
        source,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::explore::lsystem::presets;

    #[test]
    fn koch_curve_is_one_path() {
        let c = presets::koch_curve().system.compile().unwrap();
        let mut out = Vec::new();
        write_segments(
            &mut out,
            "Koch <curve>",
            300,
            120,
            Some([0, 0, 0]),
            |sink| {
                for s in c.segments(3).unwrap() {
                    sink(s);
                }
            },
        )
        .unwrap();
        let s = String::from_utf8(out).unwrap();
        assert!(s.contains("<title>Koch &lt;curve&gt;</title>"));
        assert_eq!(s.matches("<path").count(), 1);
        // 64 segments: one move and 64 lines.
        assert_eq!(s.matches('L').count(), 64);
        assert!(s.contains(r##"stroke="#ffffff""##));
        assert!(s.trim_end().ends_with("</svg>"));
    }

    #[test]
    fn numbers() {
        assert_eq!(num(1.0), "1");
        assert_eq!(num(1.256), "1.26");
        assert_eq!(num(-0.001), "0");
        assert_eq!(num(10.5), "10.5");
    }

    #[test]
    fn colour_changes_and_jumps_start_new_paths() {
        let s = crate::explore::lsystem::LSystem::new(
            "c",
            "FC2FGF",
            &[],
            crate::explore::lsystem::Angle::Divisions(4),
        );
        let c = s.compile().unwrap();
        let mut out = Vec::new();
        write_segments(&mut out, "c", 100, 100, None, |sink| {
            for s in c.segments(0).unwrap() {
                sink(s);
            }
        })
        .unwrap();
        let s = String::from_utf8(out).unwrap();
        assert_eq!(s.matches("<path").count(), 3);
        assert!(!s.contains("<rect"));
    }
}
