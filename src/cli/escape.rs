//! `ugnis escape`: render an escape-time fractal (or a saved view) to PNG or BMP, or its
//! iteration data to OpenEXR.

use std::path::PathBuf;

use anyhow::{Context, Result, bail};
use clap::Args;

use ugnis::escape::{C, Coloring, EscapeRenderer, Family, Fill, Sampling, Warp};
use ugnis::io::escape_view::{self, EscapeDoc, family_from_name, parse_complex, parse_poly};
use ugnis::io::{self, FileKind};
use ugnis::noise::Fbm;

#[derive(Args, Debug)]
pub struct EscapeArgs {
    /// mandelbrot, julia, multibrot, burning-ship, newton, logistic, cubic or warped-julia
    /// (optional with --view)
    pub kind: Option<String>,
    /// Start from a saved view file (.esc); the other options override it
    #[arg(long)]
    pub view: Option<PathBuf>,
    /// Julia / warped-Julia parameter c as RE,IM
    #[arg(long, allow_hyphen_values = true)]
    pub c: Option<String>,
    /// Power m of z^m + c (2–9)
    #[arg(long)]
    pub power: Option<u32>,
    /// Newton polynomial, highest degree first (e.g. "1 0 0 -1" for z³ − 1)
    #[arg(long, allow_hyphen_values = true)]
    pub poly: Option<String>,
    /// Logistic start z₀ as RE,IM (default 0.5,0)
    #[arg(long, allow_hyphen_values = true)]
    pub z0: Option<String>,
    /// Cubic z³ + z + p: p as RE,IM (default 0.171)
    #[arg(long, allow_hyphen_values = true)]
    pub p: Option<String>,
    /// Centre of the view as X,Y
    #[arg(long, allow_hyphen_values = true)]
    pub center: Option<String>,
    /// World width of the view (any exponent down to 1e-10000, e.g. 1e-1000)
    #[arg(long, allow_hyphen_values = true)]
    pub width: Option<String>,
    /// Image size WxH
    #[arg(long, value_parser = super::parse_size)]
    pub size: Option<(u32, u32)>,
    /// Maximum iterations
    #[arg(long)]
    pub max_iter: Option<u32>,
    /// Deep zoom: relative size of the non-linear terms a bilinear step may drop (default
    /// 2^-44 ≈ 5.7e-14; Fractalshades' default is 1e-6: faster, less exact), 1.1e-16 to 0.001
    #[arg(long, value_parser = super::finite)]
    pub bla_tolerance: Option<f64>,
    /// smooth, bands, distance, histogram or basins
    #[arg(long)]
    pub coloring: Option<String>,
    /// A built-in gradient name or a .ugr/.map/.ggr/image file
    #[arg(long)]
    pub gradient: Option<String>,
    /// Gradient offset (fraction 0–1)
    #[arg(long, allow_hyphen_values = true, value_parser = super::finite)]
    pub offset: Option<f64>,
    /// Gradient entries per iteration
    #[arg(long, value_parser = super::finite)]
    pub repeat: Option<f64>,
    /// Escape radius (default 2, or 256 for smooth colourings)
    #[arg(long, value_parser = super::finite)]
    pub bailout: Option<f64>,
    /// Mariani–Silver block filling instead of computing every pixel
    #[arg(long)]
    pub guess: bool,
    /// Warped Julia: Möbius warp parameter α as RE,IM
    #[arg(long, allow_hyphen_values = true)]
    pub alpha: Option<String>,
    /// Warped Julia: turbulence amount λ
    #[arg(long, value_parser = super::finite)]
    pub turbulence: Option<f64>,
    /// Warped Julia: polar (seamless) sampling
    #[arg(long, conflicts_with = "rect")]
    pub polar: bool,
    /// Warped Julia: rectangular sampling
    #[arg(long)]
    pub rect: bool,
    /// Worker threads (default: all cores; at most 4 per core)
    #[arg(long, default_value_t = 0)]
    pub threads: usize,
    /// Also save the view as a .esc file
    #[arg(long)]
    pub save_view: Option<PathBuf>,
    /// Output image (.png or .bmp), or iteration data (.exr: channels N, NF, DEX, DEY as
    /// Kalles Fraktaler and zoomasm read them)
    #[arg(short, long, required_unless_present = "zoom_video")]
    pub output: Option<PathBuf>,
    /// Make a zoom video (.mp4, .webm, .mkv, .mov, .gif or .apng) from --zoom-from into the view
    #[arg(long)]
    pub zoom_video: Option<PathBuf>,
    /// Frames of the zoom video
    #[arg(long, default_value_t = 250)]
    pub frames: u32,
    /// Frames per second of the zoom video
    #[arg(long, default_value_t = 25.0, value_parser = super::finite)]
    pub fps: f64,
    /// Width the zoom video starts from
    #[arg(long, default_value_t = 4.0, value_parser = super::finite)]
    pub zoom_from: f64,
    /// Folder of the zoom video's keyframes, kept to resume (default: VIDEO.keyframes)
    #[arg(long)]
    pub keyframes: Option<PathBuf>,
}

