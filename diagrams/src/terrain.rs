//! Chapter 03's figures: octaves of Perlin noise and their sum, and the
//! chunks a camera's frustum keeps, from the chapter's noise and culling.

use common::Camera;
use common::glam::{Vec2, Vec3};

use crate::kit::{ACCENT, Axes, INK, MUTED, Svg};

/// Chapter 03: octaves of Perlin noise and their sum, from the chapter's noise.
pub fn fbm_octaves() -> String {
    use terrain::noise::{Fbm, perlin3};
    let mut svg = Svg::new(640.0, 430.0);
    let fbm = Fbm { octaves: 4, persistence: 0.5, lacunarity: 2.0 };
    let row = |i: usize, height: f32| Axes {
        origin: Vec2::new(30.0, 34.0 + i as f32 * 74.0),
        size: Vec2::new(580.0, height),
        x: (0.0, 4.0),
        y: (-0.6, 0.6),
    };
    // Octave o is at lacunarity^o times the frequency and persistence^o
    // times the height, on the same slice as `Fbm::sample` takes it: x and
    // y both scaled by the frequency, z left alone. So the rows add up to
    // the sum below.
    let octave_scale = |factor: f64, octave: u32| factor.powi(octave as i32) as f32;
    let (y, z) = (0.5, 0.5);
    for octave in 0..fbm.octaves {
        let axes = row(octave as usize, 50.0);
        let (frequency, amplitude) = (octave_scale(fbm.lacunarity, octave), octave_scale(fbm.persistence, octave));
        svg.line(axes.at(0.0, 0.0), axes.at(4.0, 0.0), "#e3dccf", 1.0);
        let f = f64::from(frequency);
        axes.curve(&mut svg, |x| amplitude * perlin3(f64::from(x) * f, y * f, z) as f32, MUTED, 1.6);
        let label = format!("octave {}: frequency ×{frequency}, height ×{amplitude}", octave + 1);
        svg.text(axes.origin - Vec2::new(0.0, 6.0), &label, 11.0, "start", INK);
    }
    // The sum of the rows above; `Fbm::sample` divides it by the sum of the
    // heights, 1 + ½ + ¼ + ⅛.
    let total: f32 = (0..fbm.octaves).map(|o| octave_scale(fbm.persistence, o)).sum();
    let sum = row(fbm.octaves as usize, 80.0);
    svg.line(sum.at(0.0, 0.0), sum.at(4.0, 0.0), "#e3dccf", 1.0);
    sum.curve(&mut svg, |x| fbm.sample(f64::from(x), y, z) as f32 * total, ACCENT, 2.2);
    svg.text(sum.origin - Vec2::new(0.0, 6.0), "their sum: hills on hills (fBm)", 11.0, "start", ACCENT);
    svg.finish()
}

