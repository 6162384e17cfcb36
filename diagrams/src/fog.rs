//! Chapter 04's figure: visibility against distance for the chapter's fogs.

use common::glam::Vec2;

use crate::kit::{ACCENT, Axes, BLUE, MUTED, Svg};

/// Chapter 04: visibility against distance for the chapter's fogs.
pub fn fog_curve() -> String {
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
