//! Chapter 05's figure: the two vertex buffers of an instanced draw, one
//! stepping per vertex and one per instance.

use common::glam::Vec2;

use crate::kit::{INK, Svg};

/// Chapter 05: two vertex buffers, one stepping per vertex, one per
/// instance, with the vertices of `instancing::rock_mesh` (every seed's
/// rock has as many) and the bytes of `instancing::RockInstance`.
pub fn instancing_buffers() -> String {
    let vertices = instancing::rock_mesh(0).vertices.len();
    let bytes = std::mem::size_of::<instancing::RockInstance>();
    let mut svg = Svg::new(640.0, 280.0);
    let mesh = format!("buffer 0: the rock mesh, step_mode Vertex ({vertices} vertices)");
    svg.text(Vec2::new(20.0, 28.0), &mesh, 12.0, "start", INK);
    for i in 0..10 {
        let x = 20.0 + i as f32 * 44.0;
        svg.rect(x, 38.0, 40.0, 26.0, "#e9e1d6", INK);
        svg.text(Vec2::new(x + 20.0, 56.0), &if i < 9 { format!("v{i}") } else { "…".into() }, 11.0, "middle", INK);
    }
    let rocks = format!("buffer 1: rocks, step_mode Instance ({bytes} bytes each)");
    svg.text(Vec2::new(20.0, 98.0), &rocks, 12.0, "start", INK);
    for i in 0..4 {
        let x = 20.0 + i as f32 * 110.0;
        svg.rect(x, 108.0, 104.0, 26.0, "#e7b48f", INK);
        let label = if i < 3 { format!("rock {i}") } else { "…".into() };
        svg.text(Vec2::new(x + 52.0, 126.0), &label, 11.0, "middle", INK);
    }
    svg.text(
        Vec2::new(20.0, 172.0),
        &format!("draw_indexed(0..{vertices}, 0, 0..n): the vertex shader runs for every pair"),
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
