//! The book's diagrams, drawn as SVG by code. Plots are computed with the
//! chapters' own functions (fog visibility, Perlin octaves, frustum
//! culling, the sun's path, depth precision), so a diagram cannot disagree
//! with the code it explains. `cargo xtask book` writes them into
//! `book/src/diagrams/` on every build.

use std::fmt::Write as _;

use common::Camera;
use common::glam::{Vec2, Vec3};

/// Colours that read on the book's light and dark themes alike: every
/// diagram has its own pale background.
const INK: &str = "#1f2430";
const MUTED: &str = "#7a8194";
const ACCENT: &str = "#c0532b";
const BLUE: &str = "#2f6db3";
const PAPER: &str = "#fbf8f3";

/// A small SVG document.
struct Svg {
    width: f32,
    height: f32,
    body: String,
}

impl Svg {
    fn new(width: f32, height: f32) -> Self {
        let mut svg = Self { width, height, body: String::new() };
        svg.rect(0.0, 0.0, width, height, PAPER, "none");
        svg
    }

    fn line(&mut self, a: Vec2, b: Vec2, stroke: &str, width: f32) {
        let _ = writeln!(
            self.body,
            r#"<line x1="{:.1}" y1="{:.1}" x2="{:.1}" y2="{:.1}" stroke="{stroke}" stroke-width="{width}"/>"#,
            a.x, a.y, b.x, b.y
        );
    }

    fn dashed(&mut self, a: Vec2, b: Vec2, stroke: &str) {
        let _ = writeln!(
            self.body,
            r#"<line x1="{:.1}" y1="{:.1}" x2="{:.1}" y2="{:.1}" stroke="{stroke}" stroke-width="1.2" stroke-dasharray="5 4"/>"#,
            a.x, a.y, b.x, b.y
        );
    }

    fn arrow(&mut self, a: Vec2, b: Vec2, stroke: &str) {
        self.line(a, b, stroke, 1.6);
        let d = (b - a).normalize_or_zero();
        let side = Vec2::new(-d.y, d.x);
        let (p, q) = (b - d * 9.0 + side * 4.5, b - d * 9.0 - side * 4.5);
        self.polygon(&[b, p, q], stroke, "none");
    }

    fn polyline(&mut self, points: &[Vec2], stroke: &str, width: f32) {
        let list: Vec<String> = points.iter().map(|p| format!("{:.1},{:.1}", p.x, p.y)).collect();
        let _ = writeln!(
            self.body,
            r#"<polyline points="{}" fill="none" stroke="{stroke}" stroke-width="{width}" stroke-linejoin="round"/>"#,
            list.join(" ")
        );
    }

    /// Only what falls inside the rectangle (x, y, w, h) of what is drawn
    /// after this, until `unclip`.
    fn clip(&mut self, x: f32, y: f32, w: f32, h: f32) {
        let _ = writeln!(
            self.body,
            r#"<clipPath id="c{x:.0}{y:.0}"><rect x="{x:.1}" y="{y:.1}" width="{w:.1}" height="{h:.1}"/></clipPath><g clip-path="url(#c{x:.0}{y:.0})">"#
        );
    }

    fn unclip(&mut self) {
        self.body.push_str("</g>\n");
    }

    fn polygon(&mut self, points: &[Vec2], fill: &str, stroke: &str) {
        let list: Vec<String> = points.iter().map(|p| format!("{:.1},{:.1}", p.x, p.y)).collect();
        let _ = writeln!(self.body, r#"<polygon points="{}" fill="{fill}" stroke="{stroke}"/>"#, list.join(" "));
    }

    fn rect(&mut self, x: f32, y: f32, w: f32, h: f32, fill: &str, stroke: &str) {
        let _ = writeln!(
            self.body,
            r#"<rect x="{x:.1}" y="{y:.1}" width="{w:.1}" height="{h:.1}" fill="{fill}" stroke="{stroke}"/>"#
        );
    }

    fn circle(&mut self, c: Vec2, r: f32, fill: &str) {
        let _ = writeln!(self.body, r#"<circle cx="{:.1}" cy="{:.1}" r="{r}" fill="{fill}"/>"#, c.x, c.y);
    }

    /// A circle's outline.
    fn ring(&mut self, c: Vec2, r: f32, stroke: &str, width: f32) {
        let _ = writeln!(
            self.body,
            r#"<circle cx="{:.1}" cy="{:.1}" r="{r:.1}" fill="none" stroke="{stroke}" stroke-width="{width}"/>"#,
            c.x, c.y
        );
    }

    fn dashed_ring(&mut self, c: Vec2, r: f32, stroke: &str) {
        let _ = writeln!(
            self.body,
            r#"<circle cx="{:.1}" cy="{:.1}" r="{r:.1}" fill="none" stroke="{stroke}" stroke-width="1.2" stroke-dasharray="5 4"/>"#,
            c.x, c.y
        );
    }

    /// Text at `at`; `anchor` is start, middle or end.
    fn text(&mut self, at: Vec2, text: &str, size: f32, anchor: &str, fill: &str) {
        let escaped = text.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;");
        let _ = writeln!(
            self.body,
            r#"<text x="{:.1}" y="{:.1}" font-size="{size}" text-anchor="{anchor}" fill="{fill}">{escaped}</text>"#,
            at.x, at.y
        );
    }

    fn finish(self) -> String {
        format!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 {w} {h}\" width=\"{w}\" height=\"{h}\" \
             font-family=\"system-ui, sans-serif\">\n{}</svg>\n",
            self.body,
            w = self.width,
            h = self.height
        )
    }
}

/// A plot area: maps data coordinates into a rectangle of the picture.
struct Axes {
    origin: Vec2,
    size: Vec2,
    x: (f32, f32),
    y: (f32, f32),
}

impl Axes {
    fn at(&self, x: f32, y: f32) -> Vec2 {
        let u = (x - self.x.0) / (self.x.1 - self.x.0);
        let v = (y - self.y.0) / (self.y.1 - self.y.0);
        Vec2::new(self.origin.x + u * self.size.x, self.origin.y + self.size.y - v * self.size.y)
    }

    /// The frame, with tick labels at `xs` and `ys`.
    fn draw(&self, svg: &mut Svg, xs: &[f32], ys: &[f32], x_label: &str, y_label: &str) {
        let (left, bottom) = (self.origin.x, self.origin.y + self.size.y);
        svg.line(Vec2::new(left, bottom), Vec2::new(left + self.size.x, bottom), INK, 1.2);
        svg.line(Vec2::new(left, self.origin.y), Vec2::new(left, bottom), INK, 1.2);
        for &x in xs {
            let p = self.at(x, self.y.0);
            svg.line(p, p + Vec2::new(0.0, 5.0), INK, 1.0);
            svg.text(p + Vec2::new(0.0, 18.0), &trim(x), 11.0, "middle", INK);
        }
        for &y in ys {
            let p = self.at(self.x.0, y);
            svg.line(p, p - Vec2::new(5.0, 0.0), INK, 1.0);
            svg.text(p + Vec2::new(-8.0, 4.0), &trim(y), 11.0, "end", INK);
        }
        svg.text(Vec2::new(left + self.size.x / 2.0, bottom + 36.0), x_label, 12.0, "middle", INK);
        svg.text(Vec2::new(left, self.origin.y - 10.0), y_label, 12.0, "start", INK);
    }

