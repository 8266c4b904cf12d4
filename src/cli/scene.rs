//! `ugnis scene`: render a textured Bézier scene file to PNG or BMP.

use std::path::PathBuf;

use anyhow::{Context, Result, bail};
use clap::Args;

use ugnis::io::{self, FileKind};

#[derive(Args, Debug)]
pub struct SceneArgs {
    /// Scene file (.toml)
    pub file: PathBuf,
    /// Output image (.png or .bmp)
    #[arg(short, long)]
    pub output: PathBuf,
    /// Image size WxH (default: the scene's own; the framing scales with the height)
    #[arg(long, value_parser = super::parse_size)]
    pub size: Option<(u32, u32)>,
    /// Supersampling per axis (1–4; default: the scene's own)
    #[arg(long)]
    pub supersample: Option<u32>,
    /// Worker threads (default: all cores)
    #[arg(long, default_value_t = 0)]
    pub threads: usize,
}

pub fn run(a: SceneArgs) -> Result<()> {
    let is_bmp = io::kind_of(&a.output) == FileKind::Bmp;
    if !is_bmp && io::kind_of(&a.output) != FileKind::Png {
        bail!("output '{}' must end in .png or .bmp", a.output.display());
    }
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(a.threads)
        .build()
        .context("cannot start worker threads")?;
    let img = pool.install(|| -> Result<image::RgbImage> {
        let mut loaded = io::scene::read(&a.file)?;
        if let Some((w, h)) = a.size {
            loaded.scene.width = w;
            loaded.scene.height = h;
        }
        if let Some(s) = a.supersample {
            if !(1..=4).contains(&s) {
                bail!("--supersample {s} must be between 1 and 4");
            }
            loaded.scene.supersample = s;
        }
        ugnis::surface::render(&loaded.scene, None).context("rendering was cancelled")
    })?;
    let img = image::DynamicImage::ImageRgb8(img);
    if is_bmp {
        io::bmp::save(&a.output, &img)
    } else {
        io::png::save(&a.output, &img, &Default::default())
    }
    .with_context(|| format!("cannot write '{}'", a.output.display()))
}
