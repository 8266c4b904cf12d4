//! The reader's context: the file's source map, the warnings collected so far (with a cap per
//! code), the attribute names kept but not interpreted, typed attribute values with their
//! diagnostics, and flam3's palette library loaded on first use.

use std::cell::OnceCell;
use std::collections::{HashMap, HashSet};

use super::{LibrarySource, MAX_WARNINGS_PER_CODE, ReadOptions};
use crate::io::diag::{Diagnostic, Pos, SourceMap, parse_int, parse_number};
use crate::io::palettes::{self, PaletteLibrary};
use crate::io::xml::{Attr, scan_attrs_jwf};

pub(super) struct Ctx<'t, 'o> {
    pub(super) file: &'t str,
    pub(super) map: SourceMap<'t>,
    pub(super) warnings: Vec<Diagnostic>,
    pub(super) reported_vars: HashSet<String>,
    /// Attribute names without a value reported so far (each once per file).
    pub(super) reported_valueless: HashSet<String>,
    /// Attributes of other programs that ugnis keeps but does not interpret (reported once per
    /// file, in one line).
    pub(super) ignored_attrs: Vec<String>,
    /// Hashes of all of them (for counting distinct names without keeping every name).
    pub(super) ignored_set: HashSet<u64>,
    /// Warnings per code so far; past [`MAX_WARNINGS_PER_CODE`] they are only counted.
    pub(super) warn_counts: HashMap<&'static str, usize>,
    pub(super) opts: &'o ReadOptions<'o>,
    /// The flame being read was written by JWildfire, which reads a variation's parameters by
    /// their exact names (letter case included).
    pub(super) jwildfire_names: bool,
    /// The flame being read is drawn as JWildfire draws it (JWildfire wrote it, or ugnis copied
    /// one JWildfire wrote): variations that colour or hide points act at amount 0.
    pub(super) jwildfire_flame: bool,
    /// The flame being read was written by Apophysis, whose plugins may name their parameters
    /// without the variation's prefix (pixel_flow's `angle` for `pixel_flow_angle`).
    pub(super) apophysis_names: bool,
    pub(super) library: OnceCell<Result<PaletteLibrary, String>>,
}

pub(super) type R<T> = Result<T, Diagnostic>;

fn name_hash(name: &str) -> u64 {
    use std::hash::{BuildHasher, BuildHasherDefault};
    BuildHasherDefault::<std::collections::hash_map::DefaultHasher>::default().hash_one(name)
}

impl<'t, 'o: 't> Ctx<'t, 'o> {
    /// A context for reading `text` (without its byte order mark).
    pub(super) fn new(text: &'t str, opts: &'o ReadOptions<'o>) -> Self {
        Ctx {
            file: &opts.file,
            map: SourceMap::new(text),
            warnings: Vec::new(),
            reported_vars: HashSet::new(),
            reported_valueless: HashSet::new(),
            ignored_attrs: Vec::new(),
            ignored_set: HashSet::new(),
            warn_counts: Default::default(),
            opts,
            jwildfire_names: false,
            jwildfire_flame: false,
            apophysis_names: false,
            library: OnceCell::new(),
        }
    }
}

impl Ctx<'_, '_> {
    /// The warnings of the file, followed by one line per code with warnings past the cap and
    /// one line naming the attributes kept but not interpreted.
    pub(super) fn finish(mut self) -> Vec<Diagnostic> {
        let mut hidden: Vec<(&str, usize)> = self
            .warn_counts
            .iter()
            .filter(|(_, n)| **n > MAX_WARNINGS_PER_CODE)
            .map(|(c, n)| (*c, n - MAX_WARNINGS_PER_CODE))
            .collect();
        hidden.sort();
        for (code, n) in hidden {
            self.warnings.push(Diagnostic::warning(
                self.file,
                Pos::File,
                code,
                format!("{n} more warnings like the above are not shown"),
            ));
        }
        if !self.ignored_set.is_empty() {
            let n = self.ignored_set.len();
            let mut shown: Vec<&str> = self
                .ignored_attrs
                .iter()
                .take(6)
                .map(|s| s.as_str())
                .collect();
            if n > 6 {
                shown.push("…");
            }
            let d = Diagnostic::warning(
                self.file,
                Pos::File,
                "XML021",
                format!(
                    "kept {n} attribute name{} of other programs that ugnis does not interpret ({}); \
                     they are written back unchanged",
                    if n == 1 { "" } else { "s" },
                    shown.join(", ")
                ),
            );
            self.warnings.push(d);
        }
        self.warnings
    }