    fn curve(&self, svg: &mut Svg, f: impl Fn(f32) -> f32, stroke: &str, width: f32) {
        let points: Vec<Vec2> = (0..=200)
            .map(|i| {
                let x = self.x.0 + (self.x.1 - self.x.0) * i as f32 / 200.0;
                self.at(x, f(x).clamp(self.y.0, self.y.1))
            })
            .collect();
        svg.polyline(&points, stroke, width);
    }
}

fn trim(value: f32) -> String {
    let text = format!("{value:.2}");
    text.trim_end_matches('0').trim_end_matches('.').to_string()
}

/// Chapter 01: clip space, and where its corners land in a picture.
fn clip_space() -> String {
    let mut svg = Svg::new(700.0, 300.0);
    let clip = Axes { origin: Vec2::new(50.0, 40.0), size: Vec2::new(200.0, 200.0), x: (-1.0, 1.0), y: (-1.0, 1.0) };
    clip.draw(&mut svg, &[-1.0, 0.0, 1.0], &[-1.0, 0.0, 1.0], "x (clip space)", "y");
    let corners: Vec<Vec2> = triangle::TRIANGLE.iter().map(|v| Vec2::from(v.position)).collect();
    let colours = ["#d23b2f", "#2f9a45", "#2f5fd0"];
    svg.polygon(&corners.iter().map(|c| clip.at(c.x, c.y)).collect::<Vec<_>>(), "#e9e1d6", INK);
    // The picture: 1280 × 720 pixels, y down.
    let (width, height) = (1280.0, 720.0);
    let (left, top, scale) = (370.0, 60.0, 0.2);
    svg.rect(left, top, width * scale, height * scale, "#ffffff", INK);
    svg.text(Vec2::new(left, top - 10.0), "(0, 0)", 11.0, "middle", INK);
    svg.text(Vec2::new(left + width * scale, top + height * scale + 16.0), "(1280, 720)", 11.0, "middle", INK);
    svg.text(Vec2::new(left + width * scale / 2.0, top + height * scale + 36.0), "pixels, y down", 12.0, "middle", INK);
    let pixels: Vec<Vec2> =
        corners.iter().map(|c| Vec2::new((c.x + 1.0) / 2.0 * width, (1.0 - c.y) / 2.0 * height)).collect();
    svg.polygon(&pixels.iter().map(|p| Vec2::new(left, top) + *p * scale).collect::<Vec<_>>(), "#e9e1d6", INK);
    for ((c, p), colour) in corners.iter().zip(&pixels).zip(colours) {
        let (a, b) = (clip.at(c.x, c.y), Vec2::new(left, top) + *p * scale);
        svg.circle(a, 4.0, colour);
        svg.circle(b, 4.0, colour);
        svg.text(a + Vec2::new(6.0, -6.0), &format!("({}, {})", trim(c.x), trim(c.y)), 10.0, "start", colour);
        svg.text(b + Vec2::new(6.0, -6.0), &format!("({:.0}, {:.0})", p.x, p.y), 10.0, "start", colour);
    }
    svg.arrow(Vec2::new(275.0, 140.0), Vec2::new(345.0, 140.0), MUTED);
    svg.text(Vec2::new(310.0, 130.0), "x' = (x+1)/2·W", 10.0, "middle", MUTED);
    svg.text(Vec2::new(310.0, 162.0), "y' = (1−y)/2·H", 10.0, "middle", MUTED);
    svg.finish()
}

/// Chapter 02: the view frustum from the side.
fn frustum_side() -> String {
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
fn depth_precision() -> String {
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

/// Chapter 03: octaves of Perlin noise and their sum, from the chapter's noise.
fn fbm_octaves() -> String {
    use terrain::noise::{Fbm, perlin3};
    let mut svg = Svg::new(640.0, 430.0);
    let fbm = Fbm { octaves: 4, persistence: 0.5, lacunarity: 2.0 };
    let row = |i: usize, height: f32| Axes {
        origin: Vec2::new(30.0, 34.0 + i as f32 * 74.0),
        size: Vec2::new(580.0, height),
        x: (0.0, 4.0),
        y: (-0.6, 0.6),
    };
    for octave in 0..4 {
        let axes = row(octave, 50.0);
        let (frequency, amplitude) = (2f32.powi(octave as i32), 0.5f32.powi(octave as i32));
        svg.line(axes.at(0.0, 0.0), axes.at(4.0, 0.0), "#e3dccf", 1.0);
        axes.curve(&mut svg, |x| amplitude * perlin3(f64::from(x * frequency), 0.5, 0.5) as f32, MUTED, 1.6);
        let label = format!("octave {}: frequency ×{frequency}, height ×{amplitude}", octave + 1);
        svg.text(axes.origin - Vec2::new(0.0, 6.0), &label, 11.0, "start", INK);
    }
    // The sum of the rows above; `Fbm::sample` divides it by 1 + ½ + ¼ + ⅛.
    let total: f32 = (0..4).map(|o| 0.5f32.powi(o)).sum();
    let sum = row(4, 80.0);
    svg.line(sum.at(0.0, 0.0), sum.at(4.0, 0.0), "#e3dccf", 1.0);
    sum.curve(&mut svg, |x| fbm.sample(f64::from(x), 0.5, 0.5) as f32 * total, ACCENT, 2.2);
    svg.text(sum.origin - Vec2::new(0.0, 6.0), "their sum: hills on hills (fBm)", 11.0, "start", ACCENT);
    svg.finish()
}

/// Chapter 03: which chunks a camera's frustum keeps, seen from above,
/// computed with the chapter's `Frustum` on a 16 × 16 grid of 64 m chunks.
fn frustum_culling() -> String {
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

/// Chapter 04: visibility against distance for the chapter's fogs.
fn fog_curve() -> String {
    use fog::FogSettings;
    let mut svg = Svg::new(640.0, 320.0);
    let axes = Axes { origin: Vec2::new(70.0, 40.0), size: Vec2::new(500.0, 210.0), x: (0.0, 2500.0), y: (0.0, 1.0) };
    axes.draw(&mut svg, &[0.0, 500.0, 1000.0, 1500.0, 2000.0, 2500.0], &[0.0, 0.37, 1.0], "distance (m)", "visibility");
    let plain = FogSettings { density: FogSettings::HAZE.density, gradient: 1.0 };
    let fogs = [
        (FogSettings::HAZE, BLUE, "haze: density 0.0015, gradient 1.5"),
        (plain, MUTED, "density 0.0015, gradient 1"),
        (FogSettings::DUST_STORM, ACCENT, "dust storm: 0.004, gradient 2"),
    ];
    for (i, (fog, colour, label)) in fogs.iter().enumerate() {
        axes.curve(&mut svg, |d| fog.visibility(d), colour, 2.0);
        let opaque = fog.opaque_distance();
        if opaque < 2500.0 {
            let p = axes.at(opaque, 0.0);
            svg.line(p, p - Vec2::new(0.0, 14.0), colour, 2.0);
            svg.text(p - Vec2::new(0.0, 18.0), &format!("{opaque:.0} m"), 10.0, "middle", colour);
        }
        svg.text(Vec2::new(330.0, 60.0 + 16.0 * i as f32), label, 11.0, "start", colour);
    }
    svg.dashed(axes.at(0.0, (-1f32).exp()), axes.at(2500.0, (-1f32).exp()), "#c9c2b6");
    svg.text(Vec2::new(330.0, 118.0), "ticks: the opaque distance, below 1/255", 10.0, "start", MUTED);
    svg.finish()
}

/// Chapter 05: two vertex buffers, one stepping per vertex, one per instance.
fn instancing_buffers() -> String {
    let mut svg = Svg::new(640.0, 280.0);
    svg.text(Vec2::new(20.0, 28.0), "buffer 0: the rock mesh, step_mode Vertex (60 vertices)", 12.0, "start", INK);
    for i in 0..10 {
        let x = 20.0 + i as f32 * 44.0;
        svg.rect(x, 38.0, 40.0, 26.0, "#e9e1d6", INK);
        svg.text(Vec2::new(x + 20.0, 56.0), &if i < 9 { format!("v{i}") } else { "…".into() }, 11.0, "middle", INK);
    }
    svg.text(Vec2::new(20.0, 98.0), "buffer 1: rocks, step_mode Instance (32 bytes each)", 12.0, "start", INK);
    for i in 0..4 {
        let x = 20.0 + i as f32 * 110.0;
        svg.rect(x, 108.0, 104.0, 26.0, "#e7b48f", INK);
        let label = if i < 3 { format!("rock {i}") } else { "…".into() };
        svg.text(Vec2::new(x + 52.0, 126.0), &label, 11.0, "middle", INK);
    }
    svg.text(
        Vec2::new(20.0, 172.0),
        "draw_indexed(0..60, 0, 0..n): the vertex shader runs for every pair",
        12.0,
        "start",
        INK,
    );
    for (row, rock) in ["rock 0", "rock 1", "rock 2"].iter().enumerate() {
        let y = 184.0 + row as f32 * 28.0;
        svg.text(Vec2::new(70.0, y + 17.0), rock, 11.0, "end", INK);
        for v in 0..8 {
            let x = 80.0 + v as f32 * 60.0;
            svg.rect(x, y, 56.0, 22.0, if row % 2 == 0 { "#f3ece2" } else { "#efe2d3" }, "#d9cfc1");
            svg.text(Vec2::new(x + 28.0, y + 15.0), &format!("v{v}, r{row}"), 10.0, "middle", INK);
        }
    }
    svg.finish()
}

/// Chapter 06: the sun's height through a day, and how much day sky shows,
/// from `skybox::sun_at` and `day_blend`.
fn sun_path() -> String {
    use skybox::{day_blend, sun_at};
    let mut svg = Svg::new(640.0, 300.0);
    let axes = Axes { origin: Vec2::new(70.0, 40.0), size: Vec2::new(520.0, 190.0), x: (0.0, 1.0), y: (-1.0, 1.0) };
    axes.draw(
        &mut svg,
        &[0.0, 0.25, 0.5, 0.75, 1.0],
        &[-1.0, 0.0, 1.0],
        "time of day (0 midnight, 0.25 sunrise, 0.5 noon, 0.75 sunset)",
        "",
    );
    svg.line(axes.at(0.0, 0.0), axes.at(1.0, 0.0), "#d9cfc1", 1.0);
    axes.curve(&mut svg, |phase| sun_at(phase).direction.y, ACCENT, 2.2);
    axes.curve(&mut svg, |phase| day_blend(sun_at(phase)), BLUE, 2.0);
    svg.text(Vec2::new(80.0, 30.0), "sun height (y of the light's direction)", 11.0, "start", ACCENT);
    svg.text(Vec2::new(330.0, 30.0), "day sky shown (0 night … 1 day)", 11.0, "start", BLUE);
    for (phase, view) in [(0.02, "night"), (0.40, "day"), (0.745, "dusk")] {
        let p = axes.at(phase, sun_at(phase).direction.y);
        svg.circle(p, 4.5, INK);
        svg.text(p + Vec2::new(0.0, -10.0), view, 11.0, "middle", INK);
    }
    svg.finish()
}

/// Chapter 07: the camera mirrored in the water.
fn mirrored_camera() -> String {
    let mut svg = Svg::new(640.0, 320.0);
    let level = 160.0;
    svg.rect(0.0, level, 640.0, 160.0, "#dbe7ef", "none");
    svg.line(Vec2::new(0.0, level), Vec2::new(640.0, level), BLUE, 2.0);
    svg.text(Vec2::new(620.0, level + 18.0), "water level", 11.0, "end", BLUE);
    let eye = Vec2::new(90.0, level - 80.0);
    let mirror = Vec2::new(eye.x, 2.0 * level - eye.y);
    let peak = Vec2::new(560.0, level - 120.0);
    // Where the ray from the mirrored eye to the peak crosses the water.
    let t = (level - mirror.y) / (peak.y - mirror.y);
    let hit = mirror + (peak - mirror) * t;
    svg.polygon(&[Vec2::new(470.0, level), peak, Vec2::new(620.0, level)], "#c9a98d", "none");
    svg.arrow(eye, hit, ACCENT);
    svg.arrow(hit, peak, ACCENT);
    svg.dashed(mirror, hit, MUTED);
    svg.dashed(eye, mirror, MUTED);
    svg.circle(eye, 5.0, INK);
    svg.circle(mirror, 5.0, MUTED);
    svg.text(eye + Vec2::new(-10.0, -12.0), "camera, h above", 11.0, "start", INK);
    svg.text(mirror + Vec2::new(-10.0, 22.0), "mirrored camera, h below, pitch negated", 11.0, "start", MUTED);
    svg.text(hit + Vec2::new(0.0, 20.0), "the reflection is what the mirrored camera sees here", 11.0, "middle", INK);
    svg.text(
        Vec2::new(20.0, 24.0),
        "y′ = 2·level − y: the reflected ray and the mirrored camera's ray are one line",
        11.0,
        "start",
        INK,
    );
    svg.finish()
}

/// Chapter 07: from a fragment's clip position to texture coordinates.
fn projective_texturing() -> String {
    let mut svg = Svg::new(640.0, 260.0);
    let ndc = Axes { origin: Vec2::new(50.0, 40.0), size: Vec2::new(160.0, 160.0), x: (-1.0, 1.0), y: (-1.0, 1.0) };
    ndc.draw(&mut svg, &[-1.0, 1.0], &[-1.0, 1.0], "clip.xy / clip.w", "");
    let point = Vec2::new(0.5, 0.5);
    svg.circle(ndc.at(point.x, point.y), 5.0, ACCENT);
    let boxes = [(260.0, "refraction: u = (x+1)/2, v = (1−y)/2", false), (450.0, "reflection: v = (1+y)/2", true)];
    for (left, label, flipped) in boxes {
        svg.rect(left, 40.0, 160.0, 160.0, "#ffffff", INK);
        svg.text(Vec2::new(left, 34.0), "(0, 0)", 10.0, "middle", INK);
        svg.text(Vec2::new(left + 160.0, 214.0), "(1, 1)", 10.0, "middle", INK);
        let u = (point.x + 1.0) / 2.0;
        let v = if flipped { (1.0 + point.y) / 2.0 } else { (1.0 - point.y) / 2.0 };
        svg.circle(Vec2::new(left + u * 160.0, 40.0 + v * 160.0), 5.0, ACCENT);
        svg.text(Vec2::new(left + 80.0, 236.0), label, 11.0, "middle", INK);
    }
    svg.text(
        Vec2::new(20.0, 20.0),
        "the same fragment, looked up in each picture (texture v runs down)",
        11.0,
        "start",
        INK,
    );
    svg.finish()
}

/// Chapter 08: how a point light falls off, from `lighting::lights::attenuation`,
/// against the city project's constant–linear–quadratic formula.
fn light_falloff() -> String {
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
    axes.curve(&mut svg, |d| log(1.0 / (d * d + 1.0)), MUTED, 1.5);
    axes.curve(&mut svg, |d| log(attenuation(d, range)), ACCENT, 2.4);
    svg.dashed(axes.at(range, -4.0), axes.at(range, 0.0), "#c9c2b6");
    svg.text(axes.at(range, -0.25) + Vec2::new(6.0, 0.0), "range: exactly 0 beyond", 10.0, "start", INK);
    svg.text(Vec2::new(120.0, 224.0), "this chapter: 1/(d² + 1), windowed to 0 at 18 m", 11.0, "start", ACCENT);
    svg.text(Vec2::new(120.0, 240.0), "1/(d² + 1), never reaching 0", 11.0, "start", MUTED);
    svg.text(Vec2::new(585.0, 130.0), "the city project: 1/(1 + 0.09 d + 0.032 d²)", 11.0, "end", "#8a6fb0");
    svg.finish()
}

/// Chapter 08: a spot light's cone, from `lighting::lights::spot_factor`.
fn spot_cone() -> String {
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
fn half_vector() -> String {
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
fn clusters_side() -> String {
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
    let _ = writeln!(
        svg.body,
        r#"<circle cx="{:.1}" cy="{:.1}" r="{:.1}" fill="none" stroke="{ACCENT}" stroke-width="2"/>"#,
        centre.x,
        centre.y,
        light.2 * depth_scale
    );
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
fn bloom_chain() -> String {
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

/// Chapter 09: texture coordinates and the tangent they give, for one
/// triangle, from `textures::tangents::triangle_tangents`.
fn tangent_from_uvs() -> String {
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

/// Texels of the lab's checker per metre of its floor: the floor's
/// repeats times the texture's width, over the floor's width.
fn lab_texels_per_metre() -> f32 {
    let floor = textures::scenes::lab_floor();
    let (low, high) = floor.bounds();
    let repeats = floor.vertices.iter().map(|v| v.uv[0]).fold(0.0f32, f32::max);
    textures::materials::checkerboard().width() as f32 * repeats / (high.x - low.x)
}

/// The sampling lab's floor as its camera sees it: texels per pixel, along
/// the view and across it, against distance. The mip level a sampler picks
/// is the log₂ of that (of the larger, unless it filters anisotropically).
/// From the lab's camera and floor (`textures::view_camera`, `lab_floor`).
fn texel_footprint() -> String {
    let (_, camera) = textures::view_camera("mipmaps", 16.0 / 9.0);
    let texels_per_metre = lab_texels_per_metre();
    let (height, rows, columns) = (camera.position.y, 720.0, 1280.0);
    let per_pixel = camera.fov_y / rows;
    let tan_x = (camera.fov_y / 2.0).tan() * 16.0 / 9.0;
    // At ground distance d: a pixel row covers (d² + h²) / h × Δθ metres along
    // the view; a pixel column covers the slant range × 2 tan(fov_x / 2) / 1280.
    let along = |d: f32| texels_per_metre * (d * d + height * height) / height * per_pixel;
    let across = |d: f32| texels_per_metre * (d * d + height * height).sqrt() * 2.0 * tan_x / columns;
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
    axes.curve(&mut svg, |d| along(d.max(0.1)).log2(), ACCENT, 2.2);
    axes.curve(&mut svg, |d| across(d.max(0.1)).log2(), BLUE, 2.2);
    svg.text(axes.at(12.0, along(25.0).log2() + 1.0), "along the view", 11.0, "start", ACCENT);
    svg.text(axes.at(70.0, across(70.0).log2()) + Vec2::new(0.0, 16.0), "across it", 11.0, "start", BLUE);
    svg.finish()
}

/// A pixel's footprint on the lab's floor, in texels, at three distances:
/// trilinear filtering blurs it to a square as big as its long side;
/// anisotropic filtering takes several samples along the long side.
fn footprints() -> String {
    let (_, camera) = textures::view_camera("mipmaps", 16.0 / 9.0);
    let height = camera.position.y;
    let per_pixel = camera.fov_y / 720.0;
    let tan_x = (camera.fov_y / 2.0).tan() * 16.0 / 9.0;
    let texels_per_metre = lab_texels_per_metre();
    let mut svg = Svg::new(640.0, 285.0);
    svg.text(
        Vec2::new(20.0, 24.0),
        "one pixel's footprint on the floor, in texels (the grid is one texel)",
        11.0,
        "start",
        INK,
    );
    for (i, d) in [5.0f32, 10.0, 20.0].iter().enumerate() {
        let along = texels_per_metre * (d * d + height * height) / height * per_pixel;
        let across = texels_per_metre * (d * d + height * height).sqrt() * 2.0 * tan_x / 1280.0;
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
fn srgb_curve() -> String {
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

/// Chapter 10: shadow acne. The light looks down; each shadow-map texel
/// stores the depth of the surface at its centre, a flat step. Along a
/// sloped surface, half of every texel lies deeper than its step and
/// shadows itself; a bias of half a texel's depth change moves every step
/// below the surface.
fn shadow_acne() -> String {
    let mut svg = Svg::new(640.0, 380.0);
    let (left, top, texel) = (40.0f32, 90.0f32, 60.0f32);
    let slope = 0.45f32;
    let surface = |x: f32| top + 30.0 + slope * (x - left);
    let texels = 8;
    let right = left + texel * texels as f32;
    // Rays from the sun, straight down in light space.
    for i in 0..=texels {
        let x = left + texel * i as f32;
        svg.dashed(Vec2::new(x, top - 10.0), Vec2::new(x, 370.0), MUTED);
    }
    svg.text(
        Vec2::new(left, top - 18.0),
        "shadow-map texels, seen from the sun (rays point down)",
        11.0,
        "start",
        MUTED,
    );
    for i in 0..texels {
        let x0 = left + texel * i as f32;
        let centre = x0 + texel / 2.0;
        let stored = surface(centre);
        // The part of the surface deeper than the stored step: in shadow.
        svg.polygon(
            &[Vec2::new(centre, stored), Vec2::new(x0 + texel, surface(x0 + texel)), Vec2::new(x0 + texel, stored)],
            "#e9b8a6",
            "none",
        );
        svg.line(Vec2::new(x0, stored), Vec2::new(x0 + texel, stored), ACCENT, 2.5);
        svg.circle(Vec2::new(centre, stored), 3.0, ACCENT);
        let biased = stored + slope * texel / 2.0 + 4.0;
        svg.line(Vec2::new(x0, biased), Vec2::new(x0 + texel, biased), BLUE, 1.5);
    }
    svg.line(Vec2::new(left, surface(left)), Vec2::new(right, surface(right)), INK, 2.0);
    let legend = right + 12.0;
    svg.text(Vec2::new(legend, top + 20.0), "depth stored", 11.0, "start", ACCENT);
    svg.text(Vec2::new(legend, top + 34.0), "(one per texel)", 11.0, "start", ACCENT);
    svg.text(Vec2::new(legend, top + 58.0), "the surface", 11.0, "start", INK);
    svg.text(Vec2::new(legend, top + 82.0), "stored + bias", 11.0, "start", BLUE);
    svg.text(Vec2::new(legend, top + 106.0), "shaded: in its", 11.0, "start", ACCENT);
    svg.text(Vec2::new(legend, top + 120.0), "own shadow", 11.0, "start", ACCENT);
    svg.text(
        Vec2::new(20.0, 24.0),
        "Where the surface lies deeper than the step its texel stored (shaded), it shadows itself: stripes.",
        11.0,
        "start",
        INK,
    );
    svg.text(
        Vec2::new(20.0, 40.0),
        "Pushing each step back by the depth the surface gains across half a texel (slope-scaled bias) ends it.",
        11.0,
        "start",
        BLUE,
    );
    svg.finish()
}

/// Chapter 11's sites, each with a pale fill for its cell and a strong
/// colour for its lines.
const SITE_FILLS: [&str; 5] = ["#f6d5c0", "#cfe0f2", "#d6ebcf", "#f1e3a9", "#e2d5ef"];
const SITE_INKS: [&str; 5] = [ACCENT, BLUE, "#3f8f4e", "#b38b14", "#7c59a8"];

/// The part of the convex `polygon` nearer to `site` than to `other`: the
/// polygon clipped by their bisector.
fn clip_to_nearer(polygon: &[Vec2], site: Vec2, other: Vec2) -> Vec<Vec2> {
    let (middle, towards) = ((site + other) / 2.0, other - site);
    let beyond = |p: Vec2| (p - middle).dot(towards); // > 0: nearer to `other`
    let mut kept = Vec::new();
    for (i, &a) in polygon.iter().enumerate() {
        let b = polygon[(i + 1) % polygon.len()];
        let (da, db) = (beyond(a), beyond(b));
        if da <= 0.0 {
            kept.push(a);
        }
        if (da <= 0.0) != (db <= 0.0) {
            kept.push(a + (b - a) * (da / (da - db)));
        }
    }
    kept
}

/// Site `i`'s Voronoi cell inside the unit square: the square clipped by
/// its bisector with every other site, so its edges are exact.
fn voronoi_cell(sites: &[Vec2], i: usize) -> Vec<Vec2> {
    let square = vec![Vec2::ZERO, Vec2::X, Vec2::ONE, Vec2::Y];
    sites
        .iter()
        .enumerate()
        .filter(|&(j, _)| j != i)
        .fold(square, |cell, (_, &other)| clip_to_nearer(&cell, sites[i], other))
}

/// Which site is nearest to `p`.
fn nearest_site(sites: &[Vec2], p: Vec2) -> usize {
    (0..sites.len()).min_by(|&a, &b| p.distance(sites[a]).total_cmp(&p.distance(sites[b]))).unwrap_or(0)
}

/// Chapter 11: the Voronoi diagram as cones and a depth test (Hoff et al.
/// 1999). Left, from above: the cells, exact, and circles of equal radius
/// around two sites meeting on their shared edge. Right, a slice along the
/// dashed line through three sites: each site's cone, its depth the
/// distance to the site, and what the depth test keeps of them.
fn voronoi_cones() -> String {
    let mut svg = Svg::new(640.0, 360.0);
    // In the unit square, y down. The two sites off the slice lie farther
    // from it than any point of it from its own site, so that only the
    // slice's three sites' cones reach into the side view's depth range.
    let sites = [
        Vec2::new(0.14, 0.56),
        Vec2::new(0.46, 0.56),
        Vec2::new(0.84, 0.56),
        Vec2::new(0.66, 0.1),
        Vec2::new(0.62, 0.93),
    ];
    let slice = 0.56;
    let (origin, size) = (Vec2::new(30.0, 82.0), 250.0);
    let top = |p: Vec2| origin + p * size;
    svg.text(Vec2::new(origin.x, origin.y - 10.0), "seen from above", 12.0, "start", INK);
    for (i, fill) in (0..sites.len()).zip(SITE_FILLS) {
        svg.polygon(&voronoi_cell(&sites, i).into_iter().map(top).collect::<Vec<_>>(), fill, "#ffffff");
    }
    // Equal radii around the two left-hand sites meet on their bisector:
    // the same distance is the same cone height.
    svg.clip(origin.x, origin.y, size, size);
    let half = (sites[1].x - sites[0].x) / 2.0;
    for radius in [half, 0.22, 0.28] {
        for i in [0, 1] {
            svg.dashed_ring(top(sites[i]), radius * size, SITE_INKS[i]);
        }
        let rise = (radius * radius - half * half).max(0.0).sqrt();
        for y in [slice - rise, slice + rise] {
            let meeting = Vec2::new(sites[0].x + half, y);
            debug_assert!(nearest_site(&sites, meeting) < 2, "the circles meet on the two sites' edge");
            svg.circle(top(meeting), 2.5, INK);
        }
    }
    svg.unclip();
    svg.rect(origin.x, origin.y, size, size, "none", INK);
    svg.dashed(top(Vec2::new(0.0, slice)), top(Vec2::new(1.0, slice)), INK);
    svg.text(top(Vec2::new(1.0, slice)) + Vec2::new(-4.0, -6.0), "slice", 10.0, "end", INK);
    for (i, &site) in sites.iter().enumerate() {
        svg.circle(top(site), 4.5, "#ffffff");
        svg.circle(top(site), 3.2, SITE_INKS[i]);
    }
    // The side view: x as above, depth down at the same scale, so the
    // cones' sides fall at 45°.
    let (left, ground, depth_range) = (360.0, 150.0, 0.34);
    let side = |x: f32, depth: f32| Vec2::new(left + x * size, ground + depth * size);
    svg.text(Vec2::new(left, origin.y - 10.0), "seen from the side, along the slice", 12.0, "start", INK);
    for x in [0.2, 0.5, 0.8] {
        svg.arrow(side(x, -0.22), side(x, -0.08), MUTED);
    }
    svg.text(side(1.0, -0.24), "orthographic camera, looking down", 10.0, "end", MUTED);
    svg.clip(left, ground - 10.0, size, depth_range * size + 10.0);
    for i in 0..3 {
        let apex = side(sites[i].x, 0.0);
        let reach = depth_range + 0.05;
        svg.polyline(&[side(sites[i].x - reach, reach), apex, side(sites[i].x + reach, reach)], SITE_INKS[i], 0.8);
    }
    svg.unclip();
    svg.line(side(0.0, 0.0), side(1.0, 0.0), MUTED, 0.8);
    // What the camera sees along the slice: the nearest cone at each x,
    // one run per site, from all five sites.
    let samples = 500;
    let mut runs: Vec<(usize, Vec<Vec2>)> = Vec::new();
    for k in 0..=samples {
        let p = Vec2::new(k as f32 / samples as f32, slice);
        let owner = nearest_site(&sites, p);
        let point = side(p.x, p.distance(sites[owner]));
        match runs.last_mut() {
            Some((site, points)) if *site == owner => points.push(point),
            _ => runs.push((owner, vec![point])),
        }
    }
    let (strip, strip_height) = (ground + depth_range * size + 14.0, 14.0);
    for (site, points) in &runs {
        svg.polyline(points, SITE_INKS[*site], 3.2);
        let (a, b) = (points[0].x, points[points.len() - 1].x);
        svg.rect(a, strip, b - a, strip_height, SITE_FILLS[*site], "none");
    }
    svg.rect(left, strip, size, strip_height, "none", INK);
    // Where two cones cross, the visible surface changes site: a cell edge.
    for pair in runs.windows(2) {
        let (a, b) = (pair[0].1[pair[0].1.len() - 1], pair[1].1[0]);
        let crossing = (a + b) / 2.0;
        svg.dashed(crossing, Vec2::new(crossing.x, strip + strip_height), INK);
        svg.circle(crossing, 3.5, INK);
    }
    for (i, &site) in sites.iter().take(3).enumerate() {
        svg.circle(side(site.x, 0.0), 4.5, "#ffffff");
        svg.circle(side(site.x, 0.0), 3.2, SITE_INKS[i]);
    }
    svg.text(Vec2::new(left - 8.0, ground + 4.0), "0", 10.0, "end", MUTED);
    svg.text(Vec2::new(left - 8.0, ground + 18.0), "depth", 10.0, "end", MUTED);
    svg.arrow(Vec2::new(left - 22.0, ground + 26.0), Vec2::new(left - 22.0, ground + 60.0), MUTED);
    svg.text(
        Vec2::new(left + size / 2.0, strip + strip_height + 16.0),
        "the cells along the slice",
        10.0,
        "middle",
        INK,
    );
    svg.text(
        Vec2::new(left + size / 2.0, strip + strip_height + 40.0),
        "depth = distance to the site:",
        11.0,
        "middle",
        INK,
    );
    svg.text(
        Vec2::new(left + size / 2.0, strip + strip_height + 56.0),
        "the depth test keeps the nearest site",
        11.0,
        "middle",
        INK,
    );
    let key = Vec2::new(left, strip + strip_height + 82.0);
    svg.line(key + Vec2::new(0.0, -4.0), key + Vec2::new(20.0, -4.0), INK, 3.2);
    svg.text(key + Vec2::new(26.0, 0.0), "kept", 10.0, "start", INK);
    svg.line(key + Vec2::new(70.0, -4.0), key + Vec2::new(90.0, -4.0), INK, 0.8);
    svg.text(key + Vec2::new(96.0, 0.0), "behind a nearer cone", 10.0, "start", INK);
    svg.text(
        Vec2::new(20.0, 24.0),
        "Draw a cone under each site, its depth the distance to the site, and look down on them: at every pixel",
        11.0,
        "start",
        INK,
    );
    svg.text(
        Vec2::new(20.0, 40.0),
        "the depth test keeps the nearest cone, and so the nearest site. Cones cross where the distances are equal.",
        11.0,
        "start",
        INK,
    );
    svg.finish()
}

/// The side of the jump-flooding grid, in pixels.
const JFA_SIDE: usize = 16;
/// Seeds for the jump-flooding diagram, in pixels. Chosen (by trying
/// placements) so that no pixel is equally far from two seeds and jump
/// flooding gets a few pixels wrong: the seed at (12, 4) and its close
/// neighbour at (9, 6) take over pixels at the bottom that (4, 12) is
/// nearer to, before (4, 12)'s own news gets there.
const JFA_SEEDS: [(i32, i32); 3] = [(9, 6), (4, 12), (12, 4)];

/// Squared distance between pixel centres.
fn squared(a: (i32, i32), b: (i32, i32)) -> i32 {
    (a.0 - b.0).pow(2) + (a.1 - b.1).pow(2)
}

/// Each pixel's seed (an index into `JFA_SEEDS`), row by row.
type SeedMap = Vec<Option<usize>>;

/// The pixels `p` reads in a pass of step `k`: the nine k apart around it,
/// itself among them, less those outside the grid (no wrapping here).
fn jump_flood_reads(p: (i32, i32), k: i32) -> impl Iterator<Item = (i32, i32)> {
    let n = JFA_SIDE as i32;
    (-1..=1)
        .flat_map(move |j| (-1..=1).map(move |i| (p.0 + i * k, p.1 + j * k)))
        .filter(move |q| (0..n).contains(&q.0) && (0..n).contains(&q.1))
}

/// One pass of jump flooding with step `k`: each pixel keeps the seed
/// nearest to it among those of the pixels it reads.
fn jump_flood_pass(map: &SeedMap, k: i32) -> SeedMap {
    let n = JFA_SIDE as i32;
    (0..n * n)
        .map(|index| {
            let p = (index % n, index / n);
            jump_flood_reads(p, k)
                .filter_map(|q| map[(q.1 * n + q.0) as usize])
                .min_by_key(|&seed| squared(p, JFA_SEEDS[seed]))
        })
        .collect()
}

/// Chapter 11: jump flooding (Rong & Tan 2006) on a 16 × 16 grid, computed
/// here pass by pass, against the exact nearest seed of every pixel.
fn jump_flooding() -> String {
    let n = JFA_SIDE as i32;
    let mut map: SeedMap = vec![None; JFA_SIDE * JFA_SIDE];
    for (i, &(x, y)) in JFA_SEEDS.iter().enumerate() {
        map[(y * n + x) as usize] = Some(i);
    }
    let mut panels = vec![("the seeds".to_string(), map.clone(), None)];
    for k in [8, 4, 2, 1] {
        map = jump_flood_pass(&map, k);
        panels.push((format!("k = {k}"), map.clone(), Some(k)));
    }
    let exact: SeedMap = (0..n * n)
        .map(|index| (0..JFA_SEEDS.len()).min_by_key(|&s| squared((index % n, index / n), JFA_SEEDS[s])))
        .collect();
    let wrong: Vec<(i32, i32)> =
        (0..n * n).filter(|&index| map[index as usize] != exact[index as usize]).map(|i| (i % n, i / n)).collect();
    panels.push(("exact nearest seed".to_string(), exact, None));
    let mut svg = Svg::new(640.0, 500.0);
    let cell = 10.0;
    // The pixel whose nine reads are drawn in every pass.
    let reader = (5, 5);
    for (number, (title, map, step)) in panels.iter().enumerate() {
        let corner = Vec2::new(40.0 + (number % 3) as f32 * 200.0, 86.0 + (number / 3) as f32 * 204.0);
        let centre = |(x, y): (i32, i32)| corner + (Vec2::new(x as f32, y as f32) + 0.5) * cell;
        let title = if number == 4 { format!("{title}: the result") } else { title.clone() };
        svg.text(corner + Vec2::new(0.0, -8.0), &title, 12.0, "start", INK);
        for (index, seed) in map.iter().enumerate() {
            let (x, y) = (index as i32 % n, index as i32 / n);
            let fill = seed.map_or("#ffffff", |s| SITE_FILLS[s]);
            svg.rect(corner.x + x as f32 * cell, corner.y + y as f32 * cell, cell, cell, fill, "#e4ddd2");
        }
        svg.rect(corner.x, corner.y, cell * n as f32, cell * n as f32, "none", INK);
        if let Some(k) = step {
            let p = centre(reader);
            for q in jump_flood_reads(reader, *k).filter(|&q| q != reader) {
                svg.line(p, centre(q), INK, 0.8);
                svg.ring(centre(q), 2.8, INK, 1.2);
            }
            svg.rect(p.x - cell / 2.0, p.y - cell / 2.0, cell, cell, "none", INK);
        }
        if number >= 4 {
            for &pixel in &wrong {
                let c = centre(pixel);
                let d = cell * 0.3;
                svg.line(c - Vec2::splat(d), c + Vec2::splat(d), INK, 1.4);
                svg.line(c + Vec2::new(-d, d), c + Vec2::new(d, -d), INK, 1.4);
            }
        }
        for (i, &seed) in JFA_SEEDS.iter().enumerate() {
            svg.circle(centre(seed), 4.0, "#ffffff");
            svg.circle(centre(seed), 3.0, SITE_INKS[i]);
        }
    }
    svg.text(
        Vec2::new(20.0, 24.0),
        "log₂ n passes: each pixel reads itself and 8 others at a step k that halves each pass, and keeps",
        11.0,
        "start",
        INK,
    );
    svg.text(
        Vec2::new(20.0, 40.0),
        "the nearest seed it finds among theirs. Here n = 16: four passes, k = 8, 4, 2, 1.",
        11.0,
        "start",
        INK,
    );
    let legend = Vec2::new(40.0, 470.0);
    svg.circle(legend, 4.0, SITE_INKS[0]);
    svg.text(legend + Vec2::new(10.0, 4.0), "a seed", 11.0, "start", INK);
    svg.rect(legend.x + 70.0, legend.y - 5.0, cell, cell, "none", INK);
    svg.ring(legend + Vec2::new(98.0, 0.0), 2.8, INK, 1.2);
    svg.text(legend + Vec2::new(108.0, 4.0), "a pixel and the 8 others it reads", 11.0, "start", INK);
    let cross = legend + Vec2::new(330.0, 0.0);
    svg.line(cross - Vec2::splat(3.0), cross + Vec2::splat(3.0), INK, 1.4);
    svg.line(cross + Vec2::new(-3.0, 3.0), cross + Vec2::new(3.0, -3.0), INK, 1.4);
    svg.text(cross + Vec2::new(10.0, 4.0), "JFA's error: the exact nearest seed differs", 11.0, "start", INK);
    svg.finish()
}

/// A top view of part of the world: the cells from `from`, `cells` of
/// them across and down, drawn from `corner` at `cell` pixels a cell.
struct TopView {
    corner: Vec2,
    cell: f32,
    from: Vec2,
    cells: Vec2,
}

impl TopView {
    /// Where a point of the world, in cells, is drawn.
    fn at(&self, world: Vec2) -> Vec2 {
        self.corner + (world - self.from) * self.cell
    }

    fn size(&self) -> Vec2 {
        self.cells * self.cell
    }

    /// The world in view: its cells as faint lines, its points as dots,
    /// and the crests of waves that stay where the world puts them.
    fn draw_world(&self, svg: &mut Svg) {
        let (corner, size) = (self.corner, self.size());
        svg.rect(corner.x, corner.y, size.x, size.y, "#eef4f8", "none");
        svg.clip(corner.x, corner.y, size.x, size.y);
        // Parallel, gently curved crests, in world units.
        for start in (-4..8).map(|c| c as f32 * 2.6) {
            let crest: Vec<Vec2> = (0..=80)
                .map(|k| {
                    let y = -1.0 + k as f32 / 80.0 * 12.0;
                    self.at(Vec2::new(start + 0.45 * y + 0.5 * (y * 0.6).sin(), y))
                })
                .collect();
            svg.polyline(&crest, "#c4ddd8", 4.0);
        }
        svg.unclip();
        let (first, last) = (self.from, self.from + self.cells);
        for x in first.x as i32..=last.x as i32 {
            svg.line(self.at(Vec2::new(x as f32, first.y)), self.at(Vec2::new(x as f32, last.y)), "#d5dde4", 1.0);
        }
        for y in first.y as i32..=last.y as i32 {
            svg.line(self.at(Vec2::new(first.x, y as f32)), self.at(Vec2::new(last.x, y as f32)), "#d5dde4", 1.0);
        }
        for x in first.x as i32..=last.x as i32 {
            for y in first.y as i32..=last.y as i32 {
                svg.circle(self.at(Vec2::new(x as f32, y as f32)), 1.6, "#9aa5b1");
            }
        }
    }
}

/// Cells along each side of the diagram's water grid: odd, so that its
/// middle cell is the boat's.
const WATER_CELLS: i32 = 7;

/// The water grid's first vertex, in world cells, for a boat at `boat`,
/// as the chapter's `grid_origin` snaps it: the boat's cell less half the grid.
fn water_grid_origin(boat: Vec2) -> Vec2 {
    boat.floor() - ((WATER_CELLS - 1) / 2) as f32
}

/// The water grid from `first`: its lines `width` wide in `line`, and its
/// vertices as dots of radius `dot` in `colour`.
fn draw_water_grid(svg: &mut Svg, view: &TopView, first: Vec2, (line, width): (&str, f32), (colour, dot): (&str, f32)) {
    let n = WATER_CELLS as f32;
    for k in 0..=WATER_CELLS {
        let k = k as f32;
        svg.line(view.at(first + Vec2::new(k, 0.0)), view.at(first + Vec2::new(k, n)), line, width);
        svg.line(view.at(first + Vec2::new(0.0, k)), view.at(first + Vec2::new(n, k)), line, width);
    }
    for i in 0..=WATER_CELLS {
        for j in 0..=WATER_CELLS {
            svg.circle(view.at(first + Vec2::new(i as f32, j as f32)), dot, colour);
        }
    }
}

/// A small boat, its bow to the right, `cell` pixels a cell.
fn draw_boat(svg: &mut Svg, centre: Vec2, cell: f32, colour: &str) {
    let hull = [(-0.55, -0.2), (0.2, -0.2), (0.6, 0.0), (0.2, 0.2), (-0.55, 0.2)];
    let points: Vec<Vec2> = hull.iter().map(|&(x, y)| centre + Vec2::new(x, y) * cell).collect();
    svg.polygon(&points, colour, "#ffffff");
}

/// Chapter 11: the sea's grid follows the boat in whole cells
/// (`grid_origin` with `snap`), so its vertices sit on the same world
/// points, and waves fixed in the world stay put. Beside it, the grid
/// moved by the boat's own step: its vertices fall between the points.
fn moving_grid() -> String {
    let mut svg = Svg::new(640.0, 410.0);
    let view = TopView { corner: Vec2::new(20.0, 80.0), cell: 26.0, from: Vec2::ZERO, cells: Vec2::new(13.0, 10.0) };
    let (before, after) = (Vec2::new(5.3, 5.5), Vec2::new(6.7, 5.5));
    let before_band = "#a9c3e6";
    view.draw_world(&mut svg);
    // The cell each boat is in: the water grid's middle cell.
    for (boat, fill) in [(before, SITE_FILLS[1]), (after, SITE_FILLS[0])] {
        let cell = view.at(boat.floor());
        svg.rect(cell.x, cell.y, view.cell, view.cell, fill, "none");
    }
    // Before, wide and pale; after, thin on top: where they share a line
    // or a vertex, the world point is the same.
    draw_water_grid(&mut svg, &view, water_grid_origin(before), (before_band, 5.0), (BLUE, 4.0));
    draw_water_grid(&mut svg, &view, water_grid_origin(after), (ACCENT, 1.5), (ACCENT, 2.0));
    draw_boat(&mut svg, view.at(before), view.cell, BLUE);
    draw_boat(&mut svg, view.at(after), view.cell, ACCENT);
    let step = before.y - 0.95;
    svg.arrow(view.at(Vec2::new(before.x, step)), view.at(Vec2::new(after.x, step)), INK);
    let label = view.at(Vec2::new((before.x + after.x) / 2.0, step - 0.25));
    svg.rect(label.x - 24.0, label.y - 10.0, 48.0, 13.0, PAPER, "none");
    svg.text(label, "1.4 cells", 10.0, "middle", INK);
    svg.text(view.corner + Vec2::new(0.0, -10.0), "from above: the world's cells and wave crests", 12.0, "start", INK);
    let legend = view.corner + Vec2::new(0.0, view.size().y + 24.0);
    for (i, (boat, colour)) in [(before, BLUE), (after, ACCENT)].into_iter().enumerate() {
        let at = legend + Vec2::new(0.0, 18.0 * i as f32);
        let (line, width, dot) = if i == 0 { (before_band, 5.0, 4.0) } else { (ACCENT, 1.5, 2.0) };
        svg.line(at + Vec2::new(0.0, -4.0), at + Vec2::new(24.0, -4.0), line, width);
        svg.circle(at + Vec2::new(12.0, -4.0), dot, colour);
        let name = if i == 0 { "before" } else { "after" };
        let first = water_grid_origin(boat).x;
        let last = first + (WATER_CELLS - 1) as f32;
        let text = format!(
            "{name}: the boat at x = {}, in cell {}; the grid on cells {first} to {last}",
            trim(boat.x),
            boat.x.floor()
        );
        svg.text(at + Vec2::new(32.0, 0.0), &text, 11.0, "start", colour);
    }
    // The inset: the same step, with the grid moved by exactly the boat's 1.4 cells.
    let inset =
        TopView { corner: Vec2::new(410.0, 80.0), cell: 28.0, from: Vec2::new(3.0, 2.0), cells: Vec2::splat(7.0) };
    let size = inset.size();
    svg.text(inset.corner + Vec2::new(0.0, -10.0), "the wrong way: moved 1.4 cells", 12.0, "start", INK);
    inset.draw_world(&mut svg);
    svg.clip(inset.corner.x, inset.corner.y, size.x, size.y);
    let moved = water_grid_origin(before) + (after - before);
    draw_water_grid(&mut svg, &inset, moved, (ACCENT, 1.5), ("#ffffff", 3.2));
    for i in 0..=WATER_CELLS {
        for j in 0..=WATER_CELLS {
            svg.ring(inset.at(moved + Vec2::new(i as f32, j as f32)), 3.2, ACCENT, 1.4);
        }
    }
    svg.unclip();
    svg.rect(inset.corner.x, inset.corner.y, size.x, size.y, "none", MUTED);
    draw_boat(&mut svg, inset.at(after), inset.cell, ACCENT);
    let lines = [
        "its vertices fall between the world's",
        "points: each frame they sample the",
        "waves at new places, and the waves",
        "seem to swim along with the boat",
    ];
    for (k, line) in lines.iter().enumerate() {
        svg.text(inset.corner + Vec2::new(0.0, size.y + 20.0 + 15.0 * k as f32), line, 11.0, "start", INK);
    }
    svg.text(
        Vec2::new(20.0, 24.0),
        "The grid follows the boat in whole cells: every vertex lands on a world point where the height",
        11.0,
        "start",
        INK,
    );
    svg.text(Vec2::new(20.0, 40.0), "was already defined — nothing swims.", 11.0, "start", INK);
    svg.finish()
}

/// Every diagram, as (file name, SVG text).
pub fn all() -> Vec<(&'static str, String)> {
    vec![
        ("clip-space.svg", clip_space()),
        ("frustum-side.svg", frustum_side()),
        ("depth-precision.svg", depth_precision()),
        ("fbm-octaves.svg", fbm_octaves()),
        ("frustum-culling.svg", frustum_culling()),
        ("fog-curve.svg", fog_curve()),
        ("instancing-buffers.svg", instancing_buffers()),
        ("sun-path.svg", sun_path()),
        ("mirrored-camera.svg", mirrored_camera()),
        ("projective-texturing.svg", projective_texturing()),
        ("light-falloff.svg", light_falloff()),
        ("spot-cone.svg", spot_cone()),
        ("half-vector.svg", half_vector()),
        ("clusters.svg", clusters_side()),
        ("bloom-chain.svg", bloom_chain()),
        ("tangent-from-uvs.svg", tangent_from_uvs()),
        ("texel-footprint.svg", texel_footprint()),
        ("footprints.svg", footprints()),
        ("srgb-curve.svg", srgb_curve()),
        ("shadow-acne.svg", shadow_acne()),
        ("voronoi-cones.svg", voronoi_cones()),
        ("jump-flooding.svg", jump_flooding()),
        ("moving-grid.svg", moving_grid()),
    ]
}
