//! Chapter 08's figures: Lambert's cosine law, a point light's falloff, a
//! spot light's cone, the half vector, clusters from the side, the tone
//! curves, the bloom's chain, knee and downsample taps, FXAA, and the
//! microfacet model's terms and white furnace, from the chapter's lights,
//! clusters, tone map, bloom and physically based shading.

use common::glam::Vec2;

use crate::kit::{ACCENT, Axes, BLUE, INK, MUTED, PAPER, Svg};

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

/// `f` as a dashed line: every other of its 120 pieces.
fn dashed_curve(svg: &mut Svg, axes: &Axes, f: impl Fn(f32) -> f32, stroke: &str) {
    let at = |i: usize| {
        let x = axes.x.0 + (axes.x.1 - axes.x.0) * i as f32 / 120.0;
        axes.at(x, f(x).clamp(axes.y.0, axes.y.1))
    };
    for i in (0..120).step_by(2) {
        svg.polyline(&[at(i), at(i + 1)], stroke, 1.6);
    }
}

/// Chapter 08: tone curves against exposed light in stops: clipping,
/// Reinhard's x / (1 + x), and the ACES fit the chapter uses
/// (`lighting::post::aces_fit`, the same as tonemap.wgsl), with and without
/// the 0.6 that would give the original ACES curve's exposure.
pub fn tone_curves() -> String {
    use lighting::post::aces_fit;
    let mut svg = Svg::new(640.0, 340.0);
    let axes = Axes { origin: Vec2::new(70.0, 50.0), size: Vec2::new(520.0, 220.0), x: (-6.0, 4.0), y: (0.0, 1.0) };
    axes.draw(
        &mut svg,
        &[-6.0, -4.0, -2.0, 0.0, 2.0, 4.0],
        &[0.0, 0.25, 0.5, 0.75, 1.0],
        "light × exposure, in stops from 1 (each stop doubles it)",
        "value on screen (linear, before sRGB encoding)",
    );
    let light = |stops: f32| 2f32.powf(stops);
    svg.dashed(axes.at(0.0, 0.0), axes.at(0.0, 1.0), "#c9c2b6");
    axes.curve(&mut svg, |s| light(s).min(1.0), MUTED, 1.5);
    axes.curve(&mut svg, |s| light(s) / (1.0 + light(s)), BLUE, 1.8);
    dashed_curve(&mut svg, &axes, |s| aces_fit(0.6 * light(s)), "#8a6fb0");
    axes.curve(&mut svg, |s| aces_fit(light(s)), ACCENT, 2.4);
    // Where the fit meets 1 and clips: its asymptote, 2.51 / 2.43, is above 1.
    let clip = (0.56 + (0.56f32 * 0.56 + 4.0 * 0.08 * 0.14).sqrt()) / 0.16;
    assert!((aces_fit(clip) - 1.0).abs() < 1e-4 && aces_fit(clip * 0.99) < 1.0);
    svg.circle(axes.at(clip.log2(), 1.0), 3.5, ACCENT);
    svg.text(axes.at(clip.log2(), 1.0) + Vec2::new(0.0, -8.0), &format!("{clip:.2}: white"), 10.0, "middle", ACCENT);
    for (value, colour) in [(aces_fit(1.0), ACCENT), (0.5, BLUE)] {
        svg.circle(axes.at(0.0, value), 3.5, colour);
        svg.text(axes.at(0.0, value) + Vec2::new(-6.0, -5.0), &format!("{value:.2}"), 10.0, "end", colour);
    }
    // The key, in the corner no curve reaches.
    svg.text(Vec2::new(84.0, 68.0), "clip: min(x, 1)", 11.0, "start", MUTED);
    svg.text(Vec2::new(84.0, 82.0), "Reinhard: x / (1 + x)", 11.0, "start", BLUE);
    svg.text(Vec2::new(84.0, 96.0), "ACES fit (Narkowicz): this chapter", 11.0, "start", ACCENT);
    svg.text(Vec2::new(84.0, 110.0), "ACES fit of 0.6 x: ACES's exposure", 11.0, "start", "#8a6fb0");
    svg.finish()
}

