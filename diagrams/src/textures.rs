//! Chapter 09's figures: the tangent a triangle's texture coordinates
//! give, the sampling lab's texel footprint against distance and as
//! rectangles, the sRGB curve and its steps, the address modes, flat
//! interpolation, the brick's normal map and the green channel's two
//! conventions, from the chapter's tangents, lab scene, transfer
//! function, built-in textures and shader logic.

use common::glam::{Vec2, Vec3};
use common::wgpu;

use crate::kit::{ACCENT, Axes, BLUE, INK, MUTED, Svg};

/// Chapter 09: texture coordinates and the tangent they give, for one
/// triangle, from `textures::tangents::triangle_tangents`.
pub fn tangent_from_uvs() -> String {
    use textures::tangents::triangle_tangents;
    let mut svg = Svg::new(640.0, 300.0);
    // Left: the texture, u to the right and v down, with the triangle's corners.
    let (origin, size) = (Vec2::new(40.0, 50.0), 200.0);
    svg.rect(origin.x, origin.y, size, size, "#f1ebe2", INK);
    let uv = [Vec2::new(0.15, 0.85), Vec2::new(0.85, 0.7), Vec2::new(0.35, 0.15)];
    let at_uv = |t: Vec2| origin + t * size;
    svg.polygon(&uv.map(at_uv), "#f3d9bf", ACCENT);
    for (k, name) in ["p₀", "p₁", "p₂"].iter().enumerate() {
        svg.circle(at_uv(uv[k]), 3.5, INK);
        svg.text(at_uv(uv[k]) + Vec2::new(-14.0, if k == 2 { -6.0 } else { 16.0 }), name, 11.0, "middle", INK);
    }
    svg.arrow(origin + Vec2::new(0.0, size + 16.0), origin + Vec2::new(60.0, size + 16.0), INK);
    svg.text(origin + Vec2::new(66.0, size + 20.0), "u", 12.0, "start", INK);
    svg.arrow(origin + Vec2::new(-16.0, 0.0), origin + Vec2::new(-16.0, 60.0), INK);
    svg.text(origin + Vec2::new(-20.0, 76.0), "v", 12.0, "middle", INK);
    svg.text(Vec2::new(40.0, 30.0), "in the texture: (Δu₁, Δv₁) and (Δu₂, Δv₂)", 11.0, "start", INK);
    // Right: the triangle on a surface in 3D, drawn obliquely (x right,
    // y up, z towards the viewer and down-left).
    let p = [Vec3::new(0.0, 0.0, 0.0), Vec3::new(1.6, 0.5, -0.3), Vec3::new(0.5, 1.5, 0.4)];
    let (t, b) = triangle_tangents(p, uv).expect("the triangle covers texture");
    let project = |v: Vec3| Vec2::new(400.0, 230.0) + Vec2::new(v.x - 0.45 * v.z, -v.y + 0.3 * v.z) * 110.0;
    svg.polygon(&p.map(project), "#f3d9bf", ACCENT);
    for (k, name) in ["p₀", "p₁", "p₂"].iter().enumerate() {
        svg.circle(project(p[k]), 3.5, INK);
        svg.text(project(p[k]) + Vec2::new(-16.0, 14.0), name, 11.0, "middle", INK);
    }
    let scale = 0.45;
    svg.arrow(project(p[0]), project(p[0] + t * scale), ACCENT);
    svg.text(project(p[0] + t * scale) + Vec2::new(6.0, 4.0), "T = ∂P/∂u", 11.0, "start", ACCENT);
    svg.arrow(project(p[0]), project(p[0] - b * scale), BLUE);
    svg.text(project(p[0] - b * scale) + Vec2::new(6.0, 0.0), "−B: up the image", 11.0, "start", BLUE);
    svg.text(Vec2::new(330.0, 30.0), "on the surface: e₁ = Δu₁ T + Δv₁ B, e₂ = Δu₂ T + Δv₂ B", 11.0, "start", INK);
    svg.finish()
}

