//! Hot reload over the whole chapter: a broken edit of any WGSL file its
//! pipelines are built from (its own, the modules they import, and those
//! of the pieces it takes from chapters 08 to 10) comes back as a
//! diagnostic naming the file while the last good pipelines keep drawing;
//! the fix reloads. (The shader root belongs to the test's own device.)

use std::collections::BTreeSet;
use std::path::Path;

use common::headless::{OFFSCREEN_FORMAT, capture};
use common::{Chapter, Gpu, Target, shader};
use voronoi_water::VoronoiWaterChapter;

/// Every WGSL file the chapter builds pipelines from, with the pieces that
/// read it.
const FILES: [&str; 22] = [
    "voronoi-water/cones.wgsl",      // Voronoi
    "voronoi-water/jump_flood.wgsl", // Voronoi
    "voronoi-water/process.wgsl",    // WaterTexture, Show
    "voronoi-water/sea.wgsl",        // SeaRenderer
    "voronoi-water/islands.wgsl",    // IslandRenderer
    "voronoi-water/sky.wgsl",        // Sky
    "voronoi-water/atmosphere.wgsl", // imported by the sea, islands and sky
    "water/waves.wgsl",              // chapter 07's, imported by the sea
    "lighting/bloom.wgsl",           // chapter 08's PostChain
    "lighting/tonemap.wgsl",         // chapter 08's PostChain
    "lighting/fxaa.wgsl",            // chapter 08's PostChain, with --antialiasing post
    "lighting/brdf.wgsl",            // imported by lights.wgsl
    "lighting/sky_light.wgsl",       // imported by lights.wgsl
    "lighting/lights.wgsl",          // imported by the sea, islands and boat
    "textures/mipmap.wgsl",          // chapter 09's MipMaker, for the water texture
    "textures/surface.wgsl",         // imported by the shadow pass and the boat
    "shadows/caster.wgsl",           // chapter 10's ShadowMap
    "shadows/show_depth.wgsl",       // chapter 10's MapView
    "shadows/scene.wgsl",            // chapter 10's ShadowedRenderer, for the boat
    "shadows/shadow.wgsl",           // imported by the sea and the boat
    "shadows/point_shadow.wgsl",     // imported by the boat's scene.wgsl (the boat has no point light)
    "common/fullscreen.wgsl",        // imported by every full-screen pass
];

/// The shaders of the chapters it takes pieces from that it does not draw
/// with, and the pieces that do.
const NOT_USED: [&str; 10] = [
    "lighting/brdf_table.wgsl",  // SceneLights's split-sum table: computed once, at start
    "lighting/irradiance.wgsl",  // SceneLights's sky harmonics: computed when the sky changes
    "lighting/prefilter.wgsl",   // SceneLights's prefiltered sky: computed when the sky changes
    "lighting/city.wgsl",        // chapter 08's city
    "lighting/sky.wgsl",         // CitySky: this chapter has its own sky
    "textures/textured.wgsl",    // TexturedRenderer: the boat is shadowed
    "shadows/layers.wgsl",       // Parallax
    "shadows/lines.wgsl",        // Lines
    "shadows/point_caster.wgsl", // PointShadow: no lantern at sea
    "shadows/show_cube.wgsl",    // CubeView
];

/// The crates whose `shader!` paths must all be in one list or the other:
/// this chapter and those it takes pieces from. (Chapter 07 gives only the
/// wave maths, and waves.wgsl through the sea's imports.)
const CRATES: [&str; 4] = ["11-voronoi-water", "10-shadows", "09-textures", "08-lighting"];

/// Every path in the `shader!(…)` calls of a crate's sources, imports included.
fn shader_paths(krate: &str) -> BTreeSet<String> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("..").join(krate).join("src");
    let mut sources = Vec::new();
    files_under(&src, "rs", &mut sources);
    let mut paths = BTreeSet::new();
    for source in sources {
        let text = std::fs::read_to_string(source).unwrap();
        for call in text.split("shader!(").skip(1) {
            let arguments = call.split(')').next().unwrap();
            paths.extend(arguments.split('"').skip(1).step_by(2).map(str::to_string));
        }
    }
    paths
}