    /// Counts `name` among the attributes kept but not interpreted (the first six are named in
    /// the file's summary line).
    pub(super) fn ignore(&mut self, name: &str) {
        if self.ignored_set.insert(name_hash(name)) && self.ignored_attrs.len() < 6 {
            self.ignored_attrs.push(name.to_string());
        }
    }

    /// Takes `name` back out of the attributes kept but not interpreted (it was interpreted
    /// after all, e.g. as part of a JWildfire curve).
    pub(super) fn interpreted(&mut self, name: &str) {
        if self.ignored_set.remove(&name_hash(name)) {
            self.ignored_attrs.retain(|n| n != name);
        }
    }

    /// The attributes of a tag whose text between `<` and `>` starts at byte `base`, read as
    /// JWildfire reads them ([`scan_attrs_jwf`]; what is not XML is reported as a warning).
    pub(super) fn attrs<'e>(&mut self, content: &'e str, base: usize) -> R<Vec<Attr<'e>>> {
        let mut notes = Vec::new();
        let attrs =
            scan_attrs_jwf(content, base, &mut notes).map_err(|(o, m)| self.err(o, "XML001", m))?;
        for (off, m) in notes {
            // Once per file for each name without a value, once for the first name that is not XML.
            let word = if m.ends_with(" is not XML; read as JWildfire reads it") {
                " is not XML".to_string()
            } else {
                m.split(" has no value").next().unwrap_or("").to_string()
            };
            if self.reported_valueless.insert(word) {
                self.warn(off, "XML024", m);
            }
        }
        Ok(attrs)
    }

    pub(super) fn err(&self, off: usize, code: &'static str, msg: impl Into<String>) -> Diagnostic {
        Diagnostic::error(self.file, self.map.pos(off), code, msg)
    }

    pub(super) fn warn(&mut self, off: usize, code: &'static str, msg: impl Into<String>) {
        let n = self.warn_counts.entry(code).or_insert(0);
        *n += 1;
        if *n > MAX_WARNINGS_PER_CODE {
            return;
        }
        let d = Diagnostic::warning(self.file, self.map.pos(off), code, msg);
        self.warnings.push(d);
    }

    pub(super) fn num(&self, a: &Attr) -> R<f64> {
        parse_number(a.value.trim()).map_err(|e| {
            self.err(
                a.offset,
                "XML003",
                format!("attribute '{}': {}", a.name, e.describe(a.value.trim())),
            )
        })
    }

    pub(super) fn nums(&self, a: &Attr, code: &'static str) -> R<Vec<f64>> {
        a.value
            .split_whitespace()
            .map(|t| {
                parse_number(t).map_err(|e| {
                    self.err(
                        a.offset,
                        code,
                        format!("attribute '{}': {}", a.name, e.describe(t)),
                    )
                })
            })
            .collect()
    }

    pub(super) fn fixed<const N: usize>(
        &self,
        a: &Attr,
        code: &'static str,
        what: &str,
    ) -> R<[f64; N]> {
        let v = self.nums(a, code)?;
        v.try_into().map_err(|v: Vec<f64>| {
            self.err(
                a.offset,
                code,
                format!(
                    "attribute '{}' must hold {N} {what}, found {}",
                    a.name,
                    v.len()
                ),
            )
        })
    }

    pub(super) fn int(&self, a: &Attr) -> R<i64> {
        parse_int(a.value.trim()).map_err(|_| {
            self.err(
                a.offset,
                "XML003",
                format!(
                    "attribute '{}': '{}' is not an integer",
                    a.name,
                    a.value.trim()
                ),
            )
        })
    }

    pub(super) fn library(&self) -> &Result<PaletteLibrary, String> {
        self.library.get_or_init(|| {
            let paths = match &self.opts.library {
                LibrarySource::Loaded(l) => return Ok((*l).clone()),
                LibrarySource::Search => palettes::default_paths(),
                LibrarySource::Paths(p) => p.clone(),
            };
            match palettes::find(Some(&paths)) {
                Some(p) => palettes::load(&p)
                    .map(|l| l.value)
                    .map_err(|d| d.to_string()),
                None => Err(format!(
                    "flam3-palettes.xml was not found (looked in {}); install flam3's palette file \
                     (Debian: flam3-palette), set FLAM3_PALETTES, or pass --palettes PATH",
                    paths
                        .iter()
                        .map(|p| p.display().to_string())
                        .collect::<Vec<_>>()
                        .join(", ")
                )),
            }
        })
    }
}
