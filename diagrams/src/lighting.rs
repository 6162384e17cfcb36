//! Chapter 08's figures: a point light's falloff, a spot light's cone, the
//! half vector, clusters from the side and the bloom chain, from the
//! chapter's lights, clusters and bloom.

use common::glam::Vec2;

use crate::kit::{ACCENT, Axes, BLUE, INK, MUTED, Svg};

/// Chapter 08: how a point light falls off, from `lighting::lights::attenuation`,
/// against the city project's constant–linear–quadratic formula.
pub fn light_falloff() -> String {
    use lighting::lights::attenuation;
    // On a log scale, because on a linear one every curve is a hair above
    // zero long before the range, and the window cannot be seen.
    let mut svg = Svg::new(640.0, 320.0);
    let axes = Axes { origin: Vec2::new(80.0, 40.0), size: Vec2::new(510.0, 210.0), x: (0.0, 24.0), y: (-4.0, 0.0) };
    axes.draw(
        &mut svg,
        &[0.0, 6.0, 12.0, 18.0, 24.0],
        &[],
        "distance from the light (m)",
        "share of the light's intensity (log scale)",
    );
    for (power, label) in [(0.0, "1"), (-1.0, "0.1"), (-2.0, "0.01"), (-3.0, "0.001"), (-4.0, "0.0001")] {
        let p = axes.at(0.0, power);
        svg.line(p, p - Vec2::new(5.0, 0.0), INK, 1.0);
        svg.text(p + Vec2::new(-8.0, 4.0), label, 11.0, "end", INK);
    }
    let log = |value: f32| value.max(1e-6).log10();
    let range = 18.0;
    axes.curve(&mut svg, |d| log(1.0 / (1.0 + 0.09 * d + 0.032 * d * d)), "#8a6fb0", 1.8);
    // Without the window: the chapter's falloff with an endless range.
    axes.curve(&mut svg, |d| log(attenuation(d, f32::INFINITY)), MUTED, 1.5);
    axes.curve(&mut svg, |d| log(attenuation(d, range)), ACCENT, 2.4);
    svg.dashed(axes.at(range, -4.0), axes.at(range, 0.0), "#c9c2b6");
    svg.text(axes.at(range, -0.25) + Vec2::new(6.0, 0.0), "range: exactly 0 beyond", 10.0, "start", INK);
    svg.text(Vec2::new(120.0, 224.0), "this chapter: 1/(d² + 1), windowed to 0 at 18 m", 11.0, "start", ACCENT);
    svg.text(Vec2::new(120.0, 240.0), "1/(d² + 1), never reaching 0", 11.0, "start", MUTED);
    svg.text(Vec2::new(585.0, 130.0), "the city project: 1/(1 + 0.09 d + 0.032 d²)", 11.0, "end", "#8a6fb0");
    svg.finish()
}

/// Chapter 08: a spot light's cone, from `lighting::lights::spot_factor`.
pub fn spot_cone() -> String {
    use lighting::lights::spot_factor;
    let mut svg = Svg::new(640.0, 300.0);
    let axes = Axes { origin: Vec2::new(340.0, 40.0), size: Vec2::new(260.0, 190.0), x: (0.0, 40.0), y: (0.0, 1.0) };
    axes.draw(&mut svg, &[0.0, 16.0, 28.0, 40.0], &[0.0, 1.0], "angle from the axis (°)", "light");
    let (inner, outer) = (16f32.to_radians(), 28f32.to_radians());
    axes.curve(&mut svg, |deg| spot_factor(deg.to_radians().cos(), inner.cos(), outer.cos()), ACCENT, 2.4);
    // The cone itself, from the side.
    let apex = Vec2::new(60.0, 70.0);
    let axis = Vec2::new(0.95, 0.31).normalize();
    let ray = |angle: f32, length: f32| {
        let (s, c) = angle.sin_cos();
        apex + Vec2::new(axis.x * c - axis.y * s, axis.x * s + axis.y * c) * length
    };
    let cone = |half: f32| -> Vec<Vec2> {
        let arc = (0..=24).map(|i| ray(-half + 2.0 * half * i as f32 / 24.0, 240.0));
        std::iter::once(apex).chain(arc).collect()
    };
    svg.polygon(&cone(outer), "#f6e7d3", "none");
    svg.polygon(&cone(inner), "#efc9a0", "none");
    svg.dashed(apex, ray(0.0, 250.0), MUTED);
    svg.circle(apex, 5.0, INK);
    svg.text(ray(inner, 150.0) + Vec2::new(0.0, -6.0), "inner cone: all of it", 10.0, "middle", INK);
    svg.text(ray(outer, 200.0) + Vec2::new(0.0, 14.0), "outer cone: fading to none", 10.0, "middle", INK);
    svg.text(Vec2::new(20.0, 30.0), "a headlight: inner 16°, outer 28°", 11.0, "start", INK);
    svg.finish()
}

