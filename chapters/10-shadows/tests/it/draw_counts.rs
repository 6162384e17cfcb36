//! What a frame of the side-scroller draws, pass by pass, against the
//! level counted another way: the models' triangles as the OBJ loader and
//! the level's builders make them on the CPU, times their instances.

use std::path::Path;

use common::headless::{OFFSCREEN_FORMAT, Offscreen, draw_frame};
use common::{Chapter, Gpu, PassTimer, Target};
use shadows::game::{self, PropKind};
use shadows::parallax::LAYERS;
use shadows::{ShadowsChapter, scene};
use textures::obj;

/// The sun's shadow map draws every model once; the lantern's six cube
/// faces draw every model but the lantern; the scene draws every model,
/// two triangles a parallax layer and the sky's one; the tone map one.
#[test]
fn each_pass_counts_the_level_it_draws() {
    let gpu = Gpu::headless(ShadowsChapter::gpu_needs()).expect("an adapter (lavapipe will do)");
    let target = Target { format: OFFSCREEN_FORMAT, width: 96, height: 54, samples: 1 };
    let mut chapter = common::chapter::create::<ShadowsChapter>(&gpu, target, &Default::default()).unwrap();
    let view = 0;
    chapter.select_view(view);
    let offscreen = Offscreen::new(&gpu.device, target);
    let timer = PassTimer::off();
    let drawn = draw_frame(
        &gpu,
        &mut chapter,
        &offscreen.view,
        (ShadowsChapter::SNAPSHOT_TIME, view),
        Default::default(),
        &timer,
    );

    let level = game::level();
    let read: obj::ReadFile = &scene::read;
    let loaded = |path: &str| obj::load(Path::new(path), read).unwrap().model.triangle_count() as u64;
    let props: u64 = PropKind::ALL
        .iter()
        .map(|&kind| loaded(scene::prop_model(kind)) * scene::prop_instances(&level, kind).len() as u64)
        .sum();
    let lantern = scene::lantern_model(&level).triangle_count() as u64;
    let everything = scene::level_model(&level).triangle_count() as u64 + props + lantern + loaded(scene::PLAYER_MODEL);
    eprintln!("the level: {everything} triangles, the lantern {lantern}");

    let triangles = |pass: &str| drawn.iter().find(|c| c.pass == pass).map(|c| c.drawn.triangles);
    assert_eq!(triangles("shadow map"), Some(everything), "{drawn:?}");
    assert_eq!(triangles("lantern shadow"), Some(6 * (everything - lantern)), "{drawn:?}");
    assert_eq!(triangles("scene"), Some(everything + 2 * LAYERS.len() as u64 + 1), "{drawn:?}");
    assert_eq!(triangles("tone map"), Some(1), "{drawn:?}");
    let timed = timer.take_labels();
    assert!(drawn.iter().all(|c| timed.contains(&c.pass)), "counted {drawn:?}, timed {timed:?}");
}