/// A pixel's footprint on the sampling lab's floor, in texels, as the
/// lab's camera sees it in a 1280 × 720 picture (`textures::CameraPreset::Lab`,
/// `lab_floor`): what both footprint figures plot.
struct LabFootprint {
    /// Texels of the lab's checker per metre of its floor.
    texels_per_metre: f32,
    /// The camera's height above the floor, metres.
    height: f32,
    /// The angle one pixel spans, radians, the same both ways (square
    /// pixels): 2 tan(fov_y / 2) / 720, exact for a ray through the
    /// picture's centre. The lab's camera looks 3.2° down, so the floor
    /// 20 m out is 1.6° from that ray, and 10 m out 6.4°.
    per_pixel: f32,
}

impl LabFootprint {
    fn new() -> Self {
        let (_, camera) = textures::CameraPreset::Lab.place(16.0 / 9.0);
        // The floor's repeats times the texture's width, over the floor's width.
        let floor = textures::scenes::lab_floor();
        let (low, high) = floor.bounds();
        let repeats = floor.vertices.iter().map(|v| v.uv[0]).fold(0.0f32, f32::max);
        Self {
            texels_per_metre: textures::materials::checkerboard().width() as f32 * repeats / (high.x - low.x),
            height: camera.position.y,
            per_pixel: 2.0 * (camera.fov_y / 2.0).tan() / 720.0,
        }
    }

    /// Texels along the view at ground distance `d`: a pixel row spans
    /// slant range × Δθ metres square to the ray, which meets the floor at
    /// sin α = h / slant range, so (d² + h²) / h × Δθ metres of floor.
    fn along(&self, d: f32) -> f32 {
        self.texels_per_metre * (d * d + self.height * self.height) / self.height * self.per_pixel
    }

    /// Texels across the view at ground distance `d`: a pixel column covers
    /// slant range × Δθ metres, √(d² + h²) × Δθ.
    fn across(&self, d: f32) -> f32 {
        self.texels_per_metre * (d * d + self.height * self.height).sqrt() * self.per_pixel
    }
}

/// The sampling lab's floor as its camera sees it: texels per pixel, along
/// the view and across it, against distance. The mip level a sampler picks
/// is the log₂ of that (of the larger, unless it filters anisotropically).
/// From the lab's camera and floor (`textures::CameraPreset::Lab`, `lab_floor`).
pub fn texel_footprint() -> String {
    let footprint = LabFootprint::new();
    let mut svg = Svg::new(640.0, 330.0);
    let axes = Axes { origin: Vec2::new(70.0, 40.0), size: Vec2::new(520.0, 220.0), x: (0.0, 100.0), y: (-3.0, 9.0) };
    axes.draw(
        &mut svg,
        &[0.0, 25.0, 50.0, 75.0, 100.0],
        &[],
        "distance along the floor (m)",
        "texels per pixel (log₂: the mip level)",
    );
    for level in (-3..=9).step_by(3) {
        let p = axes.at(0.0, level as f32);
        svg.line(p, p - Vec2::new(5.0, 0.0), INK, 1.0);
        let label = if level >= 0 { format!("{}", 1 << level) } else { format!("1/{}", 1 << -level) };
        svg.text(p + Vec2::new(-8.0, 4.0), &label, 11.0, "end", INK);
    }
    svg.dashed(axes.at(0.0, 0.0), axes.at(100.0, 0.0), MUTED);
    svg.text(
        axes.at(60.0, 0.0) + Vec2::new(0.0, 14.0),
        "one texel per pixel: finer detail than this aliases",
        10.0,
        "start",
        MUTED,
    );
    axes.curve(&mut svg, |d| footprint.along(d.max(0.1)).log2(), ACCENT, 2.2);
    axes.curve(&mut svg, |d| footprint.across(d.max(0.1)).log2(), BLUE, 2.2);
    svg.text(axes.at(12.0, footprint.along(25.0).log2() + 1.0), "along the view", 11.0, "start", ACCENT);
    svg.text(axes.at(70.0, footprint.across(70.0).log2()) + Vec2::new(0.0, 16.0), "across it", 11.0, "start", BLUE);
    svg.finish()
}

