//! A chapter's own flags mean the same headless as in the window. The
//! window's first frame calls `Chapter::update`, which no headless picture
//! calls: `--walk` (chapters 03 to 07) must still put the eye on the
//! ground in a `--screenshot`, as the first walking frame does.

use common::chapter::FlagValues;
use common::headless::{RenderRequest, render_image_with, started};
use common::{Chapter, Gpu, Input};
use terrain::TerrainChapter;
use terrain::ground::EYE_HEIGHT;

#[test]
fn walk_puts_the_eye_on_the_ground_headless_too() {
    let gpu = Gpu::headless(TerrainChapter::gpu_needs()).expect("an adapter (lavapipe will do)");
    let request = RenderRequest {
        width: 160,
        height: 90,
        time: TerrainChapter::SNAPSHOT_TIME,
        view: 0,
        camera: None,
        antialiasing: common::Antialiasing::Off,
    };
    let walk = FlagValues(vec![("walk", "true".into())]);
    let walking = started::<TerrainChapter>(&gpu, &request, &walk).unwrap();
    let flying = started::<TerrainChapter>(&gpu, &request, &FlagValues::default()).unwrap();

    // Where a walker stands: the ground under the flying eye (it is well
    // inside the map), plus the eye's height.
    let (eye, above) = (walking.camera.position, flying.camera.position);
    let ground = walking.terrain.field().height_at(eye.x, eye.z);
    assert!((eye.x, eye.z) == (above.x, above.z), "walking starts under the flying eye: {eye} vs {above}");
    assert!((eye.y - ground - EYE_HEIGHT).abs() < 1e-3, "the eye {eye} over ground at {ground}");
    assert!(above.y - ground > 10.0 * EYE_HEIGHT, "the default view flies high: {above} over {ground}");

    // As the window's first frame: a walking chapter started the old way
    // (view only) and given one `update` with no input ends in the same place.
    let mut windowed = common::chapter::create::<TerrainChapter>(&gpu, request_target(&request), &walk).unwrap();
    windowed.select_view(request.view);
    windowed.update(&Input::default(), 0.0);
    assert_eq!(windowed.camera, walking.camera, "headless starts where the window's first frame does");

    // `--walk --screenshot` draws the walker's picture, not the flyer's.
    let on_foot = render_image_with::<TerrainChapter>(&gpu, &request, &walk).unwrap();
    let in_the_air = render_image_with::<TerrainChapter>(&gpu, &request, &FlagValues::default()).unwrap();
    let differing = on_foot.pixels().zip(in_the_air.pixels()).filter(|(a, b)| a != b).count();
    assert!(differing > (160 * 90) / 4, "only {differing} of 14,400 pixels differ");
}

fn request_target(request: &RenderRequest) -> common::Target {
    common::Target {
        format: common::headless::OFFSCREEN_FORMAT,
        width: request.width,
        height: request.height,
        samples: 1,
    }
}