/// Chapter 08: the bloom's bright part against brightness (a grey's
/// channel), from `lighting::bloom::BloomSettings::bright_part` with the
/// chapter's settings: a hard cut at the threshold, and the soft knee.
pub fn bloom_knee() -> String {
    use lighting::bloom::BloomSettings;
    let settings = BloomSettings::DEFAULT;
    let (threshold, knee) = (settings.threshold, settings.knee);
    let mut svg = Svg::new(640.0, 320.0);
    let axes = Axes { origin: Vec2::new(70.0, 50.0), size: Vec2::new(520.0, 200.0), x: (0.0, 3.0), y: (0.0, 2.0) };
    let (low, high) = (axes.at(threshold - knee, 2.0), axes.at(threshold + knee, 0.0));
    svg.rect(low.x, low.y, high.x - low.x, high.y - low.y, "#f6e7d3", "none");
    axes.draw(
        &mut svg,
        &[0.0, threshold - knee, threshold, threshold + knee, 2.0, 3.0],
        &[0.0, 0.5, 1.0, 1.5, 2.0],
        "brightness: the largest of the three channels",
        "what blooms",
    );
    axes.curve(&mut svg, |b| settings.bright_part([b; 3])[0], ACCENT, 2.4);
    // On top: above the knee the two are the same line.
    dashed_curve(&mut svg, &axes, |b| (b - threshold).max(0.0), INK);
    svg.text(
        axes.at(threshold, 1.9),
        &format!("the knee: {} to {}", threshold - knee, threshold + knee),
        10.0,
        "middle",
        INK,
    );
    // The key, under the curve's right half.
    svg.text(Vec2::new(585.0, 206.0), &format!("dashed, a hard cut: max(b − {threshold}, 0)"), 11.0, "end", INK);
    svg.text(
        Vec2::new(585.0, 220.0),
        &format!("the chapter: (b − {})² / {} in the knee,", threshold - knee, 4.0 * knee),
        11.0,
        "end",
        ACCENT,
    );
    svg.text(Vec2::new(585.0, 234.0), &format!("b − {threshold} above it"), 11.0, "end", ACCENT);
    svg.finish()
}

/// Chapter 08: the 13 taps of the bloom's downsample
/// (`lighting::bloom::DOWNSAMPLE_TAPS`, held to bloom.wgsl by a test) on
/// the texels of the level they read, and what each texel weighs in the end.
pub fn downsample_taps() -> String {
    use lighting::bloom::DOWNSAMPLE_TAPS;
    let mut svg = Svg::new(640.0, 330.0);
    let cell = 36.0;
    // Texels −3‥2 on each axis; tap offsets are texel corners, −2‥2.
    let panel = |left: f32| move |x: f32, y: f32| Vec2::new(left + (x + 3.0) * cell, 70.0 + (y + 3.0) * cell);
    let (taps, texels) = (panel(40.0), panel(360.0));
    // What each texel weighs: a bilinear tap at a corner reads its four texels a quarter each.
    let mut weight = [[0.0f32; 6]; 6];
    for ([x, y], w) in DOWNSAMPLE_TAPS {
        for (tx, ty) in [(x - 1.0, y - 1.0), (x, y - 1.0), (x - 1.0, y), (x, y)] {
            weight[(ty + 3.0) as usize][(tx + 3.0) as usize] += w / 4.0;
        }
    }
    let heaviest = weight.iter().flatten().fold(0.0f32, |a, &b| a.max(b));
    for (row, weights) in weight.iter().enumerate() {
        for (column, &texel_weight) in weights.iter().enumerate() {
            let (x, y) = (column as f32 - 3.0, row as f32 - 3.0);
            svg.rect(taps(x, y).x, taps(x, y).y, cell, cell, "#efe6da", "#d9cfc1");
            let share = texel_weight / heaviest;
            let shade = format!(
                "rgb({0:.0},{1:.0},{2:.0})",
                250.0 - 58.0 * share,
                240.0 - 157.0 * share,
                228.0 - 185.0 * share
            );
            svg.rect(texels(x, y).x, texels(x, y).y, cell, cell, &shade, "#d9cfc1");
            let label = format!("{}", (texel_weight * 128.0).round());
            let ink = if share > 0.6 { "#fbf8f3" } else { INK };
            svg.text(texels(x, y) + Vec2::new(cell / 2.0, cell / 2.0 + 4.0), &label, 11.0, "middle", ink);
        }
    }
    // The output texel: the 2 × 2 block around the middle corner.
    for at in [taps, texels] {
        svg.rect(at(-1.0, -1.0).x, at(-1.0, -1.0).y, 2.0 * cell, 2.0 * cell, "none", INK);
    }
    for ([x, y], w) in DOWNSAMPLE_TAPS {
        let colour = if w == 0.125 {
            ACCENT
        } else if w == 0.0625 {
            BLUE
        } else {
            MUTED
        };
        svg.circle(taps(x, y), 3.0 + 40.0 * w, colour);
    }
    svg.text(Vec2::new(40.0, 300.0), "13 taps, each where four texels meet:", 11.0, "start", INK);
    svg.text(Vec2::new(40.0, 316.0), "1/8 (orange), 1/16 (blue), 1/32 (grey)", 11.0, "start", INK);
    svg.text(Vec2::new(360.0, 300.0), "what each texel weighs, in 128ths", 11.0, "start", INK);
    svg.text(Vec2::new(360.0, 316.0), "(the outlined 2 × 2 block is the output texel)", 11.0, "start", INK);
    svg.text(
        Vec2::new(20.0, 28.0),
        "Halvings 2 to 6 of the bloom chain: 13 taps read 6 × 6 texels of a level for one texel of the next",
        11.0,
        "start",
        INK,
    );
    svg.finish()
}