/// A pixel's footprint on the lab's floor, in texels, at three distances:
/// trilinear filtering blurs it to a square as big as its long side;
/// anisotropic filtering takes several samples along the long side.
pub fn footprints() -> String {
    let footprint = LabFootprint::new();
    let mut svg = Svg::new(640.0, 285.0);
    svg.text(
        Vec2::new(20.0, 24.0),
        "one pixel's footprint on the floor, in texels (the grid is one texel)",
        11.0,
        "start",
        INK,
    );
    for (i, d) in [5.0f32, 10.0, 20.0].iter().enumerate() {
        let (along, across) = (footprint.along(*d), footprint.across(*d));
        let centre = Vec2::new(110.0 + 200.0 * i as f32, 140.0);
        let cell = 22.0;
        for k in -3..=3 {
            let o = k as f32 * cell;
            svg.line(centre + Vec2::new(o, -80.0), centre + Vec2::new(o, 80.0), "#e2dbd0", 1.0);
            svg.line(centre + Vec2::new(-80.0, o), centre + Vec2::new(80.0, o), "#e2dbd0", 1.0);
        }
        let (w, h) = (across * cell, along * cell);
        let side = w.max(h).min(160.0);
        svg.rect(centre.x - side / 2.0, centre.y - side / 2.0, side, side, "none", MUTED);
        svg.rect(centre.x - w / 2.0, centre.y - h.min(160.0) / 2.0, w, h.min(160.0), "#f3d9bf", ACCENT);
        svg.text(centre + Vec2::new(0.0, 100.0), &format!("{d} m: {across:.2} × {along:.2}"), 11.0, "middle", INK);
    }
    svg.text(
        Vec2::new(20.0, 272.0),
        "filled: the footprint (across × along the view); grey: the square a trilinear sampler averages over",
        10.0,
        "start",
        MUTED,
    );
    svg.finish()
}

/// The sRGB curve (IEC 61966-2-1), and why averaging must happen in light:
/// black and white texels average to 188, not 128
/// (`textures::mipmaps::box_filter_srgb`).
pub fn srgb_curve() -> String {
    use common::image::{Rgba, RgbaImage};
    let encode = textures::materials::linear_to_srgb;
    let mut svg = Svg::new(640.0, 320.0);
    let axes = Axes { origin: Vec2::new(70.0, 40.0), size: Vec2::new(300.0, 220.0), x: (0.0, 1.0), y: (0.0, 1.0) };
    axes.draw(&mut svg, &[0.0, 0.5, 1.0], &[0.0, 0.5, 1.0], "light (linear)", "stored value (sRGB, 0..1)");
    svg.dashed(axes.at(0.0, 0.0), axes.at(1.0, 1.0), MUTED);
    axes.curve(&mut svg, encode, ACCENT, 2.4);
    let black_white = RgbaImage::from_fn(2, 2, |x, _| if x == 0 { Rgba([0, 0, 0, 255]) } else { Rgba([255; 4]) });
    let mean = textures::mipmaps::box_filter_srgb(&black_white).get_pixel(0, 0)[0];
    let stored = mean as f32 / 255.0;
    svg.dashed(axes.at(0.5, 0.0), axes.at(0.5, stored), BLUE);
    svg.dashed(axes.at(0.0, stored), axes.at(0.5, stored), BLUE);
    svg.circle(axes.at(0.5, stored), 4.0, BLUE);
    svg.text(Vec2::new(400.0, 80.0), "Half as much light as white is", 11.0, "start", INK);
    svg.text(Vec2::new(400.0, 96.0), &format!("stored as {mean} of 255, not 128:"), 11.0, "start", INK);
    svg.text(Vec2::new(400.0, 112.0), "the curve spends more of its 256", 11.0, "start", INK);
    svg.text(Vec2::new(400.0, 128.0), "steps on dark values, where eyes", 11.0, "start", INK);
    svg.text(Vec2::new(400.0, 144.0), "tell them apart.", 11.0, "start", INK);
    svg.text(Vec2::new(400.0, 176.0), "So a mip level that averages", 11.0, "start", BLUE);
    svg.text(Vec2::new(400.0, 192.0), &format!("black and white texels must store {mean},"), 11.0, "start", BLUE);
    svg.text(Vec2::new(400.0, 208.0), "and one that averages the stored", 11.0, "start", BLUE);
    svg.text(Vec2::new(400.0, 224.0), "numbers (128) comes out too dark.", 11.0, "start", BLUE);
    svg.finish()
}

