//! `ugnis lsystem`: draw an entry of a Fractint `.l` file to SVG or PNG.

use std::path::PathBuf;

use anyhow::{Context, Result, bail};
use clap::Args;
use image::ImageEncoder;

use ugnis::explore::lsystem::MAX_ORDER;
use ugnis::io;

#[derive(Args, Debug)]
pub struct LsystemArgs {
    /// Fractint L-system file (.l)
    pub file: PathBuf,
    /// Entry to draw (case-insensitive; default: the first entry)
    #[arg(long)]
    pub name: Option<String>,
    /// Derivation steps (0–64; the drawing is refused when it would take more than 5·10⁸
    /// symbols)
    #[arg(long, default_value_t = 4)]
    pub order: u32,
    /// Picture size WxH (up to 16384 per side)
    #[arg(long, value_parser = super::parse_size, default_value = "800x800")]
    pub size: (u32, u32),
    /// Background colour as RRGGBB, or "none" (SVG only: transparent)
    #[arg(long, default_value = "000000")]
    pub background: String,
    /// Output picture: .svg or .png
    #[arg(short, long)]
    pub output: PathBuf,
}

fn parse_color(s: &str) -> Result<Option<[u8; 3]>> {
    if s.eq_ignore_ascii_case("none") {
        return Ok(None);
    }
    let h = s.trim_start_matches('#');
    if h.len() != 6 || !h.bytes().all(|b| b.is_ascii_hexdigit()) {
        bail!("--background '{s}': expected a colour RRGGBB (e.g. 000000 or ffffff) or 'none'");
    }
    let v = u32::from_str_radix(h, 16)?;
    Ok(Some([(v >> 16) as u8, (v >> 8) as u8, v as u8]))
}

pub fn run(a: LsystemArgs) -> Result<()> {
    let ext = a
        .output
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase())
        .unwrap_or_default();
    if ext != "svg" && ext != "png" {
        bail!("output '{}' must end in .svg or .png", a.output.display());
    }
    if a.order > MAX_ORDER {
        bail!("--order {} must be between 0 and {MAX_ORDER}", a.order);
    }
    let background = parse_color(&a.background)?;
    super::check_outputs(&[&a.file], &[&a.output])?;
    let p = io::read_lsystems(&a.file)?;
    // An entry asked for by name that could not be read: its problem is the error.
    let skipped = a
        .name
        .as_ref()
        .filter(|n| p.value.get(n).is_none())
        .and_then(|n| {
            let says = format!("entry '{}' is skipped", n.to_ascii_lowercase());
            p.warnings
                .iter()
                .position(|w| w.message.to_ascii_lowercase().ends_with(&says))
        });
    for (i, w) in p.warnings.iter().enumerate() {
        if Some(i) != skipped {
            stderr!("{w}");
        }
    }
    if let Some(i) = skipped {
        let mut e = p.warnings[i].clone();
        e.warning = false;
        return Err(e.into());
    }
    let file = p.value;
    let sys = match &a.name {
        Some(n) => file.get(n).with_context(|| {
            let names: Vec<&str> = file.entries.iter().map(|e| e.name.as_str()).collect();
            format!(
                "{}: no entry named '{n}'; the file has {}",
                a.file.display(),
                list(&names)
            )
        })?,
        None => file
            .entries
            .first()
            .with_context(|| format!("{}: the file has no entries", a.file.display()))?,
    };
    let c = sys
        .compile()
        .with_context(|| format!("{}: entry '{}'", a.file.display(), sys.name))?;
    let counts = c.segments(a.order)?.counts().clone();
    let (w, h) = a.size;
    if ext == "svg" {
        io::svg::save_lsystem(&a.output, &c, a.order, w, h, background)
            .map_err(anyhow::Error::msg)?;
    } else {
        let bg = background.unwrap_or([0, 0, 0]);
        let img = c.render(a.order, w, h, bg)?;
        io::atomic::write_atomic_with(&a.output, |f| {
            let mut bw = std::io::BufWriter::new(f);
            image::codecs::png::PngEncoder::new(&mut bw)
                .write_image(img.as_raw(), w, h, image::ExtendedColorType::Rgb8)
                .map_err(std::io::Error::other)?;
            std::io::Write::flush(&mut bw)
        })
        .with_context(|| format!("cannot write '{}'", a.output.display()))?;
    }
    println!(
        "{}: order {}, {} segments, string of {} symbols -> {}",
        sys.name,
        a.order,
        counts.segments,
        counts.symbols,
        a.output.display()
    );
    Ok(())
}

fn list(names: &[&str]) -> String {
    match names.len() {
        0 => "no entries".into(),
        n if n <= 12 => format!("{n} entries: {}", names.join(", ")),
        n => format!("{n} entries: {}, …", names[..12].join(", ")),
    }
}
