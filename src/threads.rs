//! Worker thread counts: 0 means one per core; more than [`PER_CORE`] per core only costs
//! memory (a flame keeps one histogram per thread) and start-up time, so larger requests are
//! clamped and the caller shows [`Threads::warning`].

/// Most threads per core a render uses.
pub const PER_CORE: usize = 4;

/// Cores of this machine (1 when unknown).
pub fn cores() -> usize {
    // Read once: the standard library reads the cgroup's CPU quota on every call.
    static CORES: std::sync::OnceLock<usize> = std::sync::OnceLock::new();
    *CORES.get_or_init(|| std::thread::available_parallelism().map_or(1, |n| n.get()))
}

/// The largest thread count a render uses.
pub fn max_threads() -> usize {
    PER_CORE * cores()
}

/// A resolved thread count.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Threads {
    /// Threads to use (≥ 1).
    pub count: usize,
    /// What was asked for (0: all cores).
    pub requested: usize,
    /// Cores of the machine it was resolved for.
    pub cores: usize,
}

impl Threads {
    /// Resolve a request: 0 → all cores; above [`max_threads`] → clamped.
    pub fn resolve(requested: usize) -> Threads {
        Self::resolve_with(requested, cores())
    }

    /// As [`Threads::resolve`] for a machine with `cores` cores.
    pub fn resolve_with(requested: usize, cores: usize) -> Threads {
        let cores = cores.max(1);
        let count = if requested == 0 {
            cores
        } else {
            requested.min(PER_CORE * cores)
        };
        Threads {
            count,
            requested,
            cores,
        }
    }

    /// Whether more threads were asked for than are used.
    pub fn clamped(&self) -> bool {
        self.requested > self.count
    }

    /// The warning to show when the request was clamped.
    pub fn warning(&self) -> Option<String> {
        self.clamped().then(|| {
            format!(
                "{} threads requested; using {} ({} per core on this {}-core machine)",
                self.requested, self.count, PER_CORE, self.cores
            )
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn requests_are_resolved_and_clamped() {
        assert_eq!(Threads::resolve_with(0, 2).count, 2);
        assert_eq!(Threads::resolve_with(3, 2).count, 3);
        let t = Threads::resolve_with(100_000, 2);
        assert_eq!(t.count, 8);
        assert!(t.clamped());
        let w = t.warning().unwrap();
        assert!(w.contains("100000 threads requested; using 8"), "{w}");
        assert!(Threads::resolve_with(8, 2).warning().is_none());
        assert!(Threads::resolve(1_000_000).count <= max_threads());
    }
}