/// Sixteen grey steps stored two ways: evenly spaced in light, and evenly
/// spaced in stored sRGB value, with where each set of steps falls on the
/// scale of light below. From `textures::materials::{srgb_to_linear,
/// linear_to_srgb}`, the transfer function the chapter's code uses.
pub fn srgb_steps() -> String {
    use textures::materials::{linear_to_srgb, srgb_to_linear};
    const STEPS: usize = 16;
    let byte = |v: f32| (v.clamp(0.0, 1.0) * 255.0).round() as u8;
    let grey = |b: u8| format!("#{b:02x}{b:02x}{b:02x}");
    let mut svg = Svg::new(640.0, 370.0);
    let (left, width) = (40.0, 560.0);
    let cell = width / STEPS as f32;
    // Each bar: the light of each step, and the byte stored for it.
    let even_light: Vec<(f32, u8)> = (0..STEPS)
        .map(|k| {
            let light = k as f32 / (STEPS - 1) as f32;
            (light, byte(linear_to_srgb(light)))
        })
        .collect();
    let even_stored: Vec<(f32, u8)> = (0..STEPS)
        .map(|k| {
            let stored = byte(k as f32 / (STEPS - 1) as f32);
            (srgb_to_linear(stored as f32 / 255.0), stored)
        })
        .collect();
    let bars = [
        (
            30.0,
            "evenly spaced in light: 0, 1/15, 2/15 … 1; under each, the byte sRGB stores for it",
            &even_light,
            ACCENT,
        ),
        (
            140.0,
            "evenly spaced in stored value: bytes 0, 17, 34 … 255; under each, the light it means",
            &even_stored,
            BLUE,
        ),
    ];
    for (top, caption, steps, colour) in bars {
        svg.text(Vec2::new(left, top), caption, 11.0, "start", colour);
        for (k, (light, stored)) in steps.iter().enumerate() {
            let x = left + cell * k as f32;
            svg.rect(x, top + 8.0, cell, 44.0, &grey(*stored), "none");
            let label = if colour == BLUE { format!("{light:.3}") } else { format!("{stored}") };
            svg.text(Vec2::new(x + cell / 2.0, top + 66.0), &label, 9.0, "middle", INK);
        }
    }
    // The scale of light, with both bars' steps marked on it.
    let axis_y = 272.0;
    let at = |light: f32| Vec2::new(left + light * width, axis_y);
    svg.line(at(0.0), at(1.0), INK, 1.2);
    for light in [0.0, 0.25, 0.5, 0.75, 1.0] {
        svg.line(at(light), at(light) + Vec2::new(0.0, 4.0), INK, 1.0);
        svg.text(at(light) + Vec2::new(0.0, 16.0), &crate::kit::trim(light), 10.0, "middle", INK);
    }
    svg.text(at(0.5) + Vec2::new(0.0, 32.0), "light (linear): where each bar's steps fall", 11.0, "middle", INK);
    for (light, _) in &even_light {
        svg.line(at(*light) - Vec2::new(0.0, 22.0), at(*light) - Vec2::new(0.0, 4.0), ACCENT, 2.0);
    }
    for (light, _) in &even_stored {
        svg.line(at(*light) - Vec2::new(0.0, 44.0), at(*light) - Vec2::new(0.0, 26.0), BLUE, 2.0);
    }
    let dark = even_stored.iter().filter(|(light, _)| *light < 0.25).count();
    svg.text(
        Vec2::new(left, axis_y + 54.0),
        &format!("blue: {dark} of the {STEPS} steps even in stored value lie in the darkest quarter of the light"),
        10.0,
        "start",
        BLUE,
    );
    let jump = even_light[1].1;
    svg.text(
        Vec2::new(left, axis_y + 68.0),
        &format!("orange: of the steps even in light, the first one up from black is already stored as byte {jump}"),
        10.0,
        "start",
        ACCENT,
    );
    svg.finish()
}