fn complex(s: &Option<String>, what: &str) -> Result<Option<C>> {
    match s {
        None => Ok(None),
        Some(v) => parse_complex(v)
            .map(Some)
            .with_context(|| format!("--{what} '{v}': expected RE,IM (e.g. -0.8,0.156)")),
    }
}

/// Build the document from the arguments.
pub fn doc_from_args(a: &EscapeArgs) -> Result<EscapeDoc> {
    let mut doc = match (&a.view, &a.kind) {
        (Some(v), _) => {
            let p = escape_view::read(v)?;
            for w in &p.warnings {
                stderr!("{w}");
            }
            let mut doc = p.value;
            // A gradient file named relative to the view: absolute, so that the view saved
            // elsewhere (--save-view) still finds it.
            if ugnis::gradient::builtin_named(&doc.gradient_source).is_none() {
                let f = escape_view::gradient_path(&doc.gradient_source, v.parent());
                if let Ok(abs) = std::fs::canonicalize(f) {
                    doc.gradient_source = abs.display().to_string();
                }
            }
            doc
        }
        (None, Some(k)) => EscapeDoc::new(family_from_name(k).with_context(|| {
            format!("unknown kind '{k}': expected mandelbrot, julia, multibrot, burning-ship, newton, logistic, cubic or warped-julia")
        })?),
        (None, None) => bail!("give a KIND (e.g. mandelbrot) or --view FILE"),
    };
    if let (Some(_), Some(k)) = (&a.view, &a.kind)
        && family_from_name(k).map(|f| f.name()) != Some(doc.params.family.name())
    {
        doc.params.family = family_from_name(k).with_context(|| format!("unknown kind '{k}'"))?;
    }
    if let Some((w, h)) = a.size {
        doc.resize(w, h);
    }
    let c = complex(&a.c, "c")?;
    match &mut doc.params.family {
        Family::Mandelbrot { power } => {
            if let Some(p) = a.power {
                *power = p;
            }
        }
        Family::Julia { power, c: jc } => {
            if let Some(p) = a.power {
                *power = p;
            }
            if let Some(v) = c {
                *jc = v;
            }
        }
        Family::Newton { coeffs } => {
            if let Some(s) = &a.poly {
                *coeffs = parse_poly(s).with_context(|| {
                    format!("--poly '{s}': expected 2–33 coefficients, highest degree first, e.g. \"1 0 0 -1\"")
                })?;
            }
        }
        Family::Logistic { z0, .. } => {
            if let Some(v) = complex(&a.z0, "z0")? {
                *z0 = v;
            }
        }
        Family::Cubic { p } => {
            if let Some(v) = complex(&a.p, "p")? {
                *p = v;
            }
        }
        Family::BurningShip => {}
        Family::WarpedJulia(w) => {
            let sampling = if a.polar {
                Sampling::Polar { radius: 1.0 }
            } else if a.rect {
                Sampling::Rect { scale: 3.0 }
            } else {
                w.sampling
            };
            *w = Warp::new(
                c.unwrap_or(w.c),
                complex(&a.alpha, "alpha")?.unwrap_or(w.alpha),
                a.turbulence.unwrap_or(w.lambda),
                if a.turbulence.is_some() && w.lambda == 0.0 {
                    Fbm::default()
                } else {
                    w.fbm
                },
                sampling,
                w.zero_mean,
            )?;
        }
    }
    if let Some(v) = &a.center {
        let c = escape_view::parse_center(v).map_err(|e| {
            let shown: String = v.chars().take(60).collect();
            anyhow::anyhow!("--center '{shown}…': {e}; expected RE,IM (e.g. -0.75,0.1)")
        })?;
        doc.view = doc.view.with_centre(c);
    }
    if let Some(wd) = &a.width {
        let wd = escape_view::parse_width(wd).map_err(|e| anyhow::anyhow!("--width: {e}"))?;
        doc.set_world_width_fx(wd);
    }
    if let Some(n) = a.max_iter {
        doc.params.max_iter = n;
    }
    if let Some(e) = a.bla_tolerance {
        if !ugnis::escape::BLA_TOLERANCE_RANGE.contains(&e) {
            anyhow::bail!("--bla-tolerance {e}: expected a number from 1.1e-16 (2^-53) to 0.001");
        }
        doc.params.bla_eps = e;
    }
    if let Some(s) = &a.coloring {
        doc.params.coloring = Coloring::from_name(s).with_context(|| {
            format!("--coloring '{s}': expected smooth, bands, distance, histogram or basins")
        })?;
    }
    if let Some(g) = &a.gradient {
        let p = escape_view::resolve_gradient_parsed(g, None).map_err(|e| anyhow::anyhow!(e))?;
        for w in &p.warnings {
            stderr!("{w}");
        }
        doc.params.palette.gradient = p.value;
        // A saved view resolves relative paths from its own directory: keep files absolute.
        doc.gradient_source = if ugnis::gradient::builtin_named(g).is_some() {
            g.clone()
        } else {
            std::fs::canonicalize(g).map_or_else(|_| g.clone(), |p| p.display().to_string())
        };
    }
    if let Some(o) = a.offset {
        doc.params.palette.offset = o;
    }
    if let Some(r) = a.repeat {
        if !r.is_finite() || r <= 0.0 {
            bail!("--repeat {r} must be positive");
        }
        doc.params.palette.repeat = r;
    }
    if let Some(b) = a.bailout {
        if !(b > 0.0 && b.is_finite()) {
            bail!("--bailout {b} must be positive");
        }
        doc.params.bailout = Some(b);
    }
    if a.guess {
        doc.params.fill = Fill::Guess;
    }
    Ok(doc)
}