/// Chapter 08: Lambert's cosine law. The same beam of parallel light on a
/// surface it meets head-on, and on one it meets at 60° from the normal,
/// where it covers 1 / cos 60° = twice the width.
pub fn lambert_cosine() -> String {
    let mut svg = Svg::new(640.0, 300.0);
    let beam = 70.0;
    for (left, degrees) in [(40.0f32, 0.0f32), (340.0, 60.0)] {
        let theta = degrees.to_radians();
        let ground = 230.0;
        let hit = Vec2::new(left + 140.0, ground);
        svg.line(Vec2::new(left, ground), Vec2::new(left + 280.0, ground), INK, 2.0);
        // l, towards the light, leans from the normal (up) by θ; `across` is
        // square to the beam, and the beam's far end is cut square to it.
        let towards_light = Vec2::new(-theta.sin(), -theta.cos());
        let across = Vec2::new(theta.cos(), -theta.sin());
        let far = hit + towards_light * 130.0;
        let (far_a, far_b) = (far - across * beam / 2.0, far + across * beam / 2.0);
        let to_ground = |p: Vec2| p - towards_light * (ground - p.y) / theta.cos();
        let (a, b) = (to_ground(far_a), to_ground(far_b));
        svg.polygon(&[a, b, far_b, far_a], "#f6e7d3", "none");
        for i in 0..5 {
            let start = far_a + (far_b - far_a) * (i as f32 + 0.5) / 5.0;
            svg.arrow(start, to_ground(start) + towards_light * 2.0, ACCENT);
        }
        // The beam's width, measured square to it, beyond its far end.
        let (m, n) = (far_a + towards_light * 10.0, far_b + towards_light * 10.0);
        svg.line(m, n, INK, 1.0);
        svg.text(m - across * 6.0 + Vec2::new(0.0, 4.0), "w", 12.0, "end", INK);
        // And the width it lands on.
        svg.line(a + Vec2::Y * 8.0, b + Vec2::Y * 8.0, BLUE, 3.0);
        let covered = if degrees == 0.0 {
            "w".to_string()
        } else {
            format!("w / cos {degrees:.0}° = {:.0} w", 1.0 / theta.cos())
        };
        svg.text(hit + Vec2::new(0.0, 28.0), &covered, 12.0, "middle", BLUE);
        svg.dashed(hit, hit + Vec2::new(0.0, -185.0), MUTED);
        svg.text(hit + Vec2::new(6.0, -176.0), "n", 12.0, "start", MUTED);
        if degrees > 0.0 {
            let arc: Vec<Vec2> = (0..=16)
                .map(|i| {
                    let phi = theta * i as f32 / 16.0;
                    hit + Vec2::new(-phi.sin(), -phi.cos()) * 44.0
                })
                .collect();
            svg.polyline(&arc, INK, 1.2);
            let middle = theta / 2.0;
            svg.text(
                hit + Vec2::new(-middle.sin(), -middle.cos()) * 56.0 + Vec2::new(0.0, 4.0),
                "θ",
                12.0,
                "middle",
                INK,
            );
        }
        svg.text(Vec2::new(left + 140.0, 24.0), &format!("θ = {degrees:.0}°"), 12.0, "middle", INK);
    }
    svg.text(
        Vec2::new(320.0, 290.0),
        "The same light over more area: each square metre gets cos θ as much.",
        11.0,
        "middle",
        INK,
    );
    svg.finish()
}

