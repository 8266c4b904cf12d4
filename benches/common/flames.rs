//! The seven benchmark flames of the preview benches: four examples and three random flames.

use std::path::Path;

use ugnis::flame::Flame;
use ugnis::flame::random::{self, RandomOptions, VariationMode};

/// The benchmark flames by name.
pub fn flames() -> Vec<(String, Flame)> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples");
    let mut out = Vec::new();
    for name in ["orchid", "ember-swirl", "lagoon-post", "moss-classic"] {
        let f = ugnis::io::read_flames(&dir.join(format!("{name}.flame")), &Default::default())
            .expect("example")
            .value
            .remove(0);
        out.push((name.to_string(), f));
    }
    let opts = RandomOptions {
        variations: VariationMode::default(),
        ..RandomOptions::default()
    };
    for seed in [11u64, 12, 13] {
        let f = random::generate(seed, &opts, &Default::default()).flame;
        out.push((format!("random-{seed}"), f));
    }
    out
}
