//! Chapter 03's figures: octaves of Perlin noise and their sum, and the
//! chunks a camera's frustum keeps, from the chapter's noise and culling.

use common::Camera;
use common::glam::{Vec2, Vec3};

use crate::kit::{ACCENT, Axes, INK, MUTED, Svg};

/// Chapter 03: octaves of Perlin noise and their sum, from the chapter's noise.
pub fn fbm_octaves() -> String {
    use terrain::noise::{Fbm, perlin3};
    let mut svg = Svg::new(640.0, 430.0);
    let fbm = Fbm { octaves: 4, persistence: 0.5, lacunarity: 2.0 };
    let row = |i: usize, height: f32| Axes {
        origin: Vec2::new(30.0, 34.0 + i as f32 * 74.0),
        size: Vec2::new(580.0, height),
        x: (0.0, 4.0),
        y: (-0.6, 0.6),
    };
    // Octave o is at lacunarity^o times the frequency and persistence^o
    // times the height, on the same slice as `Fbm::sample` takes it: x and
    // y both scaled by the frequency, z left alone. So the rows add up to
    // the sum below.
    let octave_scale = |factor: f64, octave: u32| factor.powi(octave as i32) as f32;
    let (y, z) = (0.5, 0.5);
    for octave in 0..fbm.octaves {
        let axes = row(octave as usize, 50.0);
        let (frequency, amplitude) = (octave_scale(fbm.lacunarity, octave), octave_scale(fbm.persistence, octave));
        svg.line(axes.at(0.0, 0.0), axes.at(4.0, 0.0), "#e3dccf", 1.0);
        let f = f64::from(frequency);
        axes.curve(&mut svg, |x| amplitude * perlin3(f64::from(x) * f, y * f, z) as f32, MUTED, 1.6);
        let label = format!("octave {}: frequency ×{frequency}, height ×{amplitude}", octave + 1);
        svg.text(axes.origin - Vec2::new(0.0, 6.0), &label, 11.0, "start", INK);
    }
    // The sum of the rows above; `Fbm::sample` divides it by the sum of the
    // heights, 1 + ½ + ¼ + ⅛.
    let total: f32 = (0..fbm.octaves).map(|o| octave_scale(fbm.persistence, o)).sum();
    let sum = row(fbm.octaves as usize, 80.0);
    svg.line(sum.at(0.0, 0.0), sum.at(4.0, 0.0), "#e3dccf", 1.0);
    sum.curve(&mut svg, |x| fbm.sample(f64::from(x), y, z) as f32 * total, ACCENT, 2.2);
    svg.text(sum.origin - Vec2::new(0.0, 6.0), "their sum: hills on hills (fBm)", 11.0, "start", ACCENT);
    svg.finish()
}

/// Chapter 03: which chunks a camera's frustum keeps, seen from above,
/// computed with the chapter's `Frustum` on a 16 × 16 grid of 64 m chunks.
pub fn frustum_culling() -> String {
    use terrain::chunks::Aabb;
    use terrain::culling::Frustum;
    let mut svg = Svg::new(640.0, 400.0);
    let (n, size, cell) = (16, 64.0f32, 22.0f32);
    let origin = Vec2::new(30.0, 20.0);
    let eye = Vec3::new(5.5 * size, 20.0, 13.5 * size);
    let camera = Camera { far: 700.0, ..Camera::looking_at(eye, eye + Vec3::new(0.55, -0.05, -1.0), 16.0 / 9.0) };
    let frustum = Frustum::from_view_projection(camera.view_projection());
    let mut kept = 0;
    for z in 0..n {
        for x in 0..n {
            let min = Vec3::new(x as f32 * size, -10.0, z as f32 * size);
            let visible = frustum.intersects(&Aabb { min, max: min + Vec3::new(size, 30.0, size) });
            kept += usize::from(visible);
            let fill = if visible { "#e7b48f" } else { "#e6e2da" };
            svg.rect(origin.x + x as f32 * cell, origin.y + z as f32 * cell, cell, cell, fill, "#ffffff");
        }
    }
    let to_map = |p: Vec3| origin + Vec2::new(p.x, p.z) / size * cell;
    let forward = Vec2::new(camera.forward().x, camera.forward().z).normalize();
    let half = (camera.fov_y / 2.0).tan() * camera.aspect;
    let side = Vec2::new(-forward.y, forward.x);
    let far_corner = |s: f32| to_map(eye) + (forward + side * s * half) * camera.far / size * cell;
    svg.clip(origin.x, origin.y, n as f32 * cell, n as f32 * cell);
    svg.polygon(&[to_map(eye), far_corner(1.0), far_corner(-1.0)], "none", ACCENT);
    svg.unclip();
    svg.circle(to_map(eye), 5.0, INK);
    let legend = origin.x + n as f32 * cell + 24.0;
    svg.rect(legend, 40.0, 16.0, 16.0, "#e7b48f", "none");
    svg.text(Vec2::new(legend + 24.0, 53.0), &format!("drawn ({kept} of {})", n * n), 12.0, "start", INK);
    svg.rect(legend, 66.0, 16.0, 16.0, "#e6e2da", "none");
    svg.text(Vec2::new(legend + 24.0, 79.0), "culled", 12.0, "start", INK);
    svg.line(Vec2::new(legend, 102.0), Vec2::new(legend + 16.0, 102.0), ACCENT, 1.5);
    svg.text(Vec2::new(legend + 24.0, 106.0), "the frustum, from above", 12.0, "start", INK);
    svg.text(Vec2::new(legend, 140.0), "A chunk is kept when its box", 11.0, "start", INK);
    svg.text(Vec2::new(legend, 156.0), "is not wholly outside one of", 11.0, "start", INK);
    svg.text(Vec2::new(legend, 172.0), "the six planes: boxes near an", 11.0, "start", INK);
    svg.text(Vec2::new(legend, 188.0), "edge are kept, never missed.", 11.0, "start", INK);
    svg.finish()
}
