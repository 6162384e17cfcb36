//! Chapter 01's figure: clip space, and where the triangle's corners land
//! in a picture.

use common::glam::Vec2;

use crate::kit::{Axes, INK, MUTED, Svg, trim};

/// Chapter 01: clip space, and where its corners land in a picture.
pub fn clip_space() -> String {
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
