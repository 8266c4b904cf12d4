//! Data that a few variations build once from their parameters — a grown aggregate, a crystal,
//! a tube mesh, the segments of a recursive drawing — shared between all the prepared copies
//! that use the same parameter values.
//!
//! The editor prepares a flame's variations again after every edit, and a render prepares them
//! once per thread; building such data each time would take up to seconds and hold one copy
//! per prepared variation. Instead the data is built once per distinct value of the parameters
//! it depends on (its key) and kept, as an `Arc`, in a process-wide cache: at most
//! [`MAX_ENTRIES`] entries and [`MAX_BYTES`] bytes, the least recently used dropped first. A
//! prepared variation keeps its data alive while it exists, cached or not.
//!
//! The cache is thread-safe; two threads asking for the same key at once build it once (the
//! second waits for the first), different keys are built in parallel.

use std::sync::{Arc, LazyLock, Mutex, OnceLock};

use super::VarId;

/// Builds a variation's shared data from its normalised parameters (all of them, in
/// [`super::VarDef::params`] order) and its text parameters. It must read only the parameters
/// named by the key of its [`SharedDef`] (the texts are always part of the key).
pub type BuildFn = fn(p: &[f64], texts: &[String]) -> Vec<f64>;

/// How a variation builds its shared data.
#[derive(Clone, Copy, Debug)]
pub struct SharedDef {
    /// Indices of the parameters the data depends on.
    pub key: &'static [usize],
    /// Builds the data from the normalised parameters and the text parameters.
    pub build: BuildFn,
}

/// Most entries the cache keeps.
pub const MAX_ENTRIES: usize = 64;
/// Most bytes of data the cache keeps.
pub const MAX_BYTES: usize = 512 << 20;

type Slot = Arc<OnceLock<Arc<[f64]>>>;

struct Entry {
    id: VarId,
    key: Box<[u64]>,
    slot: Slot,
    /// Tick of the last use.
    used: u64,
}

impl Entry {
    fn bytes(&self) -> usize {
        self.slot
            .get()
            .map_or(0, |d| std::mem::size_of_val::<[f64]>(d))
    }
}

/// A least-recently-used map from (variation, key bits) to a slot for the data.
struct Cache {
    entries: Vec<Entry>,
    tick: u64,
    max_entries: usize,
    max_bytes: usize,
}

impl Cache {
    const fn new(max_entries: usize, max_bytes: usize) -> Cache {
        Cache {
            entries: Vec::new(),
            tick: 0,
            max_entries,
            max_bytes,
        }
    }

    /// The slot for (id, key), new and empty if there was none.
    fn slot(&mut self, id: VarId, key: &[u64]) -> Slot {
        self.tick += 1;
        if let Some(e) = self
            .entries
            .iter_mut()
            .find(|e| e.id == id && *e.key == *key)
        {
            e.used = self.tick;
            return e.slot.clone();
        }
        let slot = Slot::default();
        self.entries.push(Entry {
            id,
            key: key.into(),
            slot: slot.clone(),
            used: self.tick,
        });
        self.trim();
        slot
    }

    /// Drops least recently used entries until the limits hold.
    fn trim(&mut self) {
        let mut bytes: usize = self.entries.iter().map(Entry::bytes).sum();
        while self.entries.len() > self.max_entries || bytes > self.max_bytes {
            let Some((oldest, _)) = self.entries.iter().enumerate().min_by_key(|(_, e)| e.used)
            else {
                break;
            };
            bytes -= self.entries.swap_remove(oldest).bytes();
        }
    }

    #[cfg(test)]
    fn len(&self) -> usize {
        self.entries.len()
    }
}

static CACHE: LazyLock<Mutex<Cache>> =
    LazyLock::new(|| Mutex::new(Cache::new(MAX_ENTRIES, MAX_BYTES)));

/// Runs `f` on the locked cache (a panic elsewhere while it was locked leaves it usable: the
/// cache holds no invariant a half-done operation could break).
fn with_cache<T>(cache: &Mutex<Cache>, f: impl FnOnce(&mut Cache) -> T) -> T {
    let mut guard = cache.lock().unwrap_or_else(|e| e.into_inner());
    f(&mut guard)
}

/// The shared data of variation `id` for the normalised parameters `p`: from the cache, or
/// built by `def` and cached.
pub(super) fn data(id: VarId, def: &SharedDef, p: &[f64], texts: &[String]) -> Arc<[f64]> {
    data_in(&CACHE, id, def, p, texts)
}