/// A picture of 8 × 8 texels, asymmetric so that mirroring shows: an "F"
/// in white on a warm-to-cool gradient across, darker every other row.
fn wrap_texture() -> common::image::RgbaImage {
    const GLYPH: [&str; 8] =
        ["........", ".FFFFF..", ".F......", ".FFFF...", ".F......", ".F......", ".F......", "........"];
    common::image::RgbaImage::from_fn(8, 8, |x, y| {
        if GLYPH[y as usize].as_bytes()[x as usize] == b'F' {
            return common::image::Rgba([250, 250, 245, 255]);
        }
        let t = x as f32 / 7.0;
        let shade = if y % 2 == 0 { 1.0 } else { 0.8 };
        let mix = |a: f32, b: f32| ((a + (b - a) * t) * shade) as u8;
        common::image::Rgba([mix(222.0, 47.0), mix(120.0, 109.0), mix(60.0, 179.0), 255])
    })
}

/// The four address modes, each as the picture looks for u from −1 to 2
/// (three repeats across) with v from 0 to 1. Each texel index i is
/// wrapped as the Vulkan specification's "Wrapping Operation" writes it,
/// with nearest filtering; clamp-to-border reads the border colour, here
/// wgpu's `SamplerBorderColor::OpaqueBlack`, outside the picture.
pub fn wrap_modes() -> String {
    let texture = wrap_texture();
    let size = texture.width() as i32;
    let border = common::image::Rgba([0, 0, 0, 255]);
    let mirror = |n: i32| if n >= 0 { n } else { -(1 + n) };
    // The texel index i wraps to, or None for the border colour.
    let wrap = |mode: wgpu::AddressMode, i: i32| match mode {
        wgpu::AddressMode::Repeat => Some(i.rem_euclid(size)),
        wgpu::AddressMode::MirrorRepeat => Some((size - 1) - mirror(i.rem_euclid(2 * size) - size)),
        wgpu::AddressMode::ClampToEdge => Some(i.clamp(0, size - 1)),
        wgpu::AddressMode::ClampToBorder => Some(i.clamp(-1, size)).filter(|i| (0..size).contains(i)),
    };
    let modes = [
        ("repeat", "AddressMode::Repeat", wgpu::AddressMode::Repeat),
        ("mirror-repeat", "AddressMode::MirrorRepeat", wgpu::AddressMode::MirrorRepeat),
        ("clamp-to-edge", "AddressMode::ClampToEdge (the default)", wgpu::AddressMode::ClampToEdge),
        ("clamp-to-border", "AddressMode::ClampToBorder (native only, a feature)", wgpu::AddressMode::ClampToBorder),
    ];
    let mut svg = Svg::new(640.0, 374.0);
    let tile = 88.0;
    for (n, (name, wgpu_name, mode)) in modes.into_iter().enumerate() {
        let picture =
            common::image::RgbaImage::from_fn(3 * size as u32, size as u32, |x, y| match wrap(mode, x as i32 - size) {
                Some(i) => *texture.get_pixel(i as u32, y),
                None => border,
            });
        let origin = Vec2::new(24.0 + 328.0 * (n % 2) as f32, 34.0 + 172.0 * (n / 2) as f32);
        svg.text(origin, name, 12.0, "start", INK);
        svg.text(origin + Vec2::new(0.0, 14.0), wgpu_name, 10.0, "start", MUTED);
        let top = origin.y + 24.0;
        svg.image(origin.x, top, 3.0 * tile, tile, &picture);
        // The picture itself, u from 0 to 1.
        let (a, b) = (Vec2::new(origin.x + tile, top), Vec2::new(origin.x + 2.0 * tile, top + tile));
        for (p, q) in
            [(a, Vec2::new(b.x, a.y)), (Vec2::new(b.x, a.y), b), (b, Vec2::new(a.x, b.y)), (Vec2::new(a.x, b.y), a)]
        {
            svg.line(p, q, INK, 2.5);
        }
        for (k, u) in ["−1", "0", "1", "2"].iter().enumerate() {
            let x = origin.x + tile * k as f32;
            svg.line(Vec2::new(x, top + tile), Vec2::new(x, top + tile + 5.0), INK, 1.0);
            svg.text(Vec2::new(x, top + tile + 17.0), &format!("u = {u}"), 10.0, "middle", INK);
        }
    }
    svg.text(
        Vec2::new(24.0, 364.0),
        "outlined: the picture, u from 0 to 1; left and right of it, what the address mode makes of u outside",
        10.0,
        "start",
        MUTED,
    );
    svg.finish()
}