/// Chapter 08: the vectors of a highlight.
pub fn half_vector() -> String {
    let mut svg = Svg::new(640.0, 280.0);
    let p = Vec2::new(320.0, 220.0);
    svg.line(Vec2::new(100.0, 220.0), Vec2::new(540.0, 220.0), INK, 2.0);
    let at = |degrees_from_normal: f32, length: f32| {
        let a = degrees_from_normal.to_radians();
        p + Vec2::new(a.sin(), -a.cos()) * length
    };
    let (light, view) = (-50.0f32, 20.0f32);
    let half = (light + view) / 2.0;
    let mirror = -light;
    svg.arrow(p, at(0.0, 150.0), INK);
    svg.arrow(p, at(light, 150.0), ACCENT);
    svg.arrow(p, at(view, 150.0), BLUE);
    svg.arrow(p, at(mirror, 150.0), MUTED);
    svg.arrow(p, at(half, 120.0), "#8a6fb0");
    svg.text(at(0.0, 162.0), "n", 13.0, "middle", INK);
    svg.text(at(light, 166.0), "l, to the light", 12.0, "middle", ACCENT);
    svg.text(at(view, 166.0) + Vec2::new(22.0, 0.0), "v, to the eye", 12.0, "middle", BLUE);
    svg.text(at(mirror, 166.0) + Vec2::new(40.0, 0.0), "r, l mirrored in n", 12.0, "middle", MUTED);
    svg.text(at(half, 132.0) + Vec2::new(-28.0, 0.0), "h = (l + v) / |l + v|", 12.0, "middle", "#8a6fb0");
    svg.text(
        Vec2::new(20.0, 24.0),
        "Phong compares r with v; Blinn compares h with n. The highlight peaks where they meet.",
        11.0,
        "start",
        INK,
    );
    svg.finish()
}

