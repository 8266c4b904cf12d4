//! Variations (slice fr_c of the registry).

#[allow(unused_imports)]
use super::*;

pub(super) static DEFS: &[VarDef] = &[];