/// Chapter 01's triangle drawn twice: its colours interpolated (in linear
/// light, as the GPU does before an sRGB target encodes them) and with
/// `@interpolate(flat)`, where every pixel takes the first vertex's colour.
pub fn flat_interpolation() -> String {
    use textures::materials::linear_to_srgb;
    let corners: Vec<Vec2> = triangle::TRIANGLE.iter().map(|v| Vec2::from(v.position)).collect();
    let colours: Vec<Vec3> = triangle::TRIANGLE.iter().map(|v| Vec3::from(v.color)).collect();
    let (w, h) = (240u32, 200u32);
    // Clip space (−1..1, y up) to the picture's pixels.
    let to_pixel = |p: Vec2| Vec2::new((p.x * 0.8 + 1.0) * 0.5 * w as f32, (1.0 - (p.y * 0.8 + 0.1)) * 0.5 * h as f32);
    let [a, b, c] = [to_pixel(corners[0]), to_pixel(corners[1]), to_pixel(corners[2])];
    let area = |p: Vec2, q: Vec2, r: Vec2| (q - p).perp_dot(r - p);
    let whole = area(a, b, c);
    let weights = |p: Vec2| Vec3::new(area(p, b, c), area(a, p, c), area(a, b, p)) / whole;
    let draw = |flat: bool| {
        common::image::RgbaImage::from_fn(w, h, |x, y| {
            // Coverage from 4 × 4 samples; colour at the pixel's centre.
            let mut covered = 0u32;
            for s in 0..16 {
                let p = Vec2::new(x as f32 + (s % 4) as f32 / 4.0 + 0.125, y as f32 + (s / 4) as f32 / 4.0 + 0.125);
                if weights(p).min_element() >= 0.0 {
                    covered += 1;
                }
            }
            let l = weights(Vec2::new(x as f32 + 0.5, y as f32 + 0.5)).max(Vec3::ZERO);
            let light = if flat { colours[0] } else { colours[0] * l.x + colours[1] * l.y + colours[2] * l.z };
            let byte = |v: f32| (linear_to_srgb(v.clamp(0.0, 1.0)) * 255.0).round() as u8;
            common::image::Rgba([byte(light.x), byte(light.y), byte(light.z), (covered * 255 / 16) as u8])
        })
    };
    let mut svg = Svg::new(640.0, 290.0);
    for (k, (flat, title, wgsl)) in [
        (false, "interpolated (the default)", "@location(0) color: vec3<f32>"),
        (true, "flat: the provoking vertex's value", "@location(0) @interpolate(flat) color: vec3<f32>"),
    ]
    .into_iter()
    .enumerate()
    {
        let origin = Vec2::new(40.0 + 320.0 * k as f32, 50.0);
        svg.text(origin + Vec2::new(0.0, -26.0), title, 12.0, "start", INK);
        svg.text(origin + Vec2::new(0.0, -12.0), wgsl, 9.5, "start", MUTED);
        svg.image(origin.x, origin.y, w as f32, h as f32, &draw(flat));
        for (i, (corner, name)) in [a, b, c].iter().zip(["0: first", "1", "2"]).enumerate() {
            let offset = match i {
                0 => Vec2::new(14.0, 4.0),
                1 => Vec2::new(-4.0, 18.0),
                _ => Vec2::new(4.0, 18.0),
            };
            svg.circle(origin + *corner, 3.0, INK);
            svg.text(origin + *corner + offset, &format!("vertex {name}"), 10.0, "start", INK);
        }
    }
    svg.text(
        Vec2::new(40.0, 278.0),
        "chapter 01's triangle (triangle::TRIANGLE): vertex 0 red, 1 green, 2 blue; WebGPU's provoking vertex is the first",
        10.0,
        "start",
        MUTED,
    );
    svg.finish()
}

/// A texel of a normal map, bytes to the direction it stores (as
/// `mapped_normal` in surface.wgsl reads it: c × 2 − 1, per channel).
fn stored_direction(texel: [u8; 4]) -> Vec3 {
    Vec3::new(texel[0] as f32, texel[1] as f32, texel[2] as f32) / 255.0 * 2.0 - 1.0
}