/// Chapter 08: clusters from the side: depth slices spaced as
/// `lighting::clusters::slice` spaces them, and a light marking the ones it reaches.
pub fn clusters_side() -> String {
    use lighting::clusters::{GRID, slice};
    let mut svg = Svg::new(640.0, 320.0);
    let (near, far) = (0.5f32, 900.0f32);
    let eye = Vec2::new(30.0, 160.0);
    let depth_scale = 580.0 / 400.0; // pixels per metre: the first 400 m
    let half = 30f32.to_radians();
    let to_screen = |depth: f32, up: f32| eye + Vec2::new(depth * depth_scale, -up * depth_scale);
    // Slice boundaries: where `slice` steps up.
    let mut boundaries = vec![near];
    let mut d = near;
    while d < 400.0 {
        d *= 1.001;
        if slice(d, near, far) != slice(boundaries[boundaries.len() - 1], near, far) {
            boundaries.push(d);
        }
    }
    let light = (150.0f32, 10.0f32, 30.0f32); // depth, height, range
    let (first, last) = (slice(light.0 - light.2, near, far), slice(light.0 + light.2, near, far));
    for pair in boundaries.windows(2) {
        let (a, b) = (pair[0], pair[1]);
        let s = slice((a + b) / 2.0, near, far);
        let fill = if s >= first && s <= last { "#f3d9bf" } else { "none" };
        for row in 0..GRID[1] {
            let t0 = -1.0 + 2.0 * row as f32 / GRID[1] as f32;
            let t1 = -1.0 + 2.0 * (row + 1) as f32 / GRID[1] as f32;
            let up = |d: f32, t: f32| d * half.tan() * t;
            let corners =
                [to_screen(a, up(a, t0)), to_screen(b, up(b, t0)), to_screen(b, up(b, t1)), to_screen(a, up(a, t1))];
            let inside = up(light.0, t1) >= light.1 - light.2 && up(light.0, t0) <= light.1 + light.2;
            svg.polygon(&corners, if inside { fill } else { "none" }, "#d9cfc1");
        }
    }
    let centre = to_screen(light.0, light.1);
    svg.ring(centre, light.2 * depth_scale, ACCENT, 2.0);
    svg.circle(centre, 4.0, ACCENT);
    svg.circle(eye, 5.0, INK);
    svg.text(eye + Vec2::new(0.0, 22.0), "eye", 11.0, "middle", INK);
    svg.text(
        Vec2::new(20.0, 24.0),
        &format!("{} depth slices from 0.5 m to 900 m, each deeper than the last (the first 400 m shown)", GRID[2]),
        11.0,
        "start",
        INK,
    );
    svg.text(
        centre + Vec2::new(0.0, light.2 * depth_scale + 16.0),
        "a light and the clusters it is listed in",
        11.0,
        "middle",
        ACCENT,
    );
    svg.finish()
}

/// Chapter 08: the bloom chain, as `lighting::bloom::level_sizes` makes it for 1280 × 720.
pub fn bloom_chain() -> String {
    use lighting::bloom::level_sizes;
    let mut svg = Svg::new(640.0, 260.0);
    let sizes = level_sizes(1280, 720);
    let scale = 0.16;
    let mut x = 20.0;
    let top = 60.0;
    svg.rect(x, top, 1280.0 * scale, 720.0 * scale, "#efe6da", INK);
    svg.text(Vec2::new(x + 640.0 * scale, top - 8.0), "HDR picture 1280 × 720", 11.0, "middle", INK);
    x += 1280.0 * scale + 18.0;
    let mut previous = Vec2::new(20.0 + 1280.0 * scale, top + 30.0);
    for (i, (w, h)) in sizes.iter().enumerate() {
        let (w, h) = (*w as f32 * scale * 1.2, *h as f32 * scale * 1.2);
        svg.rect(x, top, w, h, "#f3d9bf", INK);
        // Alternate rows, so that the small levels' labels do not overlap.
        let below = top + h + 14.0 + if i >= 3 { (i % 2) as f32 * 12.0 } else { 0.0 };
        svg.text(Vec2::new(x + w / 2.0, below), &format!("{}×{}", sizes[i].0, sizes[i].1), 9.0, "middle", INK);
        svg.arrow(previous, Vec2::new(x - 2.0, top + 8.0), ACCENT);
        previous = Vec2::new(x + w, top + 8.0);
        x += w + 22.0;
    }
    svg.text(
        Vec2::new(20.0, 24.0),
        "down: take out the bright part, then halve with a 13-tap filter, level by level",
        11.0,
        "start",
        ACCENT,
    );
    svg.arrow(Vec2::new(600.0, 215.0), Vec2::new(250.0, 215.0), BLUE);
    svg.text(
        Vec2::new(20.0, 245.0),
        "up: a 3 × 3 tent from each level, blended into the one above by the spread; the top level is the bloom",
        11.0,
        "start",
        BLUE,
    );
    svg.finish()
}
