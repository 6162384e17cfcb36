//! Hot reload, end to end without a window: a broken shader edit reports
//! naga's diagnostic and the last good pipeline keeps drawing; the fix
//! reloads. (The shader root belongs to the test's own device.)

use common::headless::{OFFSCREEN_FORMAT, capture};
use common::{Chapter, Gpu, GpuNeeds, Target, shader};
use triangle::Triangle;

#[test]
fn a_broken_edit_keeps_the_last_good_pipeline() {
    let root = std::env::temp_dir().join(format!("hot-reload-{}", std::process::id()));
    let file = root.join("triangle/triangle.wgsl");
    std::fs::create_dir_all(file.parent().unwrap()).unwrap();
    let original = std::fs::read_to_string(format!("{}/triangle/triangle.wgsl", shader::SHADER_DIR)).unwrap();
    std::fs::write(&file, &original).unwrap();

    let gpu = Gpu::headless(GpuNeeds::default()).unwrap();
    gpu.read_shaders_from(Some(root.clone()));
    let target = Target { format: OFFSCREEN_FORMAT, width: 96, height: 64, samples: 1 };
    let mut chapter = Triangle::new(&gpu, target, ()).unwrap();
    let good = capture(&gpu, &mut chapter, target, (0.0, 0), Default::default()).unwrap();

    // A type error: naga rejects it, with the file and line.
    std::fs::write(&file, original.replace("return vec4<f32>(in.color, 1.0);", "return vec4<f32>(in.color);")).unwrap();
    let error = gpu.reload_shaders(&["triangle/triangle.wgsl"]).unwrap_err();
    assert!(error.0.contains("triangle/triangle.wgsl:"), "{error}");
    assert_eq!(
        capture(&gpu, &mut chapter, target, (0.0, 0), Default::default()).unwrap(),
        good,
        "the last good pipeline must keep drawing"
    );

    // Valid WGSL that no longer fits the pipeline: wgpu's validation error is caught, not a panic.
    std::fs::write(&file, original.replace("fn fs_main(", "fn fs_renamed(")).unwrap();
    let error = gpu.reload_shaders(&["triangle/triangle.wgsl"]).unwrap_err();
    assert!(error.0.contains("fs_main"), "{error}");
    assert_eq!(capture(&gpu, &mut chapter, target, (0.0, 0), Default::default()).unwrap(), good);

    // The fix (here: everything white) reloads and shows.
    std::fs::write(&file, original.replace("return vec4<f32>(in.color, 1.0);", "return vec4<f32>(1.0);")).unwrap();
    gpu.reload_shaders(&["triangle/triangle.wgsl"]).unwrap();
    let edited = capture(&gpu, &mut chapter, target, (0.0, 0), Default::default()).unwrap();
    assert_eq!(edited.get_pixel(48, 32).0, [255, 255, 255, 255]);
    std::fs::remove_dir_all(root).unwrap();
}
