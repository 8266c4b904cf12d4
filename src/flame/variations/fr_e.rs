//! Variations (slice fr_e of the registry).

#[allow(unused_imports)]
use super::*;

pub(super) static DEFS: &[VarDef] = &[];
