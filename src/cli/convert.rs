//! `ugnis convert`: between .ifs and .fla/.flame, between .ugr, .map and .ggr, from a PNG with an
//! embedded flame to .fla, and from an image to a gradient.

use std::path::PathBuf;

use anyhow::{Result, bail};
use clap::Args;

use ugnis::io::{self, FileKind, View};

#[derive(Args, Debug)]
pub struct ConvertArgs {
    /// Input file
    pub input: PathBuf,
    /// Output file; its extension chooses the format
    pub output: PathBuf,
}

fn is_flames(k: FileKind) -> bool {
    matches!(k, FileKind::Fla | FileKind::FlameXml | FileKind::Ifs)
}

pub fn run(a: ConvertArgs) -> Result<()> {
    let (ki, ko) = (io::kind_of(&a.input), io::kind_of(&a.output));
    if is_flames(ko) || matches!(ko, FileKind::Ugr | FileKind::Map | FileKind::Ggr) {
        super::check_outputs(&[&a.input], &[&a.output])?;
    }
    if is_flames(ko) {
        // Any file the flame editor opens, but not one of unknown kind.
        if io::view_of(ki) != View::Flame || ki == FileKind::Unknown {
            bail!("{}: cannot convert this file to flames", a.input.display());
        }
        let p = super::read_flame_file(&a.input, &Default::default())?;
        for w in &p.warnings {
            stderr!("{w}");
        }
        let from_ifs = ki == FileKind::Ifs;
        let mut flames = Vec::new();
        for mut f in p.value.flames {
            if f.ifs3d.is_some() && ko != FileKind::Ifs {
                stderr!(
                    "warning: skipping '{}': 3-D IFS entries cannot be represented as flames",
                    f.name
                );
                continue;
            }
            // IFS entries have no camera: frame them now, so other programs get one.
            if from_ifs && f.ifs3d.is_none() {
                ugnis::flame::apply_auto_frame(&mut f);
            }
            flames.push(f);
        }
        if from_ifs && flames.is_empty() {
            bail!("{}: nothing to convert", a.input.display());
        }
        let name = Some(p.value.name)
            .filter(|n| !n.is_empty())
            .unwrap_or_else(|| {
                a.output
                    .file_stem()
                    .map(|s| s.to_string_lossy().into_owned())
                    .unwrap_or_default()
            });
        for w in io::write_flames(&a.output, &name, &flames)? {
            stderr!("warning: {w}");
        }
        return Ok(());
    }
    if matches!(ko, FileKind::Ugr | FileKind::Map | FileKind::Ggr) {
        let p = io::read_gradients(&a.input)?;
        for w in &p.warnings {
            stderr!("{w}");
        }
        let gradients = if ko != FileKind::Ugr && p.value.len() > 1 {
            stderr!(
                "warning: {} holds {} gradients; a .{} keeps one, writing the first ('{}')",
                a.input.display(),
                p.value.len(),
                if ko == FileKind::Map { "map" } else { "ggr" },
                p.value[0].name
            );
            p.value[..1].to_vec()
        } else {
            p.value
        };
        io::write_gradients(&a.output, &gradients)?;
        return Ok(());
    }
    bail!(
        "cannot convert {} to {}: supported are .ifs ↔ .fla/.flame, .png (with a flame) → .fla, .ugr ↔ .map ↔ .ggr, image → .ugr/.map/.ggr",
        a.input.display(),
        a.output.display()
    )
}
