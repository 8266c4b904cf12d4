//! `ugnis lorenz`: draw the Lorenz attractor, and show how two starts 1e-9 apart drift apart.

use std::path::PathBuf;

use anyhow::{Context, Result, bail};
use clap::{Args, ValueEnum};

use ugnis::explore::lorenz::{Lorenz, RenderOptions, View};
use ugnis::io::{self, FileKind};

#[derive(Clone, Copy, Debug, ValueEnum)]
pub enum ViewArg {
    /// x–y plane (seen along z)
    Xy,
    /// x–z plane (the butterfly)
    Xz,
    /// y–z plane (seen along x)
    Yz,
    /// turned by --yaw and --pitch
    Turned,
}

#[derive(Args, Debug)]
pub struct LorenzArgs {
    /// σ (0 < σ ≤ 100)
    #[arg(long, default_value_t = 10.0)]
    pub sigma: f64,
    /// r (0 < r ≤ 1000)
    #[arg(long, default_value_t = 28.0)]
    pub r: f64,
    /// b (0 < b ≤ 100; default 8/3)
    #[arg(long, default_value_t = 8.0 / 3.0)]
    pub b: f64,
    /// Runge–Kutta step h (1e-5 to 0.1; 0.005 for high quality)
    #[arg(long, default_value_t = 0.01)]
    pub h: f64,
    /// Time drawn after the transient (at most 10⁸ steps)
    #[arg(long, default_value_t = 200.0)]
    pub time: f64,
    /// Time integrated before drawing (0 to 1e9)
    #[arg(long, default_value_t = 10.0)]
    pub transient: f64,
    /// Start point X,Y,Z
    #[arg(long, default_value = "1,1,1", allow_hyphen_values = true)]
    pub start: String,
    /// Projection
    #[arg(long, value_enum, default_value_t = ViewArg::Xz)]
    pub view: ViewArg,
    /// Turned view: degrees about z
    #[arg(long, default_value_t = -45.0, allow_hyphen_values = true)]
    pub yaw: f64,
    /// Turned view: degrees about x
    #[arg(long, default_value_t = 20.0, allow_hyphen_values = true)]
    pub pitch: f64,
    /// Picture size WxH (up to 16384 per side)
    #[arg(long, value_parser = super::parse_size, default_value = "800x600")]
    pub size: (u32, u32),
    /// Also print how far a second start, 1e-9 further in x, drifts away
    #[arg(long)]
    pub sensitivity: bool,
    /// Output image (.png or .bmp)
    #[arg(short, long)]
    pub output: PathBuf,
}

fn parse_start(s: &str) -> Result<[f64; 3]> {
    let v: Vec<f64> = s
        .split(',')
        .map(|t| t.trim().parse::<f64>())
        .collect::<Result<_, _>>()
        .with_context(|| format!("--start '{s}': expected X,Y,Z (e.g. 1,1,1)"))?;
    match v.as_slice() {
        [x, y, z] => Ok([*x, *y, *z]),
        _ => bail!("--start '{s}': expected three numbers X,Y,Z"),
    }
}

pub fn run(a: LorenzArgs) -> Result<()> {
    let is_bmp = io::kind_of(&a.output) == FileKind::Bmp;
    if !is_bmp && io::kind_of(&a.output) != FileKind::Png {
        bail!("output '{}' must end in .png or .bmp", a.output.display());
    }
    super::check_outputs(&[], &[&a.output])?;
    for (what, v) in [("--time", a.time), ("--transient", a.transient)] {
        if !(v.is_finite() && (0.0..=1e9).contains(&v)) {
            bail!("{what} {v} must be between 0 and 1e9 (time units of the equations)");
        }
    }
    for (what, v) in [("--yaw", a.yaw), ("--pitch", a.pitch)] {
        if !(v.is_finite() && v.abs() <= 360.0) {
            bail!("{what} {v} must be between -360 and 360 degrees");
        }
    }
    let l = Lorenz::new(a.sigma, a.r, a.b)?;
    let start = parse_start(&a.start)?;
    let view = match a.view {
        ViewArg::Xy => View::Xy,
        ViewArg::Xz => View::Xz,
        ViewArg::Yz => View::Yz,
        ViewArg::Turned => View::Turned {
            yaw: a.yaw.to_radians(),
            pitch: a.pitch.to_radians(),
        },
    };
    let (width, height) = a.size;
    let o = RenderOptions {
        start,
        h: a.h,
        transient: a.transient,
        time: a.time,
        view,
        width,
        height,
        ..RenderOptions::default()
    };
    let img = image::DynamicImage::ImageRgb8(l.render(&o)?);
    if is_bmp {
        io::bmp::save(&a.output, &img)
    } else {
        io::png::save(&a.output, &img, &Default::default())
    }
    .with_context(|| format!("cannot write '{}'", a.output.display()))?;
    println!(
        "Lorenz σ = {}, r = {}, b = {}: t = {} to {} with h = {} -> {}",
        a.sigma,
        a.r,
        a.b,
        a.transient,
        a.transient + a.time,
        a.h,
        a.output.display()
    );
    if a.sensitivity {
        let b = [start[0] + 1e-9, start[1], start[2]];
        let mut t = l.twin(start, b, a.h)?;
        let end = a.transient + a.time;
        let steps = Lorenz::steps_for(end, a.h)?;
        let every = Lorenz::steps_for(5.0, a.h)?.max(1);
        let mut first_apart: Option<f64> = None;
        println!("two starts 1e-9 apart in x; largest coordinate difference:");
        for i in 1..=steps {
            t.step();
            if first_apart.is_none() && t.separation() > 1.0 {
                first_apart = Some(t.time());
            }
            if i % every == 0 {
                println!("  t = {:>7.2}  {:.3e}", t.time(), t.separation());
            }
        }
        match first_apart {
            Some(tt) => println!("more than 1 apart first at t = {tt:.2}"),
            None => println!("still within 1 of each other at t = {end}"),
        }
    }
    Ok(())
}