/// The brick's tangent-space normal map beside its albedo (a corner of the
/// tile, enlarged), and five of its texels read back as directions: the
/// most nearly flat one and the ones tilted furthest right, left, up and
/// down the picture. From the files `cargo xtask assets` painted, as the
/// chapter embeds them (`textures::builtin`).
pub fn normal_map() -> String {
    let read = |path: &str| {
        let bytes = textures::builtin::read(std::path::Path::new(path)).expect("the brick is built in");
        common::texture::decode_rgba(&bytes).expect("the brick's PNGs decode")
    };
    let (albedo, normal) = (read("textures/brick/albedo.png"), read("textures/brick/normal.png"));
    let (cw, ch) = (64u32, 32u32);
    let crop = |picture: &common::image::RgbaImage| {
        common::image::RgbaImage::from_fn(cw, ch, |x, y| {
            let mut p = *picture.get_pixel(x, y);
            p[3] = 255;
            p
        })
    };
    let texels: Vec<(u32, u32, [u8; 4])> =
        (0..ch).flat_map(|y| (0..cw).map(move |x| (x, y))).map(|(x, y)| (x, y, normal.get_pixel(x, y).0)).collect();
    // The texel that goes furthest one way; of equals, the one nearest the
    // crop's centre, so that the marks spread over the bricks.
    let pick = |key: &dyn Fn(Vec3) -> f32| {
        let centre = Vec2::new(cw as f32, ch as f32) / 2.0;
        let off_centre = |x: u32, y: u32| (Vec2::new(x as f32, y as f32) - centre).length();
        *texels
            .iter()
            .max_by(|a, b| {
                key(stored_direction(a.2))
                    .total_cmp(&key(stored_direction(b.2)))
                    .then(off_centre(b.0, b.1).total_cmp(&off_centre(a.0, a.1)))
            })
            .expect("the crop has texels")
    };
    let picks = [
        (pick(&|d| d.z), "nearly flat: straight out of the surface (+z)"),
        (pick(&|d| d.x), "red high: leans right, along +u, the tangent (+x)"),
        (pick(&|d| -d.x), "red low: leans left (−x)"),
        (pick(&|d| d.y), "green high: leans up the picture, the bitangent (+y)"),
        (pick(&|d| -d.y), "green low: leans down the picture (−y)"),
    ];
    let scale = 4.0;
    let mut svg = Svg::new(640.0, 350.0);
    let (left, right, top) = (Vec2::new(40.0, 44.0), Vec2::new(340.0, 44.0), 44.0);
    svg.text(left + Vec2::new(0.0, -10.0), "brick albedo (sRGB), 64 × 32 texels of the 256² tile", 11.0, "start", INK);
    svg.text(right + Vec2::new(0.0, -10.0), "brick normal map (linear), the same texels", 11.0, "start", INK);
    svg.image(left.x, top, cw as f32 * scale, ch as f32 * scale, &crop(&albedo));
    svg.image(right.x, top, cw as f32 * scale, ch as f32 * scale, &crop(&normal));
    for (k, ((x, y, texel), meaning)) in picks.iter().enumerate() {
        let at = right + (Vec2::new(*x as f32, *y as f32) + 0.5) * scale;
        svg.ring(at, 6.0, INK, 1.5);
        svg.text(at + Vec2::new(-8.0, -6.0), &format!("{}", k + 1), 11.0, "end", INK);
        let row = Vec2::new(40.0, 196.0 + 24.0 * k as f32);
        let hex = format!("#{:02x}{:02x}{:02x}", texel[0], texel[1], texel[2]);
        svg.rect(row.x, row.y, 18.0, 18.0, &hex, INK);
        let d = stored_direction(*texel);
        // Two decimals, without a "−0.00" for a hair below zero.
        let f2 = |v: f32| format!("{:.2}", if v.abs() < 0.005 { 0.0 } else { v });
        let line =
            format!("{}   ({}, {}, {}) → ({}, {}, {})", k + 1, texel[0], texel[1], texel[2], f2(d.x), f2(d.y), f2(d.z));
        svg.text(row + Vec2::new(28.0, 13.0), &line, 11.0, "start", INK);
        svg.text(row + Vec2::new(270.0, 13.0), meaning, 11.0, "start", MUTED);
    }
    svg.text(
        Vec2::new(40.0, 332.0),
        "bytes (r, g, b) → direction c / 255 × 2 − 1 in the surface's frame: x along the tangent, y up the picture, z out",
        10.0,
        "start",
        MUTED,
    );
    svg.finish()
}