/// A zoom video of the view.
fn run_zoom_video(a: &EscapeArgs, video: &std::path::Path) -> Result<()> {
    let doc = doc_from_args(a)?;
    let z = super::zoom_video::ZoomVideo {
        out: video.to_path_buf(),
        frames: a.frames,
        fps: a.fps,
        keyframes: a.keyframes.clone(),
        start_width: a.zoom_from,
    };
    super::check_outputs(&[], &[video])?;
    super::pool(a.threads)?.install(|| super::zoom_video::run(&doc, &z))
}

pub fn run(a: EscapeArgs) -> Result<()> {
    if let Some(v) = a.zoom_video.clone() {
        if a.output.is_some() {
            bail!("give either -o or --zoom-video");
        }
        return run_zoom_video(&a, &v);
    }
    let out = a.output.clone().context("give -o OUTPUT")?;
    let is_bmp = io::kind_of(&out) == FileKind::Bmp;
    let is_exr = is_exr(&out);
    if !is_bmp && !is_exr && io::kind_of(&out) != FileKind::Png {
        bail!("output '{}' must end in .png, .bmp or .exr", out.display());
    }
    let gradient_file = a
        .gradient
        .as_deref()
        .filter(|g| ugnis::gradient::builtin_named(g).is_none())
        .map(std::path::Path::new);
    let inputs: Vec<&std::path::Path> = [a.view.as_deref(), gradient_file]
        .into_iter()
        .flatten()
        .collect();
    let outputs: Vec<&std::path::Path> = [Some(out.as_path()), a.save_view.as_deref()]
        .into_iter()
        .flatten()
        .collect();
    super::check_outputs(&inputs, &outputs)?;
    let doc = doc_from_args(&a)?;
    // What is saved must read back: refuse a view that its own reader would refuse.
    let view_text = escape_view::write(&doc);
    escape_view::parse(&view_text, "the view", None)
        .map_err(|e| anyhow::anyhow!("the view cannot be saved as given: {}", e.message))?;
    let pool = super::pool(a.threads)?;
    if is_exr {
        return pool.install(|| write_exr(&doc, &out, a.save_view.as_deref()));
    }
    let img = pool.install(|| -> Result<image::RgbImage> {
        let mut r = EscapeRenderer::new(&doc.params, doc.view.clone(), doc.width, doc.height)?;
        let pb = super::progress_bar(
            doc.width as u64 * doc.height as u64,
            &format!("rendering {}", doc.params.family.name()),
        );
        let done = r.run_exact(super::no_cancel(), &|n| pb.inc(n));
        pb.finish_and_clear();
        if !done {
            return Err(super::stopped_early());
        }
        Ok(r.image())
    })?;
    let img = image::DynamicImage::ImageRgb8(img);
    // The image and the view are put in place together, or neither.
    let held = io::atomic::hold();
    if is_bmp {
        io::bmp::save(&out, &img).with_context(|| format!("cannot write '{}'", out.display()))?;
    } else {
        let meta = io::png::PngMeta {
            text: vec![("ugnis_escape_view".into(), view_text)],
            ..Default::default()
        };
        io::png::save(&out, &img, &meta)
            .with_context(|| format!("cannot write '{}'", out.display()))?;
    }
    if let Some(v) = &a.save_view {
        escape_view::save(v, &doc).with_context(|| format!("cannot write '{}'", v.display()))?;
    }
    Ok(held.commit()?)
}

