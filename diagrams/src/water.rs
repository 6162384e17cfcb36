//! Chapter 07's figures: the camera mirrored in the water, and projective
//! texturing from a fragment's clip position.

use common::Camera;
use common::glam::{Vec2, Vec3};

use crate::kit::{ACCENT, Axes, BLUE, INK, MUTED, Svg};

/// Chapter 07: the camera mirrored in the water, by `water::mirrored`.
pub fn mirrored_camera() -> String {
    let mut svg = Svg::new(640.0, 320.0);
    let level = 160.0;
    svg.rect(0.0, level, 640.0, 160.0, "#dbe7ef", "none");
    svg.line(Vec2::new(0.0, level), Vec2::new(640.0, level), BLUE, 2.0);
    svg.text(Vec2::new(620.0, level + 18.0), "water level", 11.0, "end", BLUE);
    let eye = Vec2::new(90.0, level - 80.0);
    // The chapter's mirroring, in the picture's coordinates: y′ = 2·level − y
    // reads the same with y down.
    let camera = Camera::looking_at(Vec3::new(eye.x, eye.y, 0.0), Vec3::new(eye.x + 1.0, eye.y, 0.0), 1.0);
    let mirror = Vec2::new(eye.x, water::mirrored(&camera, level).position.y);
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
pub fn projective_texturing() -> String {
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