/// One round bump, its normal map written both ways (OpenGL-style, green
/// up the picture, as this project's maps are; DirectX-style, green down),
/// and each lit from above as this chapter reads normal maps
/// (`mapped_normal` in surface.wgsl, without and with its `flip_green`).
pub fn green_up() -> String {
    use textures::materials::linear_to_srgb;
    const SIZE: i32 = 64;
    // The bump's height: 1 at the centre, falling smoothly to 0 at 22 texels.
    let height = |x: i32, y: i32| {
        let r = Vec2::new(x as f32 - 31.5, y as f32 - 31.5).length() / 22.0;
        if r < 1.0 { (r * std::f32::consts::FRAC_PI_2).cos().powi(2) } else { 0.0 }
    };
    // Slopes as the asset generator takes them (xtask/src/assets/materials.rs):
    // along +u (right) and up the picture (−y), by central differences.
    let strength = 10.0;
    let opengl = common::image::RgbaImage::from_fn(SIZE as u32, SIZE as u32, |x, y| {
        let (x, y) = (x as i32, y as i32);
        let right = (height(x + 1, y) - height(x - 1, y)) * 0.5;
        let up = (height(x, y - 1) - height(x, y + 1)) * 0.5;
        let n = Vec3::new(-right * strength, -up * strength, 1.0).normalize();
        let byte = |c: f32| ((c * 0.5 + 0.5) * 255.0).round() as u8;
        common::image::Rgba([byte(n.x), byte(n.y), byte(n.z), 255])
    });
    let mut directx = opengl.clone();
    for p in directx.pixels_mut() {
        p[1] = 255 - p[1];
    }
    // Light from above the picture and in front of it, in the surface's
    // frame (x right, y up the picture, z out).
    let light = Vec3::new(0.0, 1.0, 1.0).normalize();
    let lit = |map: &common::image::RgbaImage, flip_green: bool| {
        common::image::RgbaImage::from_fn(SIZE as u32, SIZE as u32, |x, y| {
            let mut m = stored_direction(map.get_pixel(x, y).0);
            if flip_green {
                m.y = -m.y;
            }
            let shade = 0.06 + 0.8 * m.normalize().dot(light).max(0.0);
            let v = (linear_to_srgb(shade) * 255.0).round() as u8;
            common::image::Rgba([v, v, v, 255])
        })
    };
    let columns = [
        (
            "OpenGL-style, Y+ (this project's)",
            "green up the picture",
            &opengl,
            false,
            "read as Y+: lit from above, a bump",
        ),
        ("DirectX-style, Y−", "green down the picture", &directx, false, "read as Y+: lit from below, a dent?"),
        ("the same DirectX-style map", "with the overlay's flip", &directx, true, "green read as down: right again"),
    ];
    let mut svg = Svg::new(640.0, 470.0);
    let side = 160.0;
    for (k, (title, note, map, flip, result)) in columns.iter().enumerate() {
        let x = 30.0 + 205.0 * k as f32;
        svg.text(Vec2::new(x, 24.0), title, 11.5, "start", INK);
        svg.text(Vec2::new(x, 38.0), &format!("normal map, {note}"), 10.0, "start", MUTED);
        svg.image(x, 48.0, side, side, map);
        svg.text(Vec2::new(x, 236.0), "lit by the chapter's shader,", 10.0, "start", MUTED);
        svg.text(Vec2::new(x, 250.0), "light from the top of the picture", 10.0, "start", MUTED);
        svg.image(x, 260.0, side, side, &lit(map, *flip));
        svg.arrow(Vec2::new(x + side - 14.0, 272.0), Vec2::new(x + side - 14.0, 296.0), ACCENT);
        svg.text(Vec2::new(x, 440.0), result, 10.5, "start", if k == 1 { ACCENT } else { INK });
    }
    svg.text(
        Vec2::new(30.0, 462.0),
        "light direction (0, 1, 1)/√2 in the surface's frame: up the picture and out of it; the arrow points the way it travels",
        9.5,
        "start",
        MUTED,
    );
    svg.finish()
}
