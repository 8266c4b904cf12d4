//! `ugnis info`: what a file holds.

use std::fmt::Write as _;
use std::path::PathBuf;

use anyhow::Result;
use clap::Args;

use ugnis::io::flam3_xml::ReadOptions;
use ugnis::io::{self, FileKind};

#[derive(Args, Debug)]
#[command(group(clap::ArgGroup::new("what").required(true).args(["file", "variations"])))]
pub struct InfoArgs {
    /// A flame (.fla/.flame/.flam3/.png), IFS (.ifs), gradient (.ugr/.map/.ggr) or render state (.ugnis-state) file
    pub file: Option<PathBuf>,
    /// List every variation ugnis renders, with its parameters and defaults
    #[arg(long)]
    pub variations: bool,
}

/// A text parameter's default as the variation list shows it: quoted, or its size when it is
/// a whole document (more than one line or 60 characters), which would break the list's one
/// line per variation.
fn text_default(t: &str) -> String {
    if t.contains('\n') || t.chars().count() > 60 {
        format!("<text of {} lines, {} bytes>", t.lines().count(), t.len())
    } else {
        format!("\"{t}\"")
    }
}

/// One line per variation: name, origin, properties and parameters with their defaults.
fn list_variations() {
    use ugnis::flame::variations::{self, flag};
    let mut out = String::new();
    let (mut n, mut jwildfire) = (0, 0);
    for id in 0..variations::count() as variations::VarId {
        let d = variations::info(id);
        if d.has(flag::HIDDEN) {
            continue;
        }
        n += 1;
        let origin = if d.has(flag::FLAM3) {
            "flam3"
        } else if d.has(flag::JWILDFIRE) {
            "JWildfire"
        } else {
            "Fractorium"
        };
        let mut props = Vec::new();
        if d.is_3d() {
            props.push("3-D");
        }
        if d.has(flag::RANDOM) {
            props.push("random");
        }
        if d.has(flag::SETS_COLOR) {
            props.push("direct colour");
        }
        if d.has(flag::POST_ONLY) {
            props.push("post_ only");
        }
        if d.has(flag::PRE_ONLY) {
            props.push("pre_ only");
        }
        if d.has(flag::PREPOST) {
            props.push("pre and post");
        }
        if d.has(flag::JWILDFIRE) {
            jwildfire += 1;
        }
        let params: Vec<String> = d
            .params
            .iter()
            .map(|p| format!("{}={}", p.name, p.default))
            .chain(
                d.texts
                    .iter()
                    .map(|t| format!("{}={}", t.name, text_default(t.default))),
            )
            .collect();
        out.push_str(&format!(
            "{:<24} {:<10} {:<22} {}\n",
            d.name,
            origin,
            props.join(","),
            params.join(" ")
        ));
    }
    out.push_str(&format!(
        "{n} variations ({jwildfire} of them taken from JWildfire); each also as pre_NAME and post_NAME (before the others / \
         after their sum) unless marked pre_ or post_ only\n"
    ));
    // A closed pipe (e.g. `| head`) ends the listing quietly.
    use std::io::Write;
    let _ = std::io::stdout().lock().write_all(out.as_bytes());
}

