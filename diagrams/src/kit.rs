//! The SVG kit every figure is drawn with: the [`Svg`] builder, the
//! colours, [`Axes`] for plots, and small helpers shared between chapters.

use std::fmt::Write as _;

use common::glam::Vec2;

/// Colours that read on the book's light and dark themes alike: every
/// diagram has its own pale background.
pub const INK: &str = "#1f2430";
pub const MUTED: &str = "#7a8194";
pub const ACCENT: &str = "#c0532b";
pub const BLUE: &str = "#2f6db3";
pub const PAPER: &str = "#fbf8f3";

/// A small SVG document.
pub struct Svg {
    width: f32,
    height: f32,
    body: String,
}

impl Svg {
    pub fn new(width: f32, height: f32) -> Self {
        let mut svg = Self { width, height, body: String::new() };
        svg.rect(0.0, 0.0, width, height, PAPER, "none");
        svg
    }

    pub fn line(&mut self, a: Vec2, b: Vec2, stroke: &str, width: f32) {
        let _ = writeln!(
            self.body,
            r#"<line x1="{:.1}" y1="{:.1}" x2="{:.1}" y2="{:.1}" stroke="{stroke}" stroke-width="{width}"/>"#,
            a.x, a.y, b.x, b.y
        );
    }

    pub fn dashed(&mut self, a: Vec2, b: Vec2, stroke: &str) {
        let _ = writeln!(
            self.body,
            r#"<line x1="{:.1}" y1="{:.1}" x2="{:.1}" y2="{:.1}" stroke="{stroke}" stroke-width="1.2" stroke-dasharray="5 4"/>"#,
            a.x, a.y, b.x, b.y
        );
    }

    pub fn arrow(&mut self, a: Vec2, b: Vec2, stroke: &str) {
        self.line(a, b, stroke, 1.6);
        let d = (b - a).normalize_or_zero();
        let side = Vec2::new(-d.y, d.x);
        let (p, q) = (b - d * 9.0 + side * 4.5, b - d * 9.0 - side * 4.5);
        self.polygon(&[b, p, q], stroke, "none");
    }

    pub fn polyline(&mut self, points: &[Vec2], stroke: &str, width: f32) {
        let list: Vec<String> = points.iter().map(|p| format!("{:.1},{:.1}", p.x, p.y)).collect();
        let _ = writeln!(
            self.body,
            r#"<polyline points="{}" fill="none" stroke="{stroke}" stroke-width="{width}" stroke-linejoin="round"/>"#,
            list.join(" ")
        );
    }

    /// Only what falls inside the rectangle (x, y, w, h) of what is drawn
    /// after this, until `unclip`.
    pub fn clip(&mut self, x: f32, y: f32, w: f32, h: f32) {
        let _ = writeln!(
            self.body,
            r#"<clipPath id="c{x:.0}{y:.0}"><rect x="{x:.1}" y="{y:.1}" width="{w:.1}" height="{h:.1}"/></clipPath><g clip-path="url(#c{x:.0}{y:.0})">"#
        );
    }

    pub fn unclip(&mut self) {
        self.body.push_str("</g>\n");
    }

