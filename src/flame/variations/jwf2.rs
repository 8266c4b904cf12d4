//! Variations (slice jwf2 of the registry).

#[allow(unused_imports)]
use super::*;

pub(super) static DEFS: &[VarDef] = &[];
