//! Chapter 05's figures: the two vertex buffers of an instanced draw, one
//! stepping per vertex and one per instance; the rocks culled on the GPU,
//! from the compute pass to the indirect draws; and a tiny triangle in its
//! quad of pixels.

use common::glam::Vec2;

use instancing::WORKGROUP_SIZE as WORKGROUP;

use crate::kit::{ACCENT, BLUE, INK, MUTED, PAPER, Svg};

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

/// Chapter 05: the rocks culled on the GPU, from the buffer of every rock
/// through the compute pass into three lists and three indirect draws,
/// and across the barrier into the render pass. The counts come from the
/// chapter: the rocks, the workgroup size, the dispatch, the triangles of
/// each level, and WebGPU's alignment for storage offsets.
pub fn culling_flow() -> String {
    let rocks = instancing::MAX_ROCKS;
    let bytes = std::mem::size_of::<instancing::RockInstance>();
    let limits = common::wgpu::Limits::default();
    let (x, y) = instancing::rock_culling::dispatch_size(rocks, limits.max_compute_workgroups_per_dimension);
    let triangles = instancing::rock_levels(instancing::SEED).map(|mesh| mesh.indices.len() / 3);
    let colours = ["#d9735a", "#e3c15a", "#6d8fd6"];
    let names = ["full rock", "octahedron", "tetrahedron"];
    let mut svg = Svg::new(740.0, 360.0);
    let thousands = |n: u32| common::book_figures::thousands(n.into());

    // Every rock, a storage buffer.
    let every = format!("rocks: {} × {bytes} bytes (storage, read)", thousands(rocks));
    svg.text(Vec2::new(20.0, 26.0), &every, 12.0, "start", INK);
    for i in 0..14 {
        svg.rect(20.0 + i as f32 * 22.0, 36.0, 20.0, 18.0, "#e7b48f", INK);
    }
    svg.text(Vec2::new(334.0, 50.0), "…", 12.0, "start", INK);

    // The compute pass: workgroups of invocations, one per rock.
    svg.rect(20.0, 74.0, 370.0, 126.0, "#f3ece2", MUTED);
    svg.text(Vec2::new(30.0, 92.0), "compute pass: cull_rocks", 12.0, "start", INK);
    let dispatch = format!("dispatch_workgroups({}, {y}, 1)", thousands(x));
    svg.text(Vec2::new(30.0, 110.0), &dispatch, 11.0, "start", INK);
    let invocations = format!("= {} invocations, {WORKGROUP} to a workgroup", thousands(x * y * WORKGROUP));
    svg.text(Vec2::new(30.0, 124.0), &invocations, 11.0, "start", INK);
    for group in 0..5 {
        let gx = 30.0 + group as f32 * 70.0;
        svg.rect(gx, 134.0, 64.0, 26.0, PAPER, MUTED);
        for lane in 0..8 {
            let lx = gx + 4.0 + lane as f32 * 7.5;
            svg.line(Vec2::new(lx, 139.0), Vec2::new(lx, 155.0), BLUE, 1.4);
        }
    }
    svg.text(Vec2::new(30.0, 178.0), "each invocation tests one rock; one it keeps", 11.0, "start", INK);
    svg.text(Vec2::new(30.0, 192.0), "gets a slot in its level's list by atomicAdd", 11.0, "start", ACCENT);
    svg.arrow(Vec2::new(150.0, 56.0), Vec2::new(150.0, 73.0), INK);

    // The lists (one buffer, three aligned regions) and the draws.
    let align = limits.min_storage_buffer_offset_alignment;
    svg.text(Vec2::new(20.0, 226.0), "lists: one buffer, a region per level,", 12.0, "start", INK);
    svg.text(Vec2::new(20.0, 241.0), &format!("each at a multiple of {align} bytes"), 12.0, "start", INK);
    for (level, colour) in colours.iter().enumerate() {
        let left = 20.0 + level as f32 * 122.0;
        svg.rect(left, 250.0, 118.0, 20.0, PAPER, INK);
        svg.rect(left, 250.0, [20.0, 46.0, 100.0][level], 20.0, colour, INK);
    }
    svg.text(Vec2::new(20.0, 296.0), "draws: per level (index count, instances, 0, 0, 0)", 12.0, "start", INK);
    for (level, colour) in colours.iter().enumerate() {
        let left = 20.0 + level as f32 * 122.0;
        svg.rect(left, 304.0, 118.0, 20.0, colour, INK);
        svg.text(
            Vec2::new(left + 59.0, 318.0),
            &format!("{}, n{level}, 0, 0, 0", 3 * triangles[level]),
            10.0,
            "middle",
            INK,
        );
    }
    svg.arrow(Vec2::new(370.0, 201.0), Vec2::new(370.0, 248.0), ACCENT);

    // The barrier, then the render pass.
    svg.dashed(Vec2::new(405.0, 20.0), Vec2::new(405.0, 330.0), ACCENT);
    svg.text(Vec2::new(412.0, 348.0), "barrier: the draws wait for every write", 11.0, "start", ACCENT);
    svg.rect(420.0, 74.0, 300.0, 250.0, "#f3ece2", MUTED);
    svg.text(Vec2::new(430.0, 92.0), "render pass: one indirect draw per level", 12.0, "start", INK);
    for (level, colour) in colours.iter().enumerate() {
        let top = 106.0 + level as f32 * 70.0;
        svg.rect(430.0, top, 280.0, 58.0, PAPER, colour);
        let draw = format!("draw_indexed_indirect(draws, {})", level * 20);
        svg.text(Vec2::new(440.0, top + 18.0), &draw, 11.0, "start", INK);
        svg.text(
            Vec2::new(440.0, top + 34.0),
            &format!("{}: {} triangles", names[level], triangles[level]),
            10.0,
            "start",
            INK,
        );
        svg.text(
            Vec2::new(440.0, top + 49.0),
            &format!("rock = rocks[list{level}[instance_index]]"),
            10.0,
            "start",
            INK,
        );
    }
    svg.arrow(Vec2::new(386.0, 314.0), Vec2::new(428.0, 300.0), INK);
    svg.finish()
}

