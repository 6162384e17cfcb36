//! The sun the sky shows is the sun that lights the ground: aim the camera
//! along the light's direction, render, and the sun's disc must be at the
//! centre of the picture.

use common::headless::{OFFSCREEN_FORMAT, capture};
use common::{Camera, Chapter, Target};
use skybox::{SkyboxChapter, sun_at};

#[test]
fn the_sun_is_drawn_where_the_light_comes_from() {
    let gpu = crate::plain_gpu();
    let target = Target { format: OFFSCREEN_FORMAT, width: 240, height: 136, samples: 1 };
    let mut chapter: SkyboxChapter = common::chapter::create(gpu, target, &Default::default()).unwrap();
    chapter.select_view(0);
    for phase in [0.30, 0.42, 0.55, 0.70] {
        chapter.settings.start_phase = phase;
        let light = sun_at(phase).direction;
        let eye = chapter.camera.position;
        chapter.camera = Camera { far: 3000.0, ..Camera::looking_at(eye, eye + light, target.aspect()) };
        let image = capture(gpu, &mut chapter, target, (0.0, 0), Default::default()).unwrap();
        let (x, y, _) = image
            .enumerate_pixels()
            .max_by_key(|(_, _, p)| u32::from(p[0]) + u32::from(p[1]) + u32::from(p[2]))
            .unwrap();
        let (dx, dy) = (x as i32 - 120, y as i32 - 68);
        assert!(dx.abs() <= 2 && dy.abs() <= 2, "phase {phase}: the brightest pixel is at ({x}, {y}), not the centre");
    }
}