/// Every file under `folder` whose name ends in `.extension`.
fn files_under(folder: &Path, extension: &str, found: &mut Vec<std::path::PathBuf>) {
    for entry in std::fs::read_dir(folder).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            files_under(&path, extension, found);
        } else if path.extension().is_some_and(|e| e == extension) {
            found.push(path);
        }
    }
}

#[test]
fn the_hot_reload_test_covers_every_shader_the_chapter_uses() {
    let listed: BTreeSet<&str> = FILES.into_iter().collect();
    let not_used: BTreeSet<&str> = NOT_USED.into_iter().collect();
    assert!(listed.len() == FILES.len() && listed.is_disjoint(&not_used), "a file is listed twice");
    let own = shader_paths(CRATES[0]);
    assert!(!own.is_empty(), "no shader! calls found: has the macro been renamed?");
    for path in &own {
        assert!(listed.contains(path.as_str()), "chapter 11 builds from {path}: add it to FILES");
    }
    for krate in &CRATES[1..] {
        for path in shader_paths(krate) {
            assert!(
                listed.contains(path.as_str()) || not_used.contains(path.as_str()),
                "{krate} builds from {path}: add it to FILES if chapter 11 draws with that piece, else to NOT_USED"
            );
        }
    }
    for file in FILES.iter().chain(&NOT_USED) {
        assert!(Path::new(shader::SHADER_DIR).join(file).is_file(), "{file} does not exist");
    }
}

/// With the post-process pass, so that FXAA's pipeline draws too.
const POST: common::Antialiasing = common::Antialiasing::Post;

#[test]
fn a_broken_shader_of_any_piece_keeps_the_last_good_picture() {
    let root = shader::scratch_copy("voronoi-water-hot-reload").unwrap();

    let gpu = Gpu::headless(VoronoiWaterChapter::gpu_needs()).unwrap();
    gpu.read_shaders_from(Some(root.clone()));
    let target = Target { format: OFFSCREEN_FORMAT, width: 160, height: 90, samples: 1 };
    let mut chapter = VoronoiWaterChapter::new(&gpu, target, ()).unwrap();
    let good = capture(&gpu, &mut chapter, target, (20.0, 0), POST).unwrap();

    for file in FILES {
        let path = root.join(file);
        let original = std::fs::read_to_string(&path).unwrap();
        // A parse error on a line of its own, at the end.
        std::fs::write(&path, format!("{original}\nfn broken_by_the_test(\n")).unwrap();
        let error = gpu.reload_shaders(&[file]).unwrap_err();
        assert!(error.0.contains(file), "the error does not name {file}:\n{error}");
        let picture = capture(&gpu, &mut chapter, target, (20.0, 0), POST).unwrap();
        assert!(picture == good, "{file}: the last good pipelines must keep drawing");
        std::fs::write(&path, original).unwrap();
        let rebuilt = gpu.reload_shaders(&[file]).unwrap_or_else(|e| panic!("{file} restored:\n{e}"));
        assert!(rebuilt >= 1, "nothing was rebuilt from {file}");
    }
    assert!(capture(&gpu, &mut chapter, target, (20.0, 0), POST).unwrap() == good);

    // And nothing else: no other file has a pipeline of this chapter built from it.
    let mut all = Vec::new();
    files_under(&root, "wgsl", &mut all);
    for path in all {
        let parts = path.strip_prefix(&root).unwrap().iter().map(|part| part.to_string_lossy());
        let file = parts.collect::<Vec<_>>().join("/");
        if !FILES.contains(&file.as_str()) {
            assert_eq!(gpu.reload_shaders(&[&file]), Ok(0), "chapter 11 builds from {file}: add it to FILES");
        }
    }
    let _ = std::fs::remove_dir_all(&root);
}