/// Chapter 08: FXAA on a straight edge four pixels a step. The pixels are
/// drawn as one sample at each centre sees them; for each complete step
/// of the staircase, the blend FXAA gives each pixel beside it, ½ − d / L
/// at the end where the staircase turns towards that pixel's side, worked
/// out here from the staircase alone, and under it the share of the other
/// surface the edge really leaves in the pixel, integrated from the edge's
/// equation.
pub fn fxaa() -> String {
    let (cell, columns, rows) = (60.0, 12usize, 4usize);
    let origin = Vec2::new(40.0, 70.0);
    // The edge, in pixels with y down: the blue surface lies below it.
    let edge = |x: f32| 3.25 - x / 4.0;
    let blue_at_centre = |column: usize, row: usize| row as f32 + 0.5 > edge(column as f32 + 0.5);
    // The share of pixel (column, row) below the edge, over 256 strips.
    let blue_share = |column: usize, row: usize| {
        (0..256)
            .map(|k| (row as f32 + 1.0 - edge(column as f32 + (k as f32 + 0.5) / 256.0)).clamp(0.0, 1.0))
            .sum::<f32>()
            / 256.0
    };
    let at = |x: f32, y: f32| origin + Vec2::new(x, y) * cell;
    let mut svg = Svg::new(40.0 + cell * columns as f32 + 40.0, origin.y + cell * rows as f32 + 60.0);
    for row in 0..rows {
        for column in 0..columns {
            let fill = if blue_at_centre(column, row) { "#b9cde6" } else { PAPER };
            let p = at(column as f32, row as f32);
            svg.rect(p.x, p.y, cell, cell, fill, MUTED);
        }
    }
    // Each step: a run of columns where the row above is white and the row
    // below blue. The pixel beside the end where the staircase turns
    // towards its side holds up to half of the other surface.
    let mut walked = false;
    for upper in 0..rows - 1 {
        let on_step = |column: usize| !blue_at_centre(column, upper) && blue_at_centre(column, upper + 1);
        let mut first = 0;
        while first < columns {
            if !on_step(first) {
                first += 1;
                continue;
            }
            let mut last = first;
            while last + 1 < columns && on_step(last + 1) {
                last += 1;
            }
            // Only steps whose both ends lie inside the picture.
            if first > 0 && last + 1 < columns {
                let length = (last - first + 1) as f32;
                // Beyond the left end the lower row turns white; beyond the
                // right end the upper row turns blue.
                let left_turns_lower = !blue_at_centre(first - 1, upper + 1);
                let right_turns_upper = blue_at_centre(last + 1, upper);
                for column in first..=last {
                    let to_left = column as f32 + 0.5 - first as f32;
                    let to_right = last as f32 + 1.0 - (column as f32 + 0.5);
                    let (distance, lower_blends) =
                        if to_left < to_right { (to_left, left_turns_lower) } else { (to_right, !right_turns_upper) };
                    let blend = (0.5 - distance / length).max(0.0);
                    for (row, blends, exact) in [
                        (upper, !lower_blends, blue_share(column, upper)),
                        (upper + 1, lower_blends, 1.0 - blue_share(column, upper + 1)),
                    ] {
                        let shown = if blends { blend } else { 0.0 };
                        let centre = at(column as f32 + 0.5, row as f32 + 0.5);
                        svg.text(centre + Vec2::new(0.0, -2.0), &format!("{shown:.2}"), 12.0, "middle", INK);
                        svg.text(centre + Vec2::new(0.0, 14.0), &format!("{exact:.2}"), 10.0, "middle", MUTED);
                    }
                }
                // The walk, drawn once: from the middle of the step both
                // ways, half a pixel across, to its ends.
                if !walked {
                    let y = upper as f32 + 1.0;
                    let start = (first as f32 + last as f32 + 1.0) / 2.0 - 0.5;
                    svg.arrow(at(start, y), at(first as f32, y), ACCENT);
                    svg.arrow(at(start, y), at(last as f32 + 1.0, y), ACCENT);
                    svg.circle(at(start, y), 3.5, ACCENT);
                    walked = true;
                }
            }
            first = last + 1;
        }
    }
    svg.line(at(0.0, edge(0.0)), at(columns as f32, edge(columns as f32)), BLUE, 2.0);
    let below = origin.y + cell * rows as f32 + 26.0;
    for (y, line) in [
        (
            28.0,
            "A straight edge (blue line) drawn with one sample a pixel: steps of four pixels. From a pixel on a step,",
        ),
        (46.0, "FXAA walks both ways along it (red) to the step's ends, and blends in ½ − d/L of the pixel across."),
        (
            below,
            "Large: the blend FXAA works out from the staircase alone. Small: the share of the other side the edge",
        ),
        (below + 18.0, "really leaves in the pixel, integrated from its equation. For a straight edge they agree."),
    ] {
        svg.text(Vec2::new(origin.x, y), line, 11.0, "start", INK);
    }
    svg.finish()
}

