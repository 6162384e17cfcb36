//! Broken edits of the sea's and the diagram's shaders while the chapter
//! runs: the diagnostic comes back and the last good pipelines keep
//! drawing; the fix reloads. (The shader root belongs to the test's own
//! device.)

use common::headless::{OFFSCREEN_FORMAT, capture};
use common::{Chapter, Gpu, Target, shader};
use voronoi_water::VoronoiWaterChapter;

#[test]
fn broken_sea_and_cone_shaders_keep_the_last_good_pipelines() {
    let root = shader::scratch_copy("voronoi-water-hot-reload").unwrap();

    let gpu = Gpu::headless(VoronoiWaterChapter::gpu_needs()).unwrap();
    gpu.read_shaders_from(Some(root.clone()));
    let target = Target { format: OFFSCREEN_FORMAT, width: 160, height: 90 };
    let mut chapter = VoronoiWaterChapter::new(&gpu, target).unwrap();
    let good = capture(&gpu, &mut chapter, target, 20.0, 0).unwrap();

    for (file, from, to) in [
        ("voronoi-water/sea.wgsl", "sea_point(index).world", "sea_point(index)"),
        ("voronoi-water/cones.wgsl", "fn vs_cone(", "fn vs_renamed("),
        ("voronoi-water/process.wgsl", "return box_blur(", "return blur("),
    ] {
        let path = root.join(file);
        let original = std::fs::read_to_string(&path).unwrap();
        assert!(original.contains(from), "{file} no longer has {from:?}");
        std::fs::write(&path, original.replace(from, to)).unwrap();
        let error = chapter.reload_shaders(&gpu).unwrap_err();
        assert!(!error.0.is_empty());
        let picture = capture(&gpu, &mut chapter, target, 20.0, 0).unwrap();
        assert_eq!(picture, good, "{file}: the last good pipelines keep drawing");
        std::fs::write(&path, original).unwrap();
        chapter.reload_shaders(&gpu).unwrap();
    }
    assert_eq!(capture(&gpu, &mut chapter, target, 20.0, 0).unwrap(), good);
    let _ = std::fs::remove_dir_all(&root);
}
