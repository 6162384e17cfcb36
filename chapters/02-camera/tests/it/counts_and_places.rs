//! What a frame drew, counted as it is recorded, against the scene counted
//! another way; and `--camera`, which puts any run of the chapter at a
//! place the overlay printed.

use camera::{CameraChapter, Shape, scene};
use common::chapter::view_index;
use common::headless::{OFFSCREEN_FORMAT, Offscreen, RenderRequest, draw_frame, render_image, started};
use common::{Camera, CameraPlace, Chapter, Drawn, Gpu, GpuNeeds, PassCount, PassTimer, Target, primitives};

fn gpu() -> Gpu {
    Gpu::headless(GpuNeeds::default()).expect("an adapter (lavapipe will do)")
}

/// The scene pass draws the ground and every object once: its count must
/// be the sum, over the scene's placements, of each shape's triangles as
/// the primitive functions make them on the CPU (plus the ground's plane),
/// not a number the draws were compared with by construction. The depth
/// views add the one full-screen triangle that shows the buffer.
#[test]
fn the_scene_pass_counts_every_mesh_it_draws() {
    let gpu = gpu();
    let target = Target { format: OFFSCREEN_FORMAT, width: 64, height: 36, samples: 1 };
    let mut chapter = common::chapter::create::<CameraChapter>(&gpu, target, &Default::default()).unwrap();
    let offscreen = Offscreen::new(&gpu.device, target);
    let placements = scene();
    let objects: u64 = placements.iter().map(|p| p.shape.mesh().triangles().count() as u64).sum();
    let ground = primitives::plane(1).triangles().count() as u64;
    let expected = Drawn::counted(placements.len() as u32 + 1, objects + ground);
    // Worked by hand from `scene()`: three of each of the six shapes.
    assert_eq!(placements.len(), 3 * Shape::ALL.len());
    for (name, extra) in [("default", None), ("depth", Some(Drawn::FULL_SCREEN)), ("normals", None)] {
        let view = view_index::<CameraChapter>(name).unwrap();
        chapter.select_view(view);
        let timer = PassTimer::off();
        let drawn = draw_frame(&gpu, &mut chapter, &offscreen.view, (1.0, view), Default::default(), &timer);
        let mut want = vec![PassCount { pass: "scene", drawn: expected }];
        want.extend(extra.map(|drawn| PassCount { pass: "depth view", drawn }));
        assert_eq!(drawn, want, "{name}");
        let timed = timer.take_labels();
        assert!(drawn.iter().all(|c| timed.contains(&c.pass)), "{name}: counted {drawn:?}, timed {timed:?}");
    }
}

fn request(view: usize, camera: Option<CameraPlace>) -> RenderRequest {
    RenderRequest {
        width: 96,
        height: 54,
        time: CameraChapter::SNAPSHOT_TIME,
        view,
        camera,
        antialiasing: common::Antialiasing::Off,
    }
}

/// `--camera` with the view's own camera, written with every digit, draws
/// the very picture the view draws without it; a place the overlay
/// printed (two decimals) elsewhere draws another, from exactly there.
#[test]
fn a_camera_flag_draws_from_that_place() {
    let gpu = gpu();
    let view = 0;
    let own: Camera = *started::<CameraChapter>(&gpu, &request(view, None), &Default::default())
        .unwrap()
        .camera_mut()
        .expect("chapter 02 has a camera");
    let every_digit = format!(
        "{},{},{},{},{}",
        own.position.x,
        own.position.y,
        own.position.z,
        f64::from(own.yaw).to_degrees(),
        f64::from(own.pitch).to_degrees()
    );
    let same: CameraPlace = every_digit.parse().unwrap();
    let plain = render_image::<CameraChapter>(&gpu, &request(view, None)).unwrap();
    let placed = render_image::<CameraChapter>(&gpu, &request(view, Some(same))).unwrap();
    assert!(plain == placed, "--camera {every_digit} is the view's own camera: the same bytes");

    // Two metres to the right and ten degrees further round, as the
    // overlay would print it.
    let moved = Camera { position: own.position + own.right() * 2.0, yaw: own.yaw + 10f32.to_radians(), ..own };
    let printed = CameraPlace::of(&moved).to_string();
    let elsewhere: CameraPlace = printed.parse().unwrap();
    let mut chapter = started::<CameraChapter>(&gpu, &request(view, Some(elsewhere)), &Default::default()).unwrap();
    let placed_at = *chapter.camera_mut().unwrap();
    assert_eq!(CameraPlace::of(&placed_at), elsewhere, "--camera {printed} places the camera there");
    assert_eq!((placed_at.fov_y, placed_at.near, placed_at.far), (own.fov_y, own.near, own.far), "optics kept");
    let other = render_image::<CameraChapter>(&gpu, &request(view, Some(elsewhere))).unwrap();
    let differing = plain.pixels().zip(other.pixels()).filter(|(a, b)| a != b).count();
    let tenth = (plain.width() * plain.height() / 10) as usize;
    assert!(differing > tenth, "--camera {printed}: only {differing} pixels changed");
}
