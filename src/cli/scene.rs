//! `ugnis scene`: render a scene file (textured Bézier surfaces, meshes, Menger sponges,
//! quaternion Julia sets) to PNG or BMP with the z-buffer or the ray caster.

use std::path::PathBuf;

use anyhow::{Context, Result, bail};
use clap::{Args, ValueEnum};

use ugnis::io::{self, FileKind};
use ugnis::surface::Renderer;

#[derive(Clone, Copy, Debug, ValueEnum)]
pub enum RenderArg {
    Zbuffer,
    Raycast,
}

#[derive(Clone, Copy, Debug, ValueEnum)]
pub enum OnOff {
    On,
    Off,
}

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
    /// Renderer (default: the scene's own `render`, else zbuffer)
    #[arg(long, value_enum)]
    pub render: Option<RenderArg>,
    /// Shadow rays when ray casting (default: the scene's own `shadows`, else on)
    #[arg(long, value_enum)]
    pub shadows: Option<OnOff>,
    /// Worker threads (default: all cores; at most 4 per core)
    #[arg(long, default_value_t = 0)]
    pub threads: usize,
}

pub fn run(a: SceneArgs) -> Result<()> {
    let is_bmp = io::kind_of(&a.output) == FileKind::Bmp;
    if !is_bmp && io::kind_of(&a.output) != FileKind::Png {
        bail!("output '{}' must end in .png or .bmp", a.output.display());
    }
    super::check_outputs(&[&a.file], &[&a.output])?;
    // The size is checked before the scene's textures are made (which takes a while).
    if let Some((w, h)) = a.size {
        let max = ugnis::surface::MAX_SIDE;
        if w > max || h > max {
            bail!("--size {w}x{h}: a scene image is at most {max}x{max}");
        }
    }
    let pool = super::pool(a.threads)?;
    let img = pool.install(|| -> Result<image::RgbImage> {
        let mut parsed = io::scene::read_spec(&a.file)?;
        for w in &parsed.warnings {
            stderr!("{w}");
        }
        let scene = &mut parsed.spec.scene;
        if let Some((w, h)) = a.size {
            scene.width = w;
            scene.height = h;
        }
        if let Some(s) = a.supersample {
            if !(1..=4).contains(&s) {
                bail!("--supersample {s} must be between 1 and 4");
            }
            scene.supersample = s;
        }
        match a.render {
            Some(RenderArg::Zbuffer) => scene.renderer = Renderer::ZBuffer,
            Some(RenderArg::Raycast) => scene.renderer = Renderer::RayCast,
            None => {}
        }
        if let Some(sh) = a.shadows {
            if scene.renderer != Renderer::RayCast {
                bail!("--shadows needs the ray caster (--render raycast or render = \"raycast\" in the scene)");
            }
            scene.shadows = matches!(sh, OnOff::On);
        }
        // A texture's file is an input too.
        let inputs: Vec<&std::path::Path> = parsed.files.iter().map(|p| p.as_path()).collect();
        super::check_outputs(&inputs, &[&a.output])?;
        for n in &parsed.notes {
            println!("{n}");
        }
        let loaded = parsed.build()?;
        match ugnis::surface::try_render(&loaded.scene, Some(super::no_cancel())) {
            Ok(img) => Ok(img),
            Err(ugnis::surface::RenderError::Cancelled) => Err(super::stopped_early()),
            Err(e) => Err(e).with_context(|| format!("cannot render '{}'", a.file.display())),
        }
    })?;
    let img = image::DynamicImage::ImageRgb8(img);
    if is_bmp {
        io::bmp::save(&a.output, &img)
    } else {
        io::png::save(&a.output, &img, &Default::default())
    }
    .with_context(|| format!("cannot write '{}'", a.output.display()))
}
