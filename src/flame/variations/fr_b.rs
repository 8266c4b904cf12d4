//! Variations (slice fr_b of the registry).

#[allow(unused_imports)]
use super::*;

pub(super) static DEFS: &[VarDef] = &[];
