//! Chapter 04's figure: visibility against distance for the chapter's fogs.

use common::glam::Vec2;

use crate::kit::{ACCENT, Axes, BLUE, MUTED, Svg};

/// Chapter 04: visibility against distance for the chapter's fogs, the
/// distance axis long enough to mark where each becomes opaque.
pub fn fog_curve() -> String {
    use fog::FogSettings;
    let mut svg = Svg::new(640.0, 320.0);
    let plain = FogSettings { density: FogSettings::HAZE.density, gradient: 1.0 };
    let fogs = [
        (FogSettings::HAZE, BLUE, "haze"),
        (plain, MUTED, "plain exponential"),
        (FogSettings::DUST_STORM, ACCENT, "dust storm"),
    ];
    // Whole kilometres, past the farthest opaque distance.
    let farthest = fogs.iter().map(|(fog, ..)| fog.opaque_distance()).fold(0.0, f32::max);
    let end = (farthest / 1000.0).ceil() * 1000.0;
    let axes = Axes { origin: Vec2::new(70.0, 40.0), size: Vec2::new(500.0, 210.0), x: (0.0, end), y: (0.0, 1.0) };
    let ticks: Vec<f32> = (0..=(end / 1000.0) as u32).map(|k| k as f32 * 1000.0).collect();
    axes.draw(&mut svg, &ticks, &[0.0, 0.37, 1.0], "distance (m)", "visibility");
    for (i, (fog, colour, name)) in fogs.iter().enumerate() {
        axes.curve(&mut svg, |d| fog.visibility(d), colour, 2.0);
        let opaque = fog.opaque_distance();
        let p = axes.at(opaque, 0.0);
        svg.line(p, p - Vec2::new(0.0, 14.0), colour, 2.0);
        svg.text(p - Vec2::new(0.0, 18.0), &format!("{opaque:.0} m"), 10.0, "middle", colour);
        let label = format!("{name}: density {}, gradient {}", fog.density, fog.gradient);
        svg.text(Vec2::new(330.0, 60.0 + 16.0 * i as f32), &label, 11.0, "start", colour);
    }
    svg.dashed(axes.at(0.0, (-1f32).exp()), axes.at(end, (-1f32).exp()), "#c9c2b6");
    svg.text(Vec2::new(330.0, 118.0), "ticks: the opaque distance, below 1/255", 10.0, "start", MUTED);
    svg.finish()
}
