//! Chapter 09's figures: the tangent a triangle's texture coordinates
//! give, the sampling lab's texel footprint against distance and as
//! rectangles, and the sRGB curve, from the chapter's tangents, lab scene
//! and mipmaps.

use common::glam::{Vec2, Vec3};

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
    let encode = |c: f32| if c <= 0.003_130_8 { 12.92 * c } else { 1.055 * c.powf(1.0 / 2.4) - 0.055 };
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