pub fn run(a: InfoArgs) -> Result<()> {
    if a.variations {
        list_variations();
        return Ok(());
    }
    let Some(path) = a.file.as_ref() else {
        return Ok(());
    };
    // Written at once; a reader that stops early (`| head -1`) ends the output quietly.
    let mut out = String::new();
    if io::kind_of(path) == FileKind::RenderState {
        return describe_state(path);
    }
    match io::kind_of(path) {
        FileKind::Ifs => {
            let p = io::read_ifs(path)?;
            for w in &p.warnings {
                stderr!("{w}");
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
                stderr!("{w}");
            }
            let _ = writeln!(out, "{}: {} gradient(s)", path.display(), p.value.len());
            for g in &p.value {
                let n = g.map_entries.as_ref().map_or(256, |e| e.len());
                let _ = writeln!(out, "  {:<24} {n} colours", g.name);
            }
        }
        _ => {
            // flam3's template files (render settings, no xform) are described too.
            let opts = ReadOptions {
                templates: true,
                ..Default::default()
            };
            let p = super::read_flame_file(path, &opts)?;
            for w in &p.warnings {
                stderr!("{w}");
            }
            let flames = &p.value.flames;
            let _ = writeln!(out, "{}: {} flame(s)", path.display(), flames.len());
            for (i, f) in flames.iter().enumerate() {
                if f.xforms.is_empty() {
                    describe_template(&mut out, path, f, i == 0)?;
                    continue;
                }
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
                    match f.finals().count() {
                        0 => String::new(),
                        1 => " + final".to_string(),
                        n => format!(" + {n} finals"),
                    },
                    f.variations_used().join(", ")
                );
            }
        }
    }
    super::print_stdout(&out)
}

/// A flame without xforms: a template of render settings (flam3's `vidres.flam3`), with what
/// `render --template` takes from it (known for the file's first flame).
fn describe_template(
    out: &mut String,
    path: &std::path::Path,
    f: &ugnis::flame::Flame,
    first: bool,
) -> Result<()> {
    let name = if f.name.is_empty() {
        "(unnamed)"
    } else {
        &f.name
    };
    let _ = writeln!(
        out,
        "  {name:<24} {}x{}  template: render settings, no xforms",
        f.width, f.height
    );
    if first {
        let t = io::read_template_file(path, &Default::default())?.value;
        let applied = t.applied();
        let _ = writeln!(
            out,
            "    render --template applies: {}",
            if applied.is_empty() {
                "nothing".to_string()
            } else {
                applied.join(", ")
            }
        );
        let not = t.not_applied();
        if !not.is_empty() {
            let _ = writeln!(
                out,
                "    and leaves the flame's own (as flam3-genome does): {}",
                not.join(", ")
            );
        }
    }
    Ok(())
}

/// `ugnis info S.ugnis-state`.
fn describe_state(path: &std::path::Path) -> Result<()> {
    let rd = io::render_state::StateReader::open(path)?;
    let st = &rd.state;
    let f = &st.flame;
    let raw = rd.bw as u64 * rd.bh as u64 * 16;
    let packed = rd.compressed_bytes();
    let mut out = String::new();
    let _ = writeln!(out, "{}: ugnis render state", path.display());
    let _ = writeln!(
        out,
        "  flame       {}",
        if f.name.is_empty() {
            "(unnamed)"
        } else {
            &f.name
        }
    );
    let _ = writeln!(
        out,
        "  size        {}x{}, supersample {}, quality {}",
        f.width, f.height, f.supersample, f.quality
    );
    let parts: Vec<String> = st.parts.iter().map(|p| p.to_string()).collect();
    let _ = writeln!(out, "  seed        {}", st.seed);
    let _ = writeln!(
        out,
        "  parts       {} of {}",
        parts.join(","),
        st.part_count
    );
    let _ = writeln!(
        out,
        "  samples     {} done ({:.2} per pixel), {} bad values",
        st.samples_done,
        st.samples_done as f64 / (f.width as f64 * f.height as f64),
        st.bad_values
    );
    let status = if st.is_complete() {
        "complete"
    } else if st.is_finished() {
        "finished part(s): merge with the others"
    } else {
        "unfinished: continue with `ugnis render --resume`"
    };
    let _ = writeln!(out, "  status      {status}");
    let _ = writeln!(
        out,
        "  orbits      {} worker(s) (a resume with as many threads continues them)",
        st.lanes.len()
    );
    let _ = writeln!(
        out,
        "  histogram   {}x{} buckets, {} raw, {} stored ({:.1} %)",
        rd.bw,
        rd.bh,
        ugnis::memory::fmt_bytes(raw),
        ugnis::memory::fmt_bytes(packed),
        100.0 * packed as f64 / raw.max(1) as f64
    );
    super::print_stdout(&out)
}