fn is_exr(p: &std::path::Path) -> bool {
    p.extension()
        .is_some_and(|e| e.to_string_lossy().eq_ignore_ascii_case("exr"))
}

/// Render the samples of `doc` with distance estimates and write its iteration data.
fn write_exr(doc: &EscapeDoc, out: &std::path::Path, view: Option<&std::path::Path>) -> Result<()> {
    let mut params = doc.params.clone();
    // Distance colouring computes the estimates (and the smooth counts all colourings have).
    params.coloring = Coloring::Distance;
    let mut r = EscapeRenderer::new(&params, doc.view.clone(), doc.width, doc.height)?;
    let pb = super::progress_bar(
        doc.width as u64 * doc.height as u64,
        &format!("rendering {}", doc.params.family.name()),
    );
    let done = r.run_exact(super::no_cancel(), &|n| pb.inc(n));
    pb.finish_and_clear();
    if !done {
        return Err(super::stopped_early());
    }
    // Deep views estimate distances in pixels already, the others in world units.
    let de_scale = if ugnis::escape::is_deep(&params.family, &doc.view, doc.height) {
        1.0
    } else {
        1.0 / doc.view.pixel_size(doc.height)
    };
    let data = io::exr::IterationData::from_samples(r.samples(), doc.width, doc.height, de_scale);
    let held = io::atomic::hold();
    data.save(out)
        .with_context(|| format!("cannot write '{}'", out.display()))?;
    if let Some(v) = view {
        escape_view::save(v, doc).with_context(|| format!("cannot write '{}'", v.display()))?;
    }
    Ok(held.commit()?)
}