    pub fn polygon(&mut self, points: &[Vec2], fill: &str, stroke: &str) {
        let list: Vec<String> = points.iter().map(|p| format!("{:.1},{:.1}", p.x, p.y)).collect();
        let _ = writeln!(self.body, r#"<polygon points="{}" fill="{fill}" stroke="{stroke}"/>"#, list.join(" "));
    }

    pub fn rect(&mut self, x: f32, y: f32, w: f32, h: f32, fill: &str, stroke: &str) {
        let _ = writeln!(
            self.body,
            r#"<rect x="{x:.1}" y="{y:.1}" width="{w:.1}" height="{h:.1}" fill="{fill}" stroke="{stroke}"/>"#
        );
    }

    pub fn circle(&mut self, c: Vec2, r: f32, fill: &str) {
        let _ = writeln!(self.body, r#"<circle cx="{:.1}" cy="{:.1}" r="{r}" fill="{fill}"/>"#, c.x, c.y);
    }

    /// A circle's outline.
    pub fn ring(&mut self, c: Vec2, r: f32, stroke: &str, width: f32) {
        let _ = writeln!(
            self.body,
            r#"<circle cx="{:.1}" cy="{:.1}" r="{r:.1}" fill="none" stroke="{stroke}" stroke-width="{width}"/>"#,
            c.x, c.y
        );
    }

    pub fn dashed_ring(&mut self, c: Vec2, r: f32, stroke: &str) {
        let _ = writeln!(
            self.body,
            r#"<circle cx="{:.1}" cy="{:.1}" r="{r:.1}" fill="none" stroke="{stroke}" stroke-width="1.2" stroke-dasharray="5 4"/>"#,
            c.x, c.y
        );
    }

    /// Text at `at`; `anchor` is start, middle or end.
    pub fn text(&mut self, at: Vec2, text: &str, size: f32, anchor: &str, fill: &str) {
        let escaped = text.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;");
        let _ = writeln!(
            self.body,
            r#"<text x="{:.1}" y="{:.1}" font-size="{size}" text-anchor="{anchor}" fill="{fill}">{escaped}</text>"#,
            at.x, at.y
        );
    }

    pub fn finish(self) -> String {
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
pub struct Axes {
    pub origin: Vec2,
    pub size: Vec2,
    pub x: (f32, f32),
    pub y: (f32, f32),
}

impl Axes {
    pub fn at(&self, x: f32, y: f32) -> Vec2 {
        let u = (x - self.x.0) / (self.x.1 - self.x.0);
        let v = (y - self.y.0) / (self.y.1 - self.y.0);
        Vec2::new(self.origin.x + u * self.size.x, self.origin.y + self.size.y - v * self.size.y)
    }

    /// The frame, with tick labels at `xs` and `ys`.
    pub fn draw(&self, svg: &mut Svg, xs: &[f32], ys: &[f32], x_label: &str, y_label: &str) {
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

    pub fn curve(&self, svg: &mut Svg, f: impl Fn(f32) -> f32, stroke: &str, width: f32) {
        let points: Vec<Vec2> = (0..=200)
            .map(|i| {
                let x = self.x.0 + (self.x.1 - self.x.0) * i as f32 / 200.0;
                self.at(x, f(x).clamp(self.y.0, self.y.1))
            })
            .collect();
        svg.polyline(&points, stroke, width);
    }
}

/// `value` with at most two decimals, less trailing zeros: 0.25, 1.4, 2.
pub fn trim(value: f32) -> String {
    let text = format!("{value:.2}");
    text.trim_end_matches('0').trim_end_matches('.').to_string()
}

impl Svg {
    /// A picture placed in the rectangle (x, y, w, h), embedded as a PNG,
    /// each texel drawn as a sharp square (no smoothing when enlarged).
    pub fn image(&mut self, x: f32, y: f32, w: f32, h: f32, picture: &common::image::RgbaImage) {
        let mut png = Vec::new();
        picture
            .write_to(&mut std::io::Cursor::new(&mut png), common::image::ImageFormat::Png)
            .expect("a picture in memory encodes as PNG");
        let _ = writeln!(
            self.body,
            r#"<image x="{x:.1}" y="{y:.1}" width="{w:.1}" height="{h:.1}" preserveAspectRatio="none" style="image-rendering: pixelated" href="data:image/png;base64,{}"/>"#,
            base64(&png)
        );
    }
}

/// Standard base64 (RFC 4648, with padding), for pictures inside an SVG.
fn base64(bytes: &[u8]) -> String {
    const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let n = chunk.iter().enumerate().fold(0u32, |n, (i, &b)| n | u32::from(b) << (16 - 8 * i));
        for i in 0..4 {
            if i <= chunk.len() {
                out.push(ALPHABET[(n >> (18 - 6 * i) & 63) as usize] as char);
            } else {
                out.push('=');
            }
        }
    }
    out
}
