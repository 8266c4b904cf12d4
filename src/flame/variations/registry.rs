//! The registry: every variation ugnis knows, by id, and the lookup tables built from it.

use std::collections::HashMap;
use std::sync::LazyLock;

use super::VarId;
use super::def::{VarDef, flag};
use super::{flam3, fr_a, fr_b, fr_c, fr_d, fr_e, fr_f, jwf, jwf2};

/// Every variation, by id.
pub fn all() -> &'static [&'static VarDef] {
    &REGISTRY.defs
}

/// Number of variations in the registry.
pub fn count() -> usize {
    REGISTRY.defs.len()
}

pub fn info(id: VarId) -> &'static VarDef {
    REGISTRY.defs[id as usize]
}

pub(super) struct Registry {
    pub(super) defs: Vec<&'static VarDef>,
    /// Lower-case name → id (hidden entries excluded).
    pub(super) names: HashMap<String, VarId>,
    /// Lower-case full parameter name → (id, parameter index).
    pub(super) params: HashMap<String, (VarId, usize)>,
    /// Lower-case full text parameter name → (id, text index).
    pub(super) texts: HashMap<String, (VarId, usize)>,
}

pub(super) static REGISTRY: LazyLock<Registry> = LazyLock::new(|| {
    let groups: [&'static [VarDef]; 9] = [
        flam3::DEFS,
        fr_a::DEFS,
        fr_b::DEFS,
        fr_c::DEFS,
        fr_d::DEFS,
        fr_e::DEFS,
        fr_f::DEFS,
        jwf::DEFS,
        jwf2::DEFS,
    ];
    let defs: Vec<&'static VarDef> = groups.iter().flat_map(|g| g.iter()).collect();
    let mut names = HashMap::new();
    let mut params = HashMap::new();
    let mut texts = HashMap::new();
    for (i, d) in defs.iter().enumerate() {
        if d.has(flag::HIDDEN) {
            continue;
        }
        let prev = names.insert(d.name.to_ascii_lowercase(), i as VarId);
        debug_assert!(prev.is_none(), "variation {} registered twice", d.name);
        for (k, pa) in d.params.iter().enumerate() {
            params.insert(pa.name.to_ascii_lowercase(), (i as VarId, k));
        }
        for (k, t) in d.texts.iter().enumerate() {
            texts.insert(t.name.to_ascii_lowercase(), (i as VarId, k));
        }
    }
    Registry {
        defs,
        names,
        params,
        texts,
    }
});
