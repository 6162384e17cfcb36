//! Chapter 06's figure: the sun's height through a day and how much day
//! sky shows, from the chapter's `sun_at` and `day_blend`.

use common::glam::Vec2;

use crate::kit::{ACCENT, Axes, BLUE, INK, Svg};

/// Chapter 06: the sun's height through a day, and how much day sky shows,
/// from `skybox::sun_at` and `day_blend`.
pub fn sun_path() -> String {
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
