//! The terrain made in steps, as a browser page makes it
//! (`Chapter::prepare`): the progress rises to 1, the steps are the ones
//! the chapter promises, and the finished terrain is the one `new` finds.

use common::Gpu;
use terrain::TerrainData;
use terrain::heightfield::{HeightField, TerrainSettings};

#[test]
fn steps_rise_to_one_and_leave_the_terrain_for_new() {
    let gpu = Gpu::headless(terrain::gpu_needs()).expect("an adapter (lavapipe will do)");
    // 16 chunks a side: 1025 rows of heights.
    let settings = TerrainSettings { chunks_per_side: 16, ..Default::default() };
    let mut preparation = TerrainData::prepare(&gpu, settings).expect("nothing is made yet");
    let mut progress = Vec::new();
    loop {
        let done = preparation.step(&gpu);
        progress.push(done);
        if done >= 1.0 {
            break;
        }
        assert!(progress.len() < 100, "no end in sight: {progress:?}");
    }
    // 17 steps of 64 rows of heights, 4 of 4 rows of chunks, the upload.
    assert_eq!(progress.len(), 17 + 4 + 1, "{progress:?}");
    assert!(progress.windows(2).all(|pair| pair[0] < pair[1]), "{progress:?}");
    assert!(progress.iter().all(|p| (0.0..=1.0).contains(p)), "{progress:?}");

    // Done once: a second preparation has nothing to do, and what `new`
    // gets is what the steps made.
    assert!(TerrainData::prepare(&gpu, settings).is_none());
    let data = TerrainData::get(&gpu, settings);
    assert_eq!(data.field.heights, HeightField::generate(settings).heights);
    assert_eq!(data.mesh.bounds.len(), 16 * 16);
    // Other settings are not made yet.
    assert!(TerrainData::prepare(&gpu, TerrainSettings { seed: 8, ..settings }).is_some());
}