/// Chapter 08: the microfacet model's three terms against angle, from
/// `lighting::pbr`: GGX's D for three roughnesses (log scale), Smith's G₂
/// with light and eye at the same angle, and Schlick's F for glass's
/// 0.04 and for a metal's 0.9.
pub fn microfacet_terms() -> String {
    use lighting::pbr::{fresnel_schlick, ggx_alpha, ggx_distribution, smith_visibility};
    let mut svg = Svg::new(660.0, 300.0);
    let degrees = |x: f32| x.to_radians().cos();
    let left = Axes { origin: Vec2::new(60.0, 40.0), size: Vec2::new(250.0, 190.0), x: (0.0, 90.0), y: (-2.0, 3.0) };
    left.draw(&mut svg, &[0.0, 30.0, 60.0, 90.0], &[], "angle between n and h (°)", "D (log scale)");
    for (power, label) in [(-2.0, "0.01"), (0.0, "1"), (2.0, "100")] {
        let p = left.at(0.0, power);
        svg.line(p, p - Vec2::new(5.0, 0.0), INK, 1.0);
        svg.text(p + Vec2::new(-8.0, 4.0), label, 11.0, "end", INK);
    }
    let right = Axes { origin: Vec2::new(390.0, 40.0), size: Vec2::new(250.0, 190.0), x: (0.0, 90.0), y: (0.0, 1.0) };
    right.draw(&mut svg, &[0.0, 30.0, 60.0, 90.0], &[0.0, 0.5, 1.0], "angle of light and eye to n (°)", "");
    for (roughness, colour) in [(0.2, ACCENT), (0.5, BLUE), (0.8, "#8a6fb0")] {
        let alpha = ggx_alpha(roughness);
        left.curve(&mut svg, |x| ggx_distribution(degrees(x), alpha).max(1e-3).log10(), colour, 2.0);
        // G₂ = V × 4 n·l n·v, with l and v at the same angle.
        right.curve(
            &mut svg,
            |x| {
                let c = degrees(x).max(1e-3);
                smith_visibility(c, c, alpha) * 4.0 * c * c
            },
            colour,
            2.0,
        );
        let key = left.at(58.0, 2.8 - 0.35 * (roughness - 0.2) / 0.3);
        svg.text(key, &format!("roughness {roughness}"), 11.0, "start", colour);
    }
    for (f0, colour) in [(0.04, INK), (0.9, MUTED)] {
        right.curve(&mut svg, |x| fresnel_schlick(common::glam::Vec3::splat(f0), degrees(x)).x, colour, 1.4);
    }
    svg.text(right.at(4.0, 0.08) + Vec2::new(0.0, -4.0), "F, f0 = 0.04", 11.0, "start", INK);
    svg.text(right.at(4.0, 0.8), "F, f0 = 0.9", 11.0, "start", MUTED);
    svg.text(right.at(4.0, 0.66), "G₂: coloured, by roughness", 11.0, "start", INK);
    svg.text(Vec2::new(185.0, 292.0), "D: where the facets face", 12.0, "middle", INK);
    svg.text(Vec2::new(515.0, 292.0), "G₂: facets seen and lit; F: Fresnel", 12.0, "middle", INK);
    svg.finish()
}