/// Chapter 03: which chunks a camera's frustum keeps, seen from above,
/// computed with the chapter's `Frustum` on a 16 × 16 grid of 64 m chunks.
pub fn frustum_culling() -> String {
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

/// Chapter 03: the patches the quadtree chooses around a camera, seen from
/// above, a colour per level, with the ranges where each level ends:
/// computed with the chapter's `Quadtree::select` on a flat 16 × 16 map.
pub fn lod_quadtree() -> String {
    use terrain::chunks::Aabb;
    use terrain::culling::Frustum;
    use terrain::quadtree::PATCH_QUADS;
    use terrain::{LodRanges, Quadtree};
    const LEVEL_FILLS: [&str; 5] = ["#e58a6f", "#efb46a", "#e9d77a", "#9ccb8a", "#8fbfd9"];
    let mut svg = Svg::new(640.0, 400.0);
    let (n, size, cell) = (16u32, 64.0f32, 22.0f32);
    let origin = Vec2::new(30.0, 20.0);
    let bounds: Vec<Aabb> = (0..n * n)
        .map(|i| {
            let min = Vec3::new((i % n) as f32 * size, -10.0, (i / n) as f32 * size);
            Aabb { min, max: min + Vec3::new(size, 30.0, size) }
        })
        .collect();
    let tree = Quadtree::new(&bounds, n);
    let eye = Vec3::new(5.5 * size, 20.0, 13.5 * size);
    let camera = Camera { far: 1400.0, ..Camera::looking_at(eye, eye + Vec3::new(0.55, -0.05, -1.0), 16.0 / 9.0) };
    let frustum = Frustum::from_view_projection(camera.view_projection());
    let first = LodRanges::nearest_first(tree.node_reach());
    let ranges =
        LodRanges { first, morph_start: LodRanges::morph_start(first, tree.node_reach()), top_level: tree.top_level() };
    let mut patches = Vec::new();
    tree.select(&frustum, eye, &ranges, &mut patches);
    let to_map = |x: f32, z: f32| origin + Vec2::new(x, z) / size * cell;
    svg.rect(origin.x, origin.y, n as f32 * cell, n as f32 * cell, "#e6e2da", "none");
    for p in &patches {
        let side = (PATCH_QUADS << p.level) as f32;
        let corner = to_map(p.origin[0] as f32, p.origin[1] as f32);
        svg.rect(corner.x, corner.y, side / size * cell, side / size * cell, LEVEL_FILLS[p.level as usize], "#ffffff");
    }
    svg.clip(origin.x, origin.y, n as f32 * cell, n as f32 * cell);
    for level in 0..3 {
        svg.dashed_ring(to_map(eye.x, eye.z), ranges.range(level) / size * cell, INK);
    }
    svg.unclip();
    let forward = Vec2::new(camera.forward().x, camera.forward().z).normalize();
    let half = (camera.fov_y / 2.0).tan() * camera.aspect;
    let side = Vec2::new(-forward.y, forward.x);
    let far_corner = |s: f32| to_map(eye.x, eye.z) + (forward + side * s * half) * camera.far / size * cell;
    svg.clip(origin.x, origin.y, n as f32 * cell, n as f32 * cell);
    svg.polygon(&[to_map(eye.x, eye.z), far_corner(1.0), far_corner(-1.0)], "none", ACCENT);
    svg.unclip();
    svg.circle(to_map(eye.x, eye.z), 5.0, INK);
    let legend = origin.x + n as f32 * cell + 24.0;
    for (level, fill) in LEVEL_FILLS.iter().enumerate().take(4) {
        let y = 30.0 + level as f32 * 24.0;
        svg.rect(legend, y, 16.0, 16.0, fill, "none");
        let cells = 1 << level;
        svg.text(Vec2::new(legend + 24.0, y + 13.0), &format!("level {level}: cells of {cells} m"), 12.0, "start", INK);
    }
    svg.rect(legend, 126.0, 16.0, 16.0, "#e6e2da", "none");
    svg.text(Vec2::new(legend + 24.0, 139.0), "culled: nothing drawn", 12.0, "start", INK);
    svg.dashed(Vec2::new(legend, 162.0), Vec2::new(legend + 16.0, 162.0), INK);
    svg.text(Vec2::new(legend + 24.0, 166.0), "where levels 0, 1, 2 end", 12.0, "start", INK);
    svg.line(Vec2::new(legend, 186.0), Vec2::new(legend + 16.0, 186.0), ACCENT, 1.5);
    svg.text(Vec2::new(legend + 24.0, 190.0), "the frustum, from above", 12.0, "start", INK);
    let lines = [
        format!("{} patches of 32 × 32 cells,", patches.len()),
        "each 2 048 triangles: the".to_string(),
        "farther, the larger the cells,".to_string(),
        "so on screen they stay".to_string(),
        "about the same size.".to_string(),
    ];
    for (i, line) in lines.iter().enumerate() {
        svg.text(Vec2::new(legend, 222.0 + 16.0 * i as f32), line, 11.0, "start", INK);
    }
    svg.finish()
}

/// Chapter 03: a row of a patch's vertices morphing into the next level:
/// each odd vertex slides onto its even neighbour, taking its height, until
/// the row is the coarser level's, vertex for vertex. Heights from the
/// chapter's noise.
pub fn lod_morph() -> String {
    use terrain::noise::perlin3;
    let mut svg = Svg::new(640.0, 330.0);
    let height = |x: f32| 2.2 * perlin3(f64::from(x) * 0.71 + 0.3, 0.5, 0.37) as f32;
    for (row, k) in [0.0f32, 0.5, 1.0].into_iter().enumerate() {
        let axes = Axes {
            origin: Vec2::new(40.0, 30.0 + row as f32 * 100.0),
            size: Vec2::new(560.0, 60.0),
            x: (0.0, 8.0),
            y: (-1.0, 1.0),
        };
        // Odd vertices slide back onto the even vertex before them: their
        // place and their height both move by k of the way.
        let vertex = |i: u32| {
            let x = i as f32;
            if i % 2 == 1 { (x - k, height(x) + (height(x - 1.0) - height(x)) * k) } else { (x, height(x)) }
        };
        let fine: Vec<Vec2> = (0..=8)
            .map(|i| {
                let (x, y) = vertex(i);
                axes.at(x, y)
            })
            .collect();
        let coarse: Vec<Vec2> = (0..=4).map(|i| axes.at(2.0 * i as f32, height(2.0 * i as f32))).collect();
        svg.polyline(&coarse, "#d9cfc0", 5.0);
        svg.polyline(&fine, ACCENT, 2.0);
        for i in 0..=8 {
            let (x, y) = vertex(i);
            let fill = if i % 2 == 1 { ACCENT } else { INK };
            svg.circle(axes.at(x, y), 4.0, fill);
        }
        let label = match row {
            0 => "k = 0: level L as it is (pale: level L + 1)".to_string(),
            1 => "k = 0.5: each odd vertex half way to its even neighbour".to_string(),
            _ => "k = 1: every odd vertex on its neighbour: level L + 1 exactly".to_string(),
        };
        svg.text(axes.origin - Vec2::new(0.0, 10.0), &label, 12.0, "start", INK);
    }
    svg.finish()
}