fn data_in(
    cache: &Mutex<Cache>,
    id: VarId,
    def: &SharedDef,
    p: &[f64],
    texts: &[String],
) -> Arc<[f64]> {
    let mut key: Vec<u64> = def.key.iter().map(|&i| p[i].to_bits()).collect();
    for t in texts {
        // Its length, then its bytes eight to a word.
        key.push(t.len() as u64);
        key.extend(t.as_bytes().chunks(8).map(|c| {
            let mut w = [0u8; 8];
            w[..c.len()].copy_from_slice(c);
            u64::from_le_bytes(w)
        }));
    }
    let slot = with_cache(cache, |c| c.slot(id, &key));
    let data = slot.get_or_init(|| (def.build)(p, texts).into()).clone();
    // The new data's size counts now that it exists.
    with_cache(cache, Cache::trim);
    data
}

/// Forget the cached data of the variations `which` says yes to (data built from resources
/// that have since changed); prepared variations keep the data they hold.
pub(super) fn forget(which: impl Fn(VarId) -> bool) {
    with_cache(&CACHE, |c| c.entries.retain(|e| !which(e.id)));
}

/// Number of entries in the process-wide cache.
#[cfg(test)]
pub fn cached_entries() -> usize {
    with_cache(&CACHE, |c| c.len())
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::{AtomicUsize, Ordering};

    /// Data of p[0] copies of p[1]; p[2] is not part of the key.
    fn build(p: &[f64], _: &[String]) -> Vec<f64> {
        vec![p[1]; p[0] as usize]
    }

    const DEF: SharedDef = SharedDef {
        key: &[0, 1],
        build,
    };

    #[test]
    fn same_key_shares_one_build() {
        static BUILDS: AtomicUsize = AtomicUsize::new(0);
        fn counted(p: &[f64], _: &[String]) -> Vec<f64> {
            BUILDS.fetch_add(1, Ordering::SeqCst);
            build(p, &[])
        }
        let counted_def = SharedDef {
            key: &[0, 1],
            build: counted,
        };
        let cache = Mutex::new(Cache::new(4, 1 << 20));
        let a = data_in(&cache, 1, &counted_def, &[3.0, 7.0, 0.0], &[]);
        let b = data_in(&cache, 1, &counted_def, &[3.0, 7.0, 5.0], &[]);
        assert!(Arc::ptr_eq(&a, &b));
        assert_eq!(&a[..], &[7.0; 3]);
        assert_eq!(BUILDS.load(Ordering::SeqCst), 1);
        // Another key, or another variation with the same key, is built anew.
        let c = data_in(&cache, 1, &DEF, &[3.0, 8.0, 0.0], &[]);
        let d = data_in(&cache, 2, &DEF, &[3.0, 7.0, 0.0], &[]);
        assert_eq!(&c[..], &[8.0; 3]);
        assert!(!Arc::ptr_eq(&a, &d));
        assert_eq!(with_cache(&cache, |c| c.len()), 3);
    }

    #[test]
    fn least_recently_used_entries_go_first() {
        let cache = Mutex::new(Cache::new(2, 1 << 20));
        let a = data_in(&cache, 1, &DEF, &[1.0, 1.0, 0.0], &[]);
        let _b = data_in(&cache, 1, &DEF, &[1.0, 2.0, 0.0], &[]);
        // Using a again makes b the oldest; a third key drops b.
        let _ = data_in(&cache, 1, &DEF, &[1.0, 1.0, 0.0], &[]);
        let _c = data_in(&cache, 1, &DEF, &[1.0, 3.0, 0.0], &[]);
        assert_eq!(with_cache(&cache, |c| c.len()), 2);
        let again = data_in(&cache, 1, &DEF, &[1.0, 1.0, 0.0], &[]);
        assert!(Arc::ptr_eq(&a, &again), "a was used recently and stays");
        let keys: Vec<f64> = with_cache(&cache, |c| {
            c.entries.iter().map(|e| f64::from_bits(e.key[1])).collect()
        });
        assert!(!keys.contains(&2.0), "b was dropped: {keys:?}");
    }

    #[test]
    fn byte_limit_drops_old_entries() {
        // Room for 100 doubles: two entries of 60 do not fit together.
        let cache = Mutex::new(Cache::new(64, 800));
        let _a = data_in(&cache, 1, &DEF, &[60.0, 1.0, 0.0], &[]);
        let _b = data_in(&cache, 1, &DEF, &[60.0, 2.0, 0.0], &[]);
        assert_eq!(with_cache(&cache, |c| c.len()), 1);
        let total: usize = with_cache(&cache, |c| c.entries.iter().map(Entry::bytes).sum());
        assert!(total <= 800);
        // Data larger than the whole budget is returned but not kept.
        let big = data_in(&cache, 1, &DEF, &[200.0, 3.0, 0.0], &[]);
        assert_eq!(big.len(), 200);
        assert_eq!(with_cache(&cache, |c| c.len()), 0);
    }

    /// Every variation's data depends on its key parameters only: changing all the others
    /// leaves it as it was.
    #[test]
    fn shared_data_depends_on_the_key_only() {
        use super::super::{ParamKind, all};
        for d in all().iter().filter(|d| d.shared.is_some()) {
            let sd = d.shared.unwrap();
            let base: Vec<f64> = d.params.iter().map(|p| p.normalise(p.default)).collect();
            let other: Vec<f64> = d
                .params
                .iter()
                .enumerate()
                .map(|(i, p)| {
                    if sd.key.contains(&i) {
                        base[i]
                    } else if matches!(p.kind, ParamKind::Int | ParamKind::IntNonZero) {
                        p.normalise(p.default + 1.0)
                    } else {
                        p.normalise(p.default * 1.3 + 0.7)
                    }
                })
                .collect();
            if sd.key.len() == d.params.len() {
                // Every parameter is part of the key (mandala2's table): nothing to change.
                continue;
            }
            assert_ne!(base, other, "{}: nothing outside the key", d.name);
            let texts: Vec<String> = d.texts.iter().map(|t| t.default.to_string()).collect();
            let (a, b) = ((sd.build)(&base, &texts), (sd.build)(&other, &texts));
            assert!(!a.is_empty(), "{}", d.name);
            let same =
                a.len() == b.len() && a.iter().zip(&b).all(|(x, y)| x.to_bits() == y.to_bits());
            assert!(
                same,
                "{}: data changed with a parameter outside the key",
                d.name
            );
        }
    }

    /// Prepared copies with the same key values share one allocation, whatever their weight,
    /// form or other parameters.
    #[test]
    fn prepared_copies_share_their_data() {
        use super::super::{Form, Prepared, parse_name};
        use crate::flame::affine::Affine;
        let (id, _) = parse_name("tree_js").unwrap();
        let a = Prepared::new(id, Form::Regular, 1.0, &[3.0], Affine::default(), true);
        let b = Prepared::new(
            id,
            Form::Pre,
            0.3,
            &[3.0, 0.0, 2.0],
            Affine::default(),
            false,
        );
        let c = Prepared::new(id, Form::Regular, 1.0, &[4.0], Affine::default(), true);
        let (da, db, dc) = (a.data.unwrap(), b.data.unwrap(), c.data.unwrap());
        assert!(Arc::ptr_eq(&da, &db));
        assert_eq!(dc.len() / 4, 121, "level 4: (3^5 − 1)/2 branches");
        assert!(cached_entries() >= 2);
    }

    #[test]
    fn threads_asking_at_once_share_one_build() {
        static SLOW_BUILDS: AtomicUsize = AtomicUsize::new(0);
        fn slow(p: &[f64], _: &[String]) -> Vec<f64> {
            SLOW_BUILDS.fetch_add(1, Ordering::SeqCst);
            std::thread::sleep(std::time::Duration::from_millis(50));
            vec![p[0]; 10]
        }
        let def = SharedDef {
            key: &[0],
            build: slow,
        };
        let cache = Mutex::new(Cache::new(8, 1 << 20));
        let got: Vec<Arc<[f64]>> = std::thread::scope(|s| {
            let hs: Vec<_> = (0..4)
                .map(|_| s.spawn(|| data_in(&cache, 9, &def, &[4.0], &[])))
                .collect();
            hs.into_iter().map(|h| h.join().unwrap()).collect()
        });
        assert_eq!(SLOW_BUILDS.load(Ordering::SeqCst), 1);
        assert!(got.iter().all(|d| Arc::ptr_eq(d, &got[0])));
    }
}
