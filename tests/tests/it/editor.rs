//! The shader panel, through its own entry points (what typing, Ctrl+Enter
//! and the revert button call), on a device of the test's own: an edit
//! changes the picture, a broken one is reported at its line while the last
//! good picture stays byte for byte, revert gives the shipped picture back,
//! and an edit to a module reaches every pipeline that imports it.

use common::chapter::{FlagValues, create_prepared};
use common::editor::ShaderEditor;
use common::headless::{OFFSCREEN_FORMAT, capture};
use common::{Chapter, Gpu, Target};

fn make<C: Chapter>(gpu: &Gpu, target: Target) -> C {
    create_prepared::<C>(gpu, target, C::prepare(gpu).finish(gpu), &FlagValues::default()).unwrap()
}

/// The 1-based line of the only line of `text` that contains `needle`,
/// found here, independently of the code under test.
fn line_of(text: &str, needle: &str) -> usize {
    let lines: Vec<usize> = text.lines().enumerate().filter(|(_, l)| l.contains(needle)).map(|(i, _)| i + 1).collect();
    assert_eq!(lines.len(), 1, "`{needle}` should be on one line");
    lines[0]
}

#[test]
fn edits_build_errors_point_at_their_line_and_revert_restores() {
    const FILE: &str = "triangle/triangle.wgsl";
    let gpu = Gpu::headless(C::gpu_needs()).unwrap();
    type C = triangle::Triangle;
    let target = Target { format: OFFSCREEN_FORMAT, width: 96, height: 64, samples: 1 };
    let mut chapter: C = make(&gpu, target);
    let shipped = capture(&gpu, &mut chapter, target, (0.0, 0), Default::default()).unwrap();

    let mut editor = ShaderEditor::new();
    editor.open_on(&gpu, FILE, Some("return vec4<f32>(in.color, 1.0);")).unwrap();
    let original = editor.text().unwrap().to_string();

    // A valid edit: every pixel of the triangle white.
    editor.type_text(&original.replace("return vec4<f32>(in.color, 1.0);", "return vec4<f32>(1.0);"));
    editor.build_now();
    editor.update(&gpu);
    assert_eq!(editor.error(), None);
    let white = capture(&gpu, &mut chapter, target, (0.0, 0), Default::default()).unwrap();
    assert_ne!(white, shipped, "the edit must change the picture");
    assert_eq!(white.get_pixel(48, 32).0, [255, 255, 255, 255]);

    // A broken edit: the error names its line in this file, and the last
    // good picture (the white one) keeps drawing.
    let broken = original.replacen("return vec4<f32>(in.color, 1.0);", "return vec4<f32>(in.color);", 1);
    editor.type_text(&broken);
    editor.build_now();
    editor.update(&gpu);
    let error = editor.error().expect("a broken edit is reported");
    assert_eq!(error.line, Some(line_of(&broken, "return vec4<f32>(in.color);")), "{}", error.message);
    assert_eq!(
        capture(&gpu, &mut chapter, target, (0.0, 0), Default::default()).unwrap(),
        white,
        "the last good pipeline keeps drawing"
    );

    // Valid WGSL that no longer fits the pipeline fails at pipeline creation, said the same way.
    editor.type_text(&original.replace("fn fs_main(", "fn fs_renamed("));
    editor.build_now();
    editor.update(&gpu);
    assert!(editor.error().is_some_and(|e| e.message.contains("fs_main")), "{:?}", editor.error());
    assert_eq!(capture(&gpu, &mut chapter, target, (0.0, 0), Default::default()).unwrap(), white);

    // Revert: the shipped text, and the shipped picture byte for byte.
    editor.revert(&gpu);
    assert_eq!(editor.text(), Some(original.as_str()));
    assert_eq!(editor.error(), None);
    assert!(gpu.shader_edits().is_empty(), "a reverted file is no edit");
    assert_eq!(capture(&gpu, &mut chapter, target, (0.0, 0), Default::default()).unwrap(), shipped);

    // A file the chapter does not build from is refused with the ones it does.
    let unknown = editor.open_on(&gpu, "triangle/nothing.wgsl", None).unwrap_err();
    assert!(unknown.0.contains(FILE), "{unknown}");
}

