//! Chapter 10's figure: shadow acne, and the slope-scaled bias that ends it.

use common::glam::Vec2;

use crate::kit::{ACCENT, BLUE, INK, MUTED, Svg};

/// Chapter 10: shadow acne. The light looks down; each shadow-map texel
/// stores the depth of the surface at its centre, a flat step. Along a
/// sloped surface, half of every texel lies deeper than its step and
/// shadows itself; a bias of half a texel's depth change moves every step
/// below the surface.
pub fn shadow_acne() -> String {
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
