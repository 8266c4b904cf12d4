//! `ugnis info`: what a file holds.

use std::fmt::Write as _;
use std::path::PathBuf;

use anyhow::Result;
use clap::Args;

use ugnis::io::{self, FileKind};

#[derive(Args, Debug)]
pub struct InfoArgs {
    /// A flame (.fla/.flame/.flam3/.png), IFS (.ifs) or gradient (.ugr/.map/.ggr) file
    pub file: PathBuf,
}

pub fn run(a: InfoArgs) -> Result<()> {
    let path = &a.file;
    // Written at once; a reader that stops early (`| head -1`) ends the output quietly.
    let mut out = String::new();
    match io::kind_of(path) {
        FileKind::Ifs => {
            let p = io::read_ifs(path)?;
            for w in &p.warnings {
                eprintln!("{w}");
            }
            let _ = writeln!(
                out,
                "{}: Fractint IFS, {} entries",
                path.display(),
                p.value.entries.len()
            );
            for e in &p.value.entries {
                let _ = writeln!(
                    out,
                    "  {:<20} {}  {} maps",
                    e.name,
                    if e.three_d { "3-D" } else { "2-D" },
                    e.rows.len()
                );
            }
        }
        FileKind::Ugr | FileKind::Map | FileKind::Ggr => {
            let p = io::read_gradients(path)?;
            for w in &p.warnings {
                eprintln!("{w}");
            }
            let _ = writeln!(out, "{}: {} gradient(s)", path.display(), p.value.len());
            for g in &p.value {
                let n = g.map_entries.as_ref().map_or(256, |e| e.len());
                let _ = writeln!(out, "  {:<24} {n} colours", g.name);
            }
        }
        _ => {
            let p = io::read_flames(path, &Default::default())?;
            for w in &p.warnings {
                eprintln!("{w}");
            }
            let _ = writeln!(out, "{}: {} flame(s)", path.display(), p.value.len());
            for f in &p.value {
                let _ = writeln!(
                    out,
                    "  {:<24} {}x{}  {} xforms{}  variations: {}",
                    if f.name.is_empty() {
                        "(unnamed)"
                    } else {
                        &f.name
                    },
                    f.width,
                    f.height,
                    f.xforms.len(),
                    if f.final_xform.is_some() {
                        " + final"
                    } else {
                        ""
                    },
                    f.variations_used().join(", ")
                );
            }
        }
    }
    super::print_stdout(&out)
}
