//! The flame tab's left panel: a file of many flames beside a random batch, one line each,
//! and the batch folded away.

use egui_kittest::kittest::Queryable;
use ugnis::app::Start;
use ugnis::flame::Flame;

use crate::harness_sized;

#[test]
fn the_left_panel_shows_a_files_flames_beside_a_batch_on_one_line_each() {
    let f = ugnis::io::read_flames(&crate::example("sierpinski.flame"), &Default::default())
        .unwrap()
        .value
        .remove(0);
    let flames: Vec<Flame> = (1..=12)
        .map(|k| Flame {
            name: format!("flame number {k:02} with a long name from another program"),
            ..f.clone()
        })
        .collect();
    let mut h = harness_sized(Start::Flames(flames.clone()), 1280.0, 800.0);
    let batch: Vec<Flame> = (1..=100)
        .map(|k| Flame {
            name: format!("random-{k:03}"),
            ..f.clone()
        })
        .collect();
    h.state_mut().flame.set_batch(batch, None);
    h.run_steps(3);
    let shown = (1..=12)
        .filter(|k| {
            h.query_by_label(&flames[k - 1].name)
                .is_some_and(|n| n.rect().bottom() < 800.0 && n.rect().height() < 30.0)
        })
        .count();
    assert!(
        shown >= 9,
        "{shown} of 12 file flames in view, each on one line"
    );
    // The batch folds away, and the file's list then has all the room.
    h.get_by_label("Last random batch (100)").click();
    h.run_steps(3);
    assert!(!h.state().flame.batch_shown);
    assert!(h.query_by_label("random-001").is_none());
    assert!(h.query_by_label(&flames[11].name).is_some());
}
