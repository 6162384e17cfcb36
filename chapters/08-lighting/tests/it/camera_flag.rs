//! `--camera` on a view whose camera rides a car: the frame is drawn from
//! the place given, not from the car, as when the learner takes the keys.

use common::chapter::view_index;
use common::headless::{OFFSCREEN_FORMAT, RenderRequest, capture, started};
use common::{CameraPlace, Chapter, Gpu, Target};
use lighting::LightingChapter;

#[test]
fn a_placed_camera_stops_riding() {
    let gpu = Gpu::headless(LightingChapter::gpu_needs()).expect("an adapter (lavapipe will do)");
    let (width, height) = (64, 36);
    let target = Target { format: OFFSCREEN_FORMAT, width, height, samples: 1 };
    let view = view_index::<LightingChapter>("follow").unwrap();
    let place: CameraPlace = "10,30,-40,135,-20".parse().unwrap();
    let request = |camera| RenderRequest {
        width,
        height,
        time: LightingChapter::SNAPSHOT_TIME,
        view,
        camera,
        antialiasing: common::Antialiasing::Off,
    };
    let time = LightingChapter::SNAPSHOT_TIME;

    let mut riding = started::<LightingChapter>(&gpu, &request(None), &Default::default()).unwrap();
    capture(&gpu, &mut riding, target, (time, view), Default::default()).unwrap();
    let on_the_car = CameraPlace::of(riding.camera_mut().unwrap());
    assert!(on_the_car.position.distance(place.position) > 10.0, "the car is elsewhere: {on_the_car}");

    let mut placed = started::<LightingChapter>(&gpu, &request(Some(place)), &Default::default()).unwrap();
    capture(&gpu, &mut placed, target, (time, view), Default::default()).unwrap();
    assert_eq!(CameraPlace::of(placed.camera_mut().unwrap()), place, "drawn from where --camera put it");
}