/// Chapter 05: why a tiny triangle is dear. Pixel shaders run in 2 × 2
/// quads, so a triangle that covers one pixel's centre runs four
/// invocations; three are helpers whose colours are thrown away.
pub fn pixel_quads() -> String {
    let mut svg = Svg::new(640.0, 230.0);
    let cell = 40.0;
    let (left, top) = (30.0, 30.0);
    for row in 0..4 {
        for column in 0..4 {
            let (x, y) = (left + column as f32 * cell, top + row as f32 * cell);
            svg.rect(x, y, cell, cell, PAPER, MUTED);
            svg.circle(Vec2::new(x + cell / 2.0, y + cell / 2.0), 2.0, MUTED);
        }
    }
    // The quad the triangle lands in, and the triangle: over one pixel centre.
    svg.rect(left + cell, top + cell, 2.0 * cell, 2.0 * cell, "none", ACCENT);
    for (column, row, shaded) in [(1, 1, true), (2, 1, false), (1, 2, false), (2, 2, false)] {
        let (x, y) = (left + column as f32 * cell, top + row as f32 * cell);
        svg.rect(x + 3.0, y + 3.0, cell - 6.0, cell - 6.0, if shaded { "#e7b48f" } else { "#efe2d3" }, "none");
        svg.circle(Vec2::new(x + cell / 2.0, y + cell / 2.0), 2.5, INK);
    }
    let corners =
        [Vec2::new(left + 52.0, top + 50.0), Vec2::new(left + 76.0, top + 56.0), Vec2::new(left + 58.0, top + 74.0)];
    svg.polygon(&corners, BLUE, INK);
    let lines = [
        "A triangle about a pixel big covers one pixel centre.",
        "The GPU shades pixels in 2 × 2 quads (so that a shader",
        "can compare neighbours: the slopes that pick a mip level),",
        "so it runs four fragment invocations: one for the pixel,",
        "three helpers whose colours it throws away.",
        "",
        "A triangle that covers no centre draws nothing, and the",
        "rasteriser has still spent its time setting it up.",
    ];
    for (i, line) in lines.iter().enumerate() {
        svg.text(Vec2::new(220.0, 44.0 + i as f32 * 18.0), line, 12.0, "start", INK);
    }
    svg.finish()
}
