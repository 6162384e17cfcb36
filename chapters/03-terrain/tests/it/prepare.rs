//! The terrain made in steps, as a browser page makes it
//! (`Chapter::prepare`): the progress rises to 1, the steps are the ones
//! the chapter promises, and what they make is the terrain `new` receives.

use common::Gpu;
use common::preparation::Step;
use terrain::TerrainData;
use terrain::heightfield::{HeightField, TerrainSettings};

#[test]
fn steps_rise_to_one_and_leave_the_terrain_for_new() {
    let gpu = Gpu::headless(terrain::gpu_needs()).expect("an adapter (lavapipe will do)");
    // 16 chunks a side: 1025 rows of heights.
    let settings = TerrainSettings { chunks_per_side: 16, ..Default::default() };
    let mut preparation = TerrainData::prepare(&gpu, settings);
    let mut progress = Vec::new();
    let made = loop {
        match preparation.step(&gpu) {
            Step::Progress(done) => progress.push(done),
            Step::Done(data) => break data,
        }
        assert!(progress.len() < 100, "no end in sight: {progress:?}");
    };
    // 17 steps of 64 rows of heights, 4 of 4 rows of chunks, then the
    // upload, which finishes it.
    assert_eq!(progress.len(), 17 + 4, "{progress:?}");
    assert!(progress.windows(2).all(|pair| pair[0] < pair[1]), "{progress:?}");
    assert!(progress.iter().all(|p| (0.0..1.0).contains(p)), "{progress:?}");

    // What the steps made is the terrain of those settings, and it is kept:
    // a second preparation is ready at once with the same data.
    assert_eq!(made.field.heights, HeightField::generate(settings).heights);
    assert_eq!(made.chunk_bounds.len(), 16 * 16);
    assert!(gpu.is_cached::<TerrainSettings, TerrainData>(&settings));
    let again = TerrainData::prepare(&gpu, settings).finish(&gpu);
    assert!(std::sync::Arc::ptr_eq(&made, &again));
    // Other settings are not made yet.
    assert!(!gpu.is_cached::<TerrainSettings, TerrainData>(&TerrainSettings { seed: 8, ..settings }));
}