#[test]
fn typing_builds_after_a_pause_not_before() {
    type C = triangle::Triangle;
    let gpu = Gpu::headless(C::gpu_needs()).unwrap();
    let target = Target { format: OFFSCREEN_FORMAT, width: 32, height: 32, samples: 1 };
    let mut chapter: C = make(&gpu, target);
    let shipped = capture(&gpu, &mut chapter, target, (0.0, 0), Default::default()).unwrap();
    let mut editor = ShaderEditor::new();
    editor.open_on(&gpu, "triangle/triangle.wgsl", None).unwrap();
    let original = editor.text().unwrap().to_string();
    editor.type_text(&original.replace("return vec4<f32>(in.color, 1.0);", "return vec4<f32>(1.0);"));
    editor.update(&gpu);
    assert_eq!(
        capture(&gpu, &mut chapter, target, (0.0, 0), Default::default()).unwrap(),
        shipped,
        "still typing: nothing built yet"
    );
    std::thread::sleep(common::editor::PAUSE_BEFORE_BUILD);
    editor.update(&gpu);
    assert_ne!(
        capture(&gpu, &mut chapter, target, (0.0, 0), Default::default()).unwrap(),
        shipped,
        "built once typing paused"
    );
}

#[test]
fn an_edit_to_a_module_reaches_every_pipeline_that_imports_it() {
    // Chapter 11's atmosphere module: the sky pipeline imports its
    // `sky_colour`, the sea's and the islands' its `fogged`.
    type C = voronoi_water::VoronoiWaterChapter;
    const MODULE: &str = "voronoi-water/atmosphere.wgsl";
    let gpu = Gpu::headless(C::gpu_needs()).unwrap();
    let target = Target { format: OFFSCREEN_FORMAT, width: 128, height: 72, samples: 1 };
    let mut chapter: C = make(&gpu, target);
    let time = C::SNAPSHOT_TIME;
    let shipped = capture(&gpu, &mut chapter, target, (time, 0), Default::default()).unwrap();
    let files: Vec<&str> = gpu.shader_files().iter().map(|f| f.path).collect();
    for importer in ["voronoi-water/sky.wgsl", "voronoi-water/sea.wgsl", "voronoi-water/islands.wgsl", MODULE] {
        assert!(files.contains(&importer), "{importer} not among {files:?}");
    }

    let text = gpu.shader_text(MODULE).unwrap();
    let magenta = "return vec3<f32>(1.0, 0.0, 1.0);\n";
    let mut edited = String::new();
    for line in text.lines() {
        edited.push_str(line);
        edited.push('\n');
        if line.starts_with("fn sky_colour(") || line.starts_with("fn fogged(") {
            edited.push_str(magenta);
        }
    }
    assert_eq!(edited.matches(magenta).count(), 2);
    let rebuilt = gpu.edit_shader(MODULE, Some(&edited)).unwrap();
    assert!(rebuilt >= 3, "sky, sea and islands at least: {rebuilt}");
    let changed = capture(&gpu, &mut chapter, target, (time, 0), Default::default()).unwrap();
    // The top row is sky, the bottom row sea: both changed.
    let row_differs = |y: u32| (0..target.width).any(|x| changed.get_pixel(x, y) != shipped.get_pixel(x, y));
    assert!(row_differs(0), "the sky pipeline did not see the module's edit");
    assert!(row_differs(target.height - 1), "the sea pipeline did not see the module's edit");

    gpu.edit_shader(MODULE, None).unwrap();
    assert_eq!(capture(&gpu, &mut chapter, target, (time, 0), Default::default()).unwrap(), shipped);

    // Errors at their line in the file edited, never the composed module's
    // (where the imported modules come first): a type error in the sea's
    // own file, which imports four modules, and one in the module itself.
    let mut editor = ShaderEditor::new();
    for (file, before, after) in [
        (
            "voronoi-water/sea.wgsl",
            "return vec4<f32>(fogged(colour, in.world), 1.0);",
            "return fogged(colour, in.world);",
        ),
        (MODULE, "let clear = exp(-atmosphere.fog.x * distance);", "let clear = exp(-atmosphere.fog.x * true);"),
    ] {
        editor.open_on(&gpu, file, None).unwrap();
        let broken = editor.text().unwrap().replacen(before, after, 1);
        editor.type_text(&broken);
        editor.build_now();
        editor.update(&gpu);
        let error = editor.error().expect("a broken edit is reported");
        assert_eq!(error.line, Some(line_of(&broken, after)), "{file}: {}", error.message);
        editor.revert(&gpu);
    }
    assert_eq!(capture(&gpu, &mut chapter, target, (time, 0), Default::default()).unwrap(), shipped);
}