/// Chapter 08: what a white surface sends back of a white sky that lights
/// it evenly (the white furnace), against the view's angle: Blinn-Phong's
/// albedo-plus-highlight with the city's glass settings, and Cook-Torrance
/// for a white non-metal and a white metal (`lighting::pbr`), each
/// integrated over the hemisphere here.
pub fn white_furnace() -> String {
    use common::glam::Vec3;
    use lighting::pbr::{Physical, cook_torrance};
    use std::f32::consts::PI;
    // ∫ g(l) cos / π dω_l over the hemisphere, on a grid of 96 × 192.
    let reflected = |n_dot_v: f32, g: &dyn Fn(Vec3, Vec3) -> f32| {
        let v = Vec3::new((1.0 - n_dot_v * n_dot_v).sqrt(), 0.0, n_dot_v);
        let (rings, spokes) = (96, 192);
        let mut sum = 0.0;
        for i in 0..rings {
            let theta = (i as f32 + 0.5) / rings as f32 * PI / 2.0;
            for j in 0..spokes {
                let phi = (j as f32 + 0.5) / spokes as f32 * 2.0 * PI;
                let l = Vec3::new(theta.sin() * phi.cos(), theta.sin() * phi.sin(), theta.cos());
                sum += g(v, l) * l.z / PI * theta.sin() * (PI / 2.0 / rings as f32) * (2.0 * PI / spokes as f32);
            }
        }
        sum
    };
    let blinn_phong = |v: Vec3, l: Vec3| {
        let (albedo, specular, s) = (1.0, 1.0, 16.0);
        let h = (v + l).normalize();
        albedo + specular * (s + 8.0) / 8.0 * h.z.max(0.0).powf(s)
    };
    let white = |metallic| Physical { base_colour: Vec3::ONE, metallic, roughness: 0.5 };
    let mut svg = Svg::new(640.0, 300.0);
    let axes = Axes { origin: Vec2::new(70.0, 40.0), size: Vec2::new(520.0, 190.0), x: (0.05, 1.0), y: (0.0, 2.5) };
    axes.draw(
        &mut svg,
        &[0.25, 0.5, 0.75, 1.0],
        &[0.0, 0.5, 1.0, 1.5, 2.0, 2.5],
        "n · v",
        "light sent back / light arriving",
    );
    svg.dashed(axes.at(0.05, 1.0), axes.at(1.0, 1.0), "#c9c2b6");
    axes.curve(&mut svg, |x| reflected(x, &blinn_phong), MUTED, 2.0);
    axes.curve(&mut svg, |x| reflected(x, &|v, l| cook_torrance(Vec3::Z, v, l, white(0.0)).x), ACCENT, 2.4);
    axes.curve(&mut svg, |x| reflected(x, &|v, l| cook_torrance(Vec3::Z, v, l, white(1.0)).x), BLUE, 2.0);
    svg.text(axes.at(0.45, 2.05), "Blinn-Phong, albedo 1 + highlight 1, s = 16", 11.0, "middle", MUTED);
    svg.text(axes.at(0.7, 1.08), "1: all the light that arrives", 10.0, "middle", INK);
    svg.text(axes.at(0.55, 0.72), "Cook-Torrance, white non-metal, roughness 0.5", 11.0, "start", ACCENT);
    svg.text(axes.at(0.55, 0.56), "Cook-Torrance, white metal, roughness 0.5", 11.0, "start", BLUE);
    svg.finish()
}

