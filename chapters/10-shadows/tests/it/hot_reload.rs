//! A broken edit of the shadow pass's shader, while the chapter runs: the
//! diagnostic comes back and the last good pipelines keep drawing, even
//! when the bias changes meanwhile (which makes the pass's pipeline again).
//! (The shader root belongs to the test's own device.)

use common::headless::{OFFSCREEN_FORMAT, capture};
use common::{Chapter, Gpu, Target, shader};
use shadows::ShadowsChapter;
use shadows::shadow_map::Bias;

const CASTER: &str = "shadows/caster.wgsl";

#[test]
fn a_broken_caster_shader_keeps_the_last_good_shadow_pass() {
    let root = shader::scratch_copy("shadows-hot-reload").unwrap();
    let file = root.join(CASTER);
    let original = std::fs::read_to_string(&file).unwrap();

    let gpu = Gpu::headless(ShadowsChapter::gpu_needs()).unwrap();
    gpu.read_shaders_from(Some(root.clone()));
    let target = Target { format: OFFSCREEN_FORMAT, width: 160, height: 90, samples: 1 };
    let mut chapter = ShadowsChapter::new(&gpu, target, ()).unwrap();
    let good = capture(&gpu, &mut chapter, target, (5.7, 0), Default::default()).unwrap();

    for broken in [
        original.replace("place(vertex, instance).world", "place(vertex, instance)"),
        original.replace("fn vs_caster(", "fn vs_renamed("),
    ] {
        std::fs::write(&file, broken).unwrap();
        let error = gpu.reload_shaders(&[CASTER]).unwrap_err();
        assert!(error.0.contains("caster.wgsl") || error.0.contains("vs_caster"), "{error}");
        assert_eq!(
            capture(&gpu, &mut chapter, target, (5.7, 0), Default::default()).unwrap(),
            good,
            "the last good pipeline keeps drawing"
        );
    }
    // A new bias needs a new pipeline, which the broken file cannot make:
    // the last good one keeps drawing, with the bias it was made with.
    let bias = chapter.settings.shadow.bias;
    chapter.settings.shadow.bias = Bias::TOO_MUCH;
    assert_eq!(capture(&gpu, &mut chapter, target, (5.7, 0), Default::default()).unwrap(), good);
    chapter.settings.shadow.bias = bias;

    std::fs::write(&file, original).unwrap();
    let rebuilt = gpu.reload_shaders(&[CASTER]).unwrap();
    assert!(rebuilt >= 1, "nothing was built from {CASTER}");
    assert_eq!(capture(&gpu, &mut chapter, target, (5.7, 0), Default::default()).unwrap(), good);
    let _ = std::fs::remove_dir_all(&root);
}
