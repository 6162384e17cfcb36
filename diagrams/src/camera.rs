//! Chapter 02's figures: the view frustum from the side, and how stored
//! depth spends its range under the real projection.

use common::Camera;
use common::glam::{Vec2, Vec3};

use crate::kit::{ACCENT, Axes, BLUE, INK, MUTED, Svg};

/// Chapter 02: the view frustum from the side.
pub fn frustum_side() -> String {
    let mut svg = Svg::new(640.0, 440.0);
    let eye = Vec2::new(60.0, 220.0);
    let half = 30f32.to_radians(); // a 60° vertical field of view
    let (near, far) = (70.0, 330.0);
    let edge = |d: f32, up: f32| eye + Vec2::new(d, -up * d * half.tan());
    svg.polygon(&[edge(near, 1.0), edge(far, 1.0), edge(far, -1.0), edge(near, -1.0)], "#efe6da", "none");
    svg.line(eye, edge(far, 1.0), INK, 1.2);
    svg.line(eye, edge(far, -1.0), INK, 1.2);
    svg.line(edge(near, 1.0), edge(near, -1.0), BLUE, 2.0);
    svg.line(edge(far, 1.0), edge(far, -1.0), BLUE, 2.0);
    svg.dashed(eye, eye + Vec2::new(far + 40.0, 0.0), MUTED);
    svg.circle(eye, 5.0, INK);
    svg.text(eye + Vec2::new(0.0, 24.0), "eye", 12.0, "middle", INK);
    svg.text(edge(near, -1.0) + Vec2::new(0.0, 18.0), "near (z = 0)", 11.0, "middle", BLUE);
    svg.text(edge(far, -1.0) + Vec2::new(-4.0, 18.0), "far (z = 1)", 11.0, "middle", BLUE);
    svg.text(edge(far, 1.0) + Vec2::new(8.0, 14.0), "fov_y = 60° from edge to edge", 11.0, "start", INK);
    svg.text(
        Vec2::new(20.0, 24.0),
        "Everything drawn lies between the planes: −w ≤ x ≤ w, −w ≤ y ≤ w, 0 ≤ z ≤ w.",
        11.0,
        "start",
        INK,
    );
    // An object, and where it lands on the near plane.
    let object = eye + Vec2::new(240.0, -70.0);
    svg.rect(object.x - 14.0, object.y - 14.0, 28.0, 28.0, ACCENT, "none");
    let hit = eye + (object - eye) * (near / (object.x - eye.x));
    svg.dashed(eye, object, ACCENT);
    svg.circle(hit, 3.5, ACCENT);
    svg.text(object + Vec2::new(22.0, 4.0), "an object, and its image on the near plane", 11.0, "start", ACCENT);
    svg.finish()
}

/// Chapter 02: how stored depth spends its range, from the real projection.
pub fn depth_precision() -> String {
    let mut svg = Svg::new(640.0, 300.0);
    let camera = Camera { near: 0.1, far: 200.0, ..Camera::looking_at(Vec3::ZERO, Vec3::NEG_Z, 1.0) };
    let stored = |distance: f32| {
        let clip = camera.projection() * Vec3::new(0.0, 0.0, -distance).extend(1.0);
        clip.z / clip.w
    };
    let axes = Axes { origin: Vec2::new(70.0, 40.0), size: Vec2::new(520.0, 200.0), x: (0.1, 20.0), y: (0.0, 1.0) };
    axes.draw(
        &mut svg,
        &[0.1, 5.0, 10.0, 15.0, 20.0],
        &[0.0, 0.5, 0.99],
        "distance from the eye (m), near 0.1 m, far 200 m",
        "stored depth",
    );
    axes.curve(&mut svg, stored, BLUE, 2.2);
    for (distance, label) in [(0.2, "0.5 at 0.2 m"), (10.0, "0.99 at 10 m")] {
        let p = axes.at(distance, stored(distance));
        svg.circle(p, 4.0, ACCENT);
        svg.text(p + Vec2::new(8.0, 16.0), label, 11.0, "start", ACCENT);
    }
    svg.finish()
}

/// The standard positions of four samples in a pixel, as fractions of its
/// side from its top-left corner: Vulkan, Metal and Direct3D share them,
/// and WebGPU relies on them (gpuweb issue 108).
pub const FOUR_SAMPLES: [(f32, f32); 4] = [(0.375, 0.125), (0.875, 0.375), (0.125, 0.625), (0.625, 0.875)];

/// Chapter 02: an edge crossing a row of pixels, sampled once at each
/// pixel's centre and at the four standard sample positions; each pixel
/// is shaded by the share of its samples inside.
pub fn multisampling() -> String {
    let (cell, pixels, rows) = (64.0, 6, 3);
    let origin = Vec2::new(40.0, 70.0);
    let mut svg = Svg::new(720.0, origin.y + cell * rows as f32 + 50.0);
    // The edge: inside is below the line from (0, 2.6) to (6, 0.4), in pixels.
    let (a, b) = (Vec2::new(0.0, 2.6), Vec2::new(6.0, 0.4));
    let inside = |p: Vec2| (b - a).perp_dot(p - a) > 0.0;
    let at = |p: Vec2| origin + p * cell;
    for row in 0..rows {
        for column in 0..pixels {
            let corner = Vec2::new(column as f32, row as f32);
            let covered = FOUR_SAMPLES.iter().filter(|(x, y)| inside(corner + Vec2::new(*x, *y))).count();
            // The resolve: the pixel's colour is the mean of its samples.
            let shade = 255 - (covered as u32 * 150 / 4) as u8;
            let fill = format!("#{shade:02x}{:02x}{:02x}", 255 - (covered as u32 * 60 / 4) as u8, 255u8);
            let p = at(corner);
            svg.rect(p.x, p.y, cell, cell, &fill, MUTED);
            for (x, y) in FOUR_SAMPLES {
                let sample = corner + Vec2::new(x, y);
                if inside(sample) {
                    svg.circle(at(sample), 4.5, BLUE);
                } else {
                    svg.ring(at(sample), 4.5, BLUE, 1.2);
                }
            }
            let centre = corner + Vec2::splat(0.5);
            svg.circle(at(centre), 3.0, if inside(centre) { ACCENT } else { MUTED });
        }
    }
    svg.line(at(a), at(b), ACCENT, 2.0);
    svg.text(
        Vec2::new(origin.x, 28.0),
        "An edge (red) across pixels: one sample at each centre (small dot) sees all or nothing;",
        11.0,
        "start",
        INK,
    );
    svg.text(
        Vec2::new(origin.x, 46.0),
        "four samples (blue: filled inside, hollow outside) give the share covered, in quarters.",
        11.0,
        "start",
        INK,
    );
    let below = origin.y + cell * rows as f32 + 28.0;
    svg.text(
        Vec2::new(origin.x, below),
        "Each pixel's shade is the mean of its samples (the resolve); the shader ran once for each pixel touched.",
        11.0,
        "start",
        INK,
    );
    svg.finish()
}
