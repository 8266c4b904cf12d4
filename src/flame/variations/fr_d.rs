//! Variations (slice fr_d of the registry).

#[allow(unused_imports)]
use super::*;

pub(super) static DEFS: &[VarDef] = &[];