/// Chapter 08: the lobe a prefiltered sky assumes against the one a
/// surface has. Seen 70° from its normal, a rough surface's specular lobe
/// (D V n·l, `lighting::pbr`, in the plane of n and v) is cut off at the
/// horizon and bent up towards n, where its facets shadow one another (V);
/// the prefiltered cube blurs as though the
/// surface faced the mirror direction r and were seen from it (D n·l with
/// n = v = r), a lobe the same all round r. Each is scaled to its peak.
pub fn prefiltered_lobe() -> String {
    use common::glam::Vec3;
    use lighting::pbr::{ggx_alpha, ggx_distribution, smith_visibility};
    let mut svg = Svg::new(560.0, 300.0);
    let origin = Vec2::new(280.0, 250.0);
    let scale = 190.0;
    // Directions in the plane of n (up) and v: angle from n, positive towards +x.
    let dir = |angle: f32| Vec3::new(angle.to_radians().sin(), angle.to_radians().cos(), 0.0);
    let screen = |d: Vec3, length: f32| origin + Vec2::new(d.x, -d.y) * length;
    let (view_angle, roughness) = (-70.0f32, 0.6);
    let (n, v) = (Vec3::Y, dir(view_angle));
    let r = dir(-view_angle);
    let alpha = ggx_alpha(roughness);
    let lobe = |weight: &dyn Fn(Vec3) -> f32, from: f32, to: f32| {
        let angles: Vec<f32> = (0..=360).map(|i| from + (to - from) * i as f32 / 360.0).collect();
        let values: Vec<f32> = angles.iter().map(|&a| weight(dir(a)).max(0.0)).collect();
        let peak = values.iter().cloned().fold(0.0, f32::max);
        angles.iter().zip(values).map(|(&a, w)| screen(dir(a), scale * w / peak)).collect::<Vec<Vec2>>()
    };
    let real = |l: Vec3| {
        let h = (l + v).normalize();
        ggx_distribution(n.dot(h), alpha) * smith_visibility(n.dot(v), n.dot(l).max(0.0), alpha) * n.dot(l).max(0.0)
    };
    let assumed = |l: Vec3| ggx_distribution(r.dot((l + r).normalize()), alpha) * r.dot(l).max(0.0);
    svg.line(origin - Vec2::new(250.0, 0.0), origin + Vec2::new(250.0, 0.0), INK, 2.0);
    svg.polyline(&lobe(&assumed, -view_angle - 90.0, -view_angle + 90.0), BLUE, 2.0);
    svg.polyline(&lobe(&real, -90.0, 90.0), ACCENT, 2.4);
    svg.arrow(origin, screen(n, 120.0), INK);
    svg.arrow(screen(v, 150.0), origin, MUTED);
    svg.dashed(origin, screen(r, 225.0), BLUE);
    svg.text(screen(n, 128.0), "n", 13.0, "middle", INK);
    svg.text(screen(v, 162.0), "eye (v)", 12.0, "middle", MUTED);
    svg.text(screen(r, 238.0), "r", 13.0, "middle", BLUE);
    svg.text(
        Vec2::new(20.0, 26.0),
        "the lobe the surface has: D V n·l, cut off at the horizon, bent up by shadowing (V)",
        12.0,
        "start",
        ACCENT,
    );
    svg.text(
        Vec2::new(20.0, 44.0),
        "the lobe the cube assumes: D n·l with n = v = r, round about r, dipping below the surface",
        12.0,
        "start",
        BLUE,
    );
    let caption = format!("roughness {roughness}, seen {}° from the normal; each lobe scaled to its peak", -view_angle);
    svg.text(origin + Vec2::new(0.0, 30.0), &caption, 11.0, "middle", MUTED);
    svg.finish()
}
