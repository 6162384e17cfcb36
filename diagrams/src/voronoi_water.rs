//! Chapter 11's figures: the Voronoi diagram as cones and a depth test,
//! jump flooding pass by pass (with the chapter's `voronoi::jump_steps`),
//! the sea's grid following the boat in whole cells (the chapter's
//! `sea::grid_origin_for`), and the sail's swell (`sail::belly`).

use common::glam::Vec2;

use crate::kit::{ACCENT, BLUE, INK, MUTED, PAPER, Svg, trim};

/// Chapter 11's sites, each with a pale fill for its cell and a strong
/// colour for its lines.
const SITE_FILLS: [&str; 5] = ["#f6d5c0", "#cfe0f2", "#d6ebcf", "#f1e3a9", "#e2d5ef"];
const SITE_INKS: [&str; 5] = [ACCENT, BLUE, "#3f8f4e", "#b38b14", "#7c59a8"];

/// The part of the convex `polygon` nearer to `site` than to `other`: the
/// polygon clipped by their bisector.
fn clip_to_nearer(polygon: &[Vec2], site: Vec2, other: Vec2) -> Vec<Vec2> {
    let (middle, towards) = ((site + other) / 2.0, other - site);
    let beyond = |p: Vec2| (p - middle).dot(towards); // > 0: nearer to `other`
    let mut kept = Vec::new();
    for (i, &a) in polygon.iter().enumerate() {
        let b = polygon[(i + 1) % polygon.len()];
        let (da, db) = (beyond(a), beyond(b));
        if da <= 0.0 {
            kept.push(a);
        }
        if (da <= 0.0) != (db <= 0.0) {
            kept.push(a + (b - a) * (da / (da - db)));
        }
    }
    kept
}

/// Site `i`'s Voronoi cell inside the unit square: the square clipped by
/// its bisector with every other site, so its edges are exact.
fn voronoi_cell(sites: &[Vec2], i: usize) -> Vec<Vec2> {
    let square = vec![Vec2::ZERO, Vec2::X, Vec2::ONE, Vec2::Y];
    sites
        .iter()
        .enumerate()
        .filter(|&(j, _)| j != i)
        .fold(square, |cell, (_, &other)| clip_to_nearer(&cell, sites[i], other))
}

/// Which site is nearest to `p`.
fn nearest_site(sites: &[Vec2], p: Vec2) -> usize {
    (0..sites.len()).min_by(|&a, &b| p.distance(sites[a]).total_cmp(&p.distance(sites[b]))).unwrap_or(0)
}

/// Chapter 11: the Voronoi diagram as cones and a depth test (Hoff et al.
/// 1999). Left, from above: the cells, exact, and circles of equal radius
/// around two sites meeting on their shared edge. Right, a slice along the
/// dashed line through three sites: each site's cone, its depth the
/// distance to the site, and what the depth test keeps of them.
pub fn voronoi_cones() -> String {
    let mut svg = Svg::new(640.0, 360.0);
    // In the unit square, y down. The two sites off the slice lie farther
    // from it than any point of it from its own site, so that only the
    // slice's three sites' cones reach into the side view's depth range.
    let sites = [
        Vec2::new(0.14, 0.56),
        Vec2::new(0.46, 0.56),
        Vec2::new(0.84, 0.56),
        Vec2::new(0.66, 0.1),
        Vec2::new(0.62, 0.93),
    ];
    let slice = 0.56;
    let (origin, size) = (Vec2::new(30.0, 82.0), 250.0);
    let top = |p: Vec2| origin + p * size;
    svg.text(Vec2::new(origin.x, origin.y - 10.0), "seen from above", 12.0, "start", INK);
    for (i, fill) in (0..sites.len()).zip(SITE_FILLS) {
        svg.polygon(&voronoi_cell(&sites, i).into_iter().map(top).collect::<Vec<_>>(), fill, "#ffffff");
    }
    // Equal radii around the two left-hand sites meet on their bisector:
    // the same distance is the same cone height.
    svg.clip(origin.x, origin.y, size, size);
    let half = (sites[1].x - sites[0].x) / 2.0;
    for radius in [half, 0.22, 0.28] {
        for i in [0, 1] {
            svg.dashed_ring(top(sites[i]), radius * size, SITE_INKS[i]);
        }
        let rise = (radius * radius - half * half).max(0.0).sqrt();
        for y in [slice - rise, slice + rise] {
            let meeting = Vec2::new(sites[0].x + half, y);
            debug_assert!(nearest_site(&sites, meeting) < 2, "the circles meet on the two sites' edge");
            svg.circle(top(meeting), 2.5, INK);
        }
    }
    svg.unclip();
    svg.rect(origin.x, origin.y, size, size, "none", INK);
    svg.dashed(top(Vec2::new(0.0, slice)), top(Vec2::new(1.0, slice)), INK);
    svg.text(top(Vec2::new(1.0, slice)) + Vec2::new(-4.0, -6.0), "slice", 10.0, "end", INK);
    for (i, &site) in sites.iter().enumerate() {
        svg.circle(top(site), 4.5, "#ffffff");
        svg.circle(top(site), 3.2, SITE_INKS[i]);
    }
    // The side view: x as above, depth down at the same scale, so the
    // cones' sides fall at 45°.
    let (left, ground, depth_range) = (360.0, 150.0, 0.34);
    let side = |x: f32, depth: f32| Vec2::new(left + x * size, ground + depth * size);
    svg.text(Vec2::new(left, origin.y - 10.0), "seen from the side, along the slice", 12.0, "start", INK);
    for x in [0.2, 0.5, 0.8] {
        svg.arrow(side(x, -0.22), side(x, -0.08), MUTED);
    }
    svg.text(side(1.0, -0.24), "orthographic camera, looking down", 10.0, "end", MUTED);
    svg.clip(left, ground - 10.0, size, depth_range * size + 10.0);
    for i in 0..3 {
        let apex = side(sites[i].x, 0.0);
        let reach = depth_range + 0.05;
        svg.polyline(&[side(sites[i].x - reach, reach), apex, side(sites[i].x + reach, reach)], SITE_INKS[i], 0.8);
    }
    svg.unclip();
    svg.line(side(0.0, 0.0), side(1.0, 0.0), MUTED, 0.8);
    // What the camera sees along the slice: the nearest cone at each x,
    // one run per site, from all five sites.
    let samples = 500;
    let mut runs: Vec<(usize, Vec<Vec2>)> = Vec::new();
    for k in 0..=samples {
        let p = Vec2::new(k as f32 / samples as f32, slice);
        let owner = nearest_site(&sites, p);
        let point = side(p.x, p.distance(sites[owner]));
        match runs.last_mut() {
            Some((site, points)) if *site == owner => points.push(point),
            _ => runs.push((owner, vec![point])),
        }
    }
    let (strip, strip_height) = (ground + depth_range * size + 14.0, 14.0);
    for (site, points) in &runs {
        svg.polyline(points, SITE_INKS[*site], 3.2);
        let (a, b) = (points[0].x, points[points.len() - 1].x);
        svg.rect(a, strip, b - a, strip_height, SITE_FILLS[*site], "none");
    }
    svg.rect(left, strip, size, strip_height, "none", INK);
    // Where two cones cross, the visible surface changes site: a cell edge.
    for pair in runs.windows(2) {
        let (a, b) = (pair[0].1[pair[0].1.len() - 1], pair[1].1[0]);
        let crossing = (a + b) / 2.0;
        svg.dashed(crossing, Vec2::new(crossing.x, strip + strip_height), INK);
        svg.circle(crossing, 3.5, INK);
    }
    for (i, &site) in sites.iter().take(3).enumerate() {
        svg.circle(side(site.x, 0.0), 4.5, "#ffffff");
        svg.circle(side(site.x, 0.0), 3.2, SITE_INKS[i]);
    }
    svg.text(Vec2::new(left - 8.0, ground + 4.0), "0", 10.0, "end", MUTED);
    svg.text(Vec2::new(left - 8.0, ground + 18.0), "depth", 10.0, "end", MUTED);
    svg.arrow(Vec2::new(left - 22.0, ground + 26.0), Vec2::new(left - 22.0, ground + 60.0), MUTED);
    svg.text(
        Vec2::new(left + size / 2.0, strip + strip_height + 16.0),
        "the cells along the slice",
        10.0,
        "middle",
        INK,
    );
    svg.text(
        Vec2::new(left + size / 2.0, strip + strip_height + 40.0),
        "depth = distance to the site:",
        11.0,
        "middle",
        INK,
    );
    svg.text(
        Vec2::new(left + size / 2.0, strip + strip_height + 56.0),
        "the depth test keeps the nearest site",
        11.0,
        "middle",
        INK,
    );
    let key = Vec2::new(left, strip + strip_height + 82.0);
    svg.line(key + Vec2::new(0.0, -4.0), key + Vec2::new(20.0, -4.0), INK, 3.2);
    svg.text(key + Vec2::new(26.0, 0.0), "kept", 10.0, "start", INK);
    svg.line(key + Vec2::new(70.0, -4.0), key + Vec2::new(90.0, -4.0), INK, 0.8);
    svg.text(key + Vec2::new(96.0, 0.0), "behind a nearer cone", 10.0, "start", INK);
    svg.text(
        Vec2::new(20.0, 24.0),
        "Draw a cone under each site, its depth the distance to the site, and look down on them: at every pixel",
        11.0,
        "start",
        INK,
    );
    svg.text(
        Vec2::new(20.0, 40.0),
        "the depth test keeps the nearest cone, and so the nearest site. Cones cross where the distances are equal.",
        11.0,
        "start",
        INK,
    );
    svg.finish()
}

/// The side of the jump-flooding grid, in pixels.
const JFA_SIDE: usize = 16;
/// Seeds for the jump-flooding diagram, in pixels. Chosen (by trying
/// placements) so that no pixel is equally far from two seeds and jump
/// flooding gets a few pixels wrong: the seed at (12, 4) and its close
/// neighbour at (9, 6) take over pixels at the bottom that (4, 12) is
/// nearer to, before (4, 12)'s own news gets there.
const JFA_SEEDS: [(i32, i32); 3] = [(9, 6), (4, 12), (12, 4)];

/// Squared distance between pixel centres.
fn squared(a: (i32, i32), b: (i32, i32)) -> i32 {
    (a.0 - b.0).pow(2) + (a.1 - b.1).pow(2)
}

/// Each pixel's seed (an index into `JFA_SEEDS`), row by row.
type SeedMap = Vec<Option<usize>>;

/// The pixels `p` reads in a pass of step `k`: the nine k apart around it,
/// itself among them, less those outside the grid (no wrapping here).
fn jump_flood_reads(p: (i32, i32), k: i32) -> impl Iterator<Item = (i32, i32)> {
    let n = JFA_SIDE as i32;
    (-1..=1)
        .flat_map(move |j| (-1..=1).map(move |i| (p.0 + i * k, p.1 + j * k)))
        .filter(move |q| (0..n).contains(&q.0) && (0..n).contains(&q.1))
}

/// One pass of jump flooding with step `k`: each pixel keeps the seed
/// nearest to it among those of the pixels it reads.
fn jump_flood_pass(map: &SeedMap, k: i32) -> SeedMap {
    let n = JFA_SIDE as i32;
    (0..n * n)
        .map(|index| {
            let p = (index % n, index / n);
            jump_flood_reads(p, k)
                .filter_map(|q| map[(q.1 * n + q.0) as usize])
                .min_by_key(|&seed| squared(p, JFA_SEEDS[seed]))
        })
        .collect()
}

/// Chapter 11: jump flooding (Rong & Tan 2006) on a 16 × 16 grid, with the
/// chapter's steps (`voronoi::jump_steps`), computed here pass by pass,
/// against the exact nearest seed of every pixel.
pub fn jump_flooding() -> String {
    let n = JFA_SIDE as i32;
    let mut map: SeedMap = vec![None; JFA_SIDE * JFA_SIDE];
    for (i, &(x, y)) in JFA_SEEDS.iter().enumerate() {
        map[(y * n + x) as usize] = Some(i);
    }
    let mut panels = vec![("the seeds".to_string(), map.clone(), None)];
    // The chapter's steps for a 16 × 16 picture: 8, 4, 2, 1.
    for k in voronoi_water::voronoi::jump_steps(JFA_SIDE as u32, JFA_SIDE as u32, false) {
        let k = k as i32;
        map = jump_flood_pass(&map, k);
        panels.push((format!("k = {k}"), map.clone(), Some(k)));
    }
    let exact: SeedMap = (0..n * n)
        .map(|index| (0..JFA_SEEDS.len()).min_by_key(|&s| squared((index % n, index / n), JFA_SEEDS[s])))
        .collect();
    let wrong: Vec<(i32, i32)> =
        (0..n * n).filter(|&index| map[index as usize] != exact[index as usize]).map(|i| (i % n, i / n)).collect();
    panels.push(("exact nearest seed".to_string(), exact, None));
    let mut svg = Svg::new(640.0, 500.0);
    let cell = 10.0;
    // The pixel whose nine reads are drawn in every pass.
    let reader = (5, 5);
    for (number, (title, map, step)) in panels.iter().enumerate() {
        let corner = Vec2::new(40.0 + (number % 3) as f32 * 200.0, 86.0 + (number / 3) as f32 * 204.0);
        let centre = |(x, y): (i32, i32)| corner + (Vec2::new(x as f32, y as f32) + 0.5) * cell;
        let title = if number == 4 { format!("{title}: the result") } else { title.clone() };
        svg.text(corner + Vec2::new(0.0, -8.0), &title, 12.0, "start", INK);
        for (index, seed) in map.iter().enumerate() {
            let (x, y) = (index as i32 % n, index as i32 / n);
            let fill = seed.map_or("#ffffff", |s| SITE_FILLS[s]);
            svg.rect(corner.x + x as f32 * cell, corner.y + y as f32 * cell, cell, cell, fill, "#e4ddd2");
        }
        svg.rect(corner.x, corner.y, cell * n as f32, cell * n as f32, "none", INK);
        if let Some(k) = step {
            let p = centre(reader);
            for q in jump_flood_reads(reader, *k).filter(|&q| q != reader) {
                svg.line(p, centre(q), INK, 0.8);
                svg.ring(centre(q), 2.8, INK, 1.2);
            }
            svg.rect(p.x - cell / 2.0, p.y - cell / 2.0, cell, cell, "none", INK);
        }
        if number >= 4 {
            for &pixel in &wrong {
                let c = centre(pixel);
                let d = cell * 0.3;
                svg.line(c - Vec2::splat(d), c + Vec2::splat(d), INK, 1.4);
                svg.line(c + Vec2::new(-d, d), c + Vec2::new(d, -d), INK, 1.4);
            }
        }
        for (i, &seed) in JFA_SEEDS.iter().enumerate() {
            svg.circle(centre(seed), 4.0, "#ffffff");
            svg.circle(centre(seed), 3.0, SITE_INKS[i]);
        }
    }
    svg.text(
        Vec2::new(20.0, 24.0),
        "log₂ n passes: each pixel reads itself and 8 others at a step k that halves each pass, and keeps",
        11.0,
        "start",
        INK,
    );
    svg.text(
        Vec2::new(20.0, 40.0),
        "the nearest seed it finds among theirs. Here n = 16: four passes, k = 8, 4, 2, 1.",
        11.0,
        "start",
        INK,
    );
    let legend = Vec2::new(40.0, 470.0);
    svg.circle(legend, 4.0, SITE_INKS[0]);
    svg.text(legend + Vec2::new(10.0, 4.0), "a seed", 11.0, "start", INK);
    svg.rect(legend.x + 70.0, legend.y - 5.0, cell, cell, "none", INK);
    svg.ring(legend + Vec2::new(98.0, 0.0), 2.8, INK, 1.2);
    svg.text(legend + Vec2::new(108.0, 4.0), "a pixel and the 8 others it reads", 11.0, "start", INK);
    let cross = legend + Vec2::new(330.0, 0.0);
    svg.line(cross - Vec2::splat(3.0), cross + Vec2::splat(3.0), INK, 1.4);
    svg.line(cross + Vec2::new(-3.0, 3.0), cross + Vec2::new(3.0, -3.0), INK, 1.4);
    svg.text(cross + Vec2::new(10.0, 4.0), "JFA's error: the exact nearest seed differs", 11.0, "start", INK);
    svg.finish()
}

/// A top view of part of the world: the cells from `from`, `cells` of
/// them across and down, drawn from `corner` at `cell` pixels a cell.
struct TopView {
    corner: Vec2,
    cell: f32,
    from: Vec2,
    cells: Vec2,
}

impl TopView {
    /// Where a point of the world, in cells, is drawn.
    fn at(&self, world: Vec2) -> Vec2 {
        self.corner + (world - self.from) * self.cell
    }

    fn size(&self) -> Vec2 {
        self.cells * self.cell
    }

    /// The world in view: its cells as faint lines, its points as dots,
    /// and the crests of waves that stay where the world puts them.
    fn draw_world(&self, svg: &mut Svg) {
        let (corner, size) = (self.corner, self.size());
        svg.rect(corner.x, corner.y, size.x, size.y, "#eef4f8", "none");
        svg.clip(corner.x, corner.y, size.x, size.y);
        // Parallel, gently curved crests, in world units.
        for start in (-4..8).map(|c| c as f32 * 2.6) {
            let crest: Vec<Vec2> = (0..=80)
                .map(|k| {
                    let y = -1.0 + k as f32 / 80.0 * 12.0;
                    self.at(Vec2::new(start + 0.45 * y + 0.5 * (y * 0.6).sin(), y))
                })
                .collect();
            svg.polyline(&crest, "#c4ddd8", 4.0);
        }
        svg.unclip();
        let (first, last) = (self.from, self.from + self.cells);
        for x in first.x as i32..=last.x as i32 {
            svg.line(self.at(Vec2::new(x as f32, first.y)), self.at(Vec2::new(x as f32, last.y)), "#d5dde4", 1.0);
        }
        for y in first.y as i32..=last.y as i32 {
            svg.line(self.at(Vec2::new(first.x, y as f32)), self.at(Vec2::new(last.x, y as f32)), "#d5dde4", 1.0);
        }
        for x in first.x as i32..=last.x as i32 {
            for y in first.y as i32..=last.y as i32 {
                svg.circle(self.at(Vec2::new(x as f32, y as f32)), 1.6, "#9aa5b1");
            }
        }
    }
}

/// Cells along each side of the diagram's water grid: odd, so that its
/// middle cell is the boat's.
const WATER_CELLS: i32 = 7;

/// The water grid's first vertex, in world cells, for a boat `boat` cells
/// from the world's origin: the chapter's `grid_origin`, snapped, for the
/// diagram's grid (the boat's cell less half the grid).
fn water_grid_origin(boat: Vec2) -> Vec2 {
    voronoi_water::sea::grid_origin_for(boat, WATER_CELLS as u32 + 1, true)
}

/// The water grid from `first`: its lines `width` wide in `line`, and its
/// vertices as dots of radius `dot` in `colour`.
fn draw_water_grid(svg: &mut Svg, view: &TopView, first: Vec2, (line, width): (&str, f32), (colour, dot): (&str, f32)) {
    let n = WATER_CELLS as f32;
    for k in 0..=WATER_CELLS {
        let k = k as f32;
        svg.line(view.at(first + Vec2::new(k, 0.0)), view.at(first + Vec2::new(k, n)), line, width);
        svg.line(view.at(first + Vec2::new(0.0, k)), view.at(first + Vec2::new(n, k)), line, width);
    }
    for i in 0..=WATER_CELLS {
        for j in 0..=WATER_CELLS {
            svg.circle(view.at(first + Vec2::new(i as f32, j as f32)), dot, colour);
        }
    }
}

/// A small boat, its bow to the right, `cell` pixels a cell.
fn draw_boat(svg: &mut Svg, centre: Vec2, cell: f32, colour: &str) {
    let hull = [(-0.55, -0.2), (0.2, -0.2), (0.6, 0.0), (0.2, 0.2), (-0.55, 0.2)];
    let points: Vec<Vec2> = hull.iter().map(|&(x, y)| centre + Vec2::new(x, y) * cell).collect();
    svg.polygon(&points, colour, "#ffffff");
}

/// Chapter 11: the sea's grid follows the boat in whole cells
/// (`grid_origin` with `snap`), so its vertices sit on the same world
/// points, and waves fixed in the world stay put. Beside it, the grid
/// moved by the boat's own step: its vertices fall between the points.
pub fn moving_grid() -> String {
    let mut svg = Svg::new(640.0, 410.0);
    let view = TopView { corner: Vec2::new(20.0, 80.0), cell: 26.0, from: Vec2::ZERO, cells: Vec2::new(13.0, 10.0) };
    let (before, after) = (Vec2::new(5.3, 5.5), Vec2::new(6.7, 5.5));
    let before_band = "#a9c3e6";
    view.draw_world(&mut svg);
    // The cell each boat is in: the water grid's middle cell.
    for (boat, fill) in [(before, SITE_FILLS[1]), (after, SITE_FILLS[0])] {
        let cell = view.at(boat.floor());
        svg.rect(cell.x, cell.y, view.cell, view.cell, fill, "none");
    }
    // Before, wide and pale; after, thin on top: where they share a line
    // or a vertex, the world point is the same.
    draw_water_grid(&mut svg, &view, water_grid_origin(before), (before_band, 5.0), (BLUE, 4.0));
    draw_water_grid(&mut svg, &view, water_grid_origin(after), (ACCENT, 1.5), (ACCENT, 2.0));
    draw_boat(&mut svg, view.at(before), view.cell, BLUE);
    draw_boat(&mut svg, view.at(after), view.cell, ACCENT);
    let step = before.y - 0.95;
    svg.arrow(view.at(Vec2::new(before.x, step)), view.at(Vec2::new(after.x, step)), INK);
    let label = view.at(Vec2::new((before.x + after.x) / 2.0, step - 0.25));
    svg.rect(label.x - 24.0, label.y - 10.0, 48.0, 13.0, PAPER, "none");
    svg.text(label, "1.4 cells", 10.0, "middle", INK);
    svg.text(view.corner + Vec2::new(0.0, -10.0), "from above: the world's cells and wave crests", 12.0, "start", INK);
    let legend = view.corner + Vec2::new(0.0, view.size().y + 24.0);
    for (i, (boat, colour)) in [(before, BLUE), (after, ACCENT)].into_iter().enumerate() {
        let at = legend + Vec2::new(0.0, 18.0 * i as f32);
        let (line, width, dot) = if i == 0 { (before_band, 5.0, 4.0) } else { (ACCENT, 1.5, 2.0) };
        svg.line(at + Vec2::new(0.0, -4.0), at + Vec2::new(24.0, -4.0), line, width);
        svg.circle(at + Vec2::new(12.0, -4.0), dot, colour);
        let name = if i == 0 { "before" } else { "after" };
        let first = water_grid_origin(boat).x;
        let last = first + (WATER_CELLS - 1) as f32;
        let text = format!(
            "{name}: the boat at x = {}, in cell {}; the grid on cells {first} to {last}",
            trim(boat.x),
            boat.x.floor()
        );
        svg.text(at + Vec2::new(32.0, 0.0), &text, 11.0, "start", colour);
    }
    // The inset: the same step, with the grid moved by exactly the boat's 1.4 cells.
    let inset =
        TopView { corner: Vec2::new(410.0, 80.0), cell: 28.0, from: Vec2::new(3.0, 2.0), cells: Vec2::splat(7.0) };
    let size = inset.size();
    svg.text(inset.corner + Vec2::new(0.0, -10.0), "the wrong way: moved 1.4 cells", 12.0, "start", INK);
    inset.draw_world(&mut svg);
    svg.clip(inset.corner.x, inset.corner.y, size.x, size.y);
    let moved = water_grid_origin(before) + (after - before);
    draw_water_grid(&mut svg, &inset, moved, (ACCENT, 1.5), ("#ffffff", 3.2));
    for i in 0..=WATER_CELLS {
        for j in 0..=WATER_CELLS {
            svg.ring(inset.at(moved + Vec2::new(i as f32, j as f32)), 3.2, ACCENT, 1.4);
        }
    }
    svg.unclip();
    svg.rect(inset.corner.x, inset.corner.y, size.x, size.y, "none", MUTED);
    draw_boat(&mut svg, inset.at(after), inset.cell, ACCENT);
    let lines = [
        "its vertices fall between the world's",
        "points: each frame they sample the",
        "waves at new places, and the waves",
        "seem to swim along with the boat",
    ];
    for (k, line) in lines.iter().enumerate() {
        svg.text(inset.corner + Vec2::new(0.0, size.y + 20.0 + 15.0 * k as f32), line, 11.0, "start", INK);
    }
    svg.text(
        Vec2::new(20.0, 24.0),
        "The grid follows the boat in whole cells: every vertex lands on a world point where the height",
        11.0,
        "start",
        INK,
    );
    svg.text(Vec2::new(20.0, 40.0), "was already defined — nothing swims.", 11.0, "start", INK);
    svg.finish()
}

/// A colour between `a` and `b` (`#rrggbb`), `t` of the way.
fn blend(a: &str, b: &str, t: f32) -> String {
    let channel = |c: &str, i: usize| f32::from(u8::from_str_radix(&c[1 + 2 * i..3 + 2 * i], 16).unwrap_or(0));
    let mixed: Vec<String> = (0..3)
        .map(|i| format!("{:02x}", (channel(a, i) + (channel(b, i) - channel(a, i)) * t.clamp(0.0, 1.0)).round() as u8))
        .collect();
    format!("#{}", mixed.concat())
}

/// Chapter 11: how the sail swells. Left, the cloth from the side, shaded
/// by the chapter's `sail::belly`: zero along the mast, the boom and the
/// free edge, deepest in the middle. Right, from above: the wind, its part
/// across the boat (`sail::wind_across`), and the cloth's section a third
/// of the way up, moved by `sail::swell`, to scale.
pub fn sail_swell() -> String {
    use voronoi_water::sail::{SWELL_DEPTH, belly, swell, wind_across};
    let mut svg = Svg::new(640.0, 340.0);
    svg.text(
        Vec2::new(20.0, 24.0),
        "The cloth moves sideways by depth × across × belly(u, v), with",
        11.0,
        "start",
        INK,
    );
    svg.text(
        Vec2::new(20.0, 40.0),
        &format!("belly(u, v) = 27 u v (1 − u − v) and depth = {} m", trim(SWELL_DEPTH)),
        11.0,
        "start",
        INK,
    );
    // The cloth from the starboard side, bow to the left: the model's sizes.
    let (luff, foot, scale) = (7.9 - 3.32, 3.4 + 0.92, 48.0);
    let origin = Vec2::new(60.0, 300.0);
    let at = |u: f32, v: f32| origin + Vec2::new(u * foot, -v * luff) * scale;
    const FINE: usize = 24;
    for j in 0..FINE {
        for i in 0..FINE - j {
            let step = 1.0 / FINE as f32;
            let (u, v) = (i as f32 * step, j as f32 * step);
            let mut triangles = vec![[(u, v), (u + step, v), (u, v + step)]];
            if i + j + 1 < FINE {
                triangles.push([(u + step, v), (u + step, v + step), (u, v + step)]);
            }
            for t in triangles {
                let (cu, cv) = ((t[0].0 + t[1].0 + t[2].0) / 3.0, (t[0].1 + t[1].1 + t[2].1) / 3.0);
                let fill = blend("#f4efe6", ACCENT, belly(cu, cv));
                let points: Vec<Vec2> = t.iter().map(|&(u, v)| at(u, v)).collect();
                svg.polygon(&points, &fill, &fill);
            }
        }
    }
    // The model's own grid: 6 rows.
    for k in 1..6 {
        let t = k as f32 / 6.0;
        svg.line(at(t, 0.0), at(0.0, t), MUTED, 0.5);
        svg.line(at(t, 0.0), at(t, 1.0 - t), MUTED, 0.5);
        svg.line(at(0.0, t), at(1.0 - t, t), MUTED, 0.5);
    }
    svg.line(at(0.0, -0.05), at(0.0, 1.08), INK, 3.0);
    svg.line(at(-0.02, 0.0), at(1.04, 0.0), "#7a4a22", 4.0);
    svg.polyline(&[at(1.0, 0.0), at(0.0, 1.0)], MUTED, 1.0);
    svg.circle(at(1.0 / 3.0, 1.0 / 3.0), 3.0, INK);
    svg.text(at(1.0 / 3.0, 1.0 / 3.0) + Vec2::new(6.0, -6.0), "belly 1 at (⅓, ⅓)", 10.0, "start", INK);
    svg.text(at(0.0, 0.55) + Vec2::new(-8.0, 0.0), "mast: 0", 10.0, "end", INK);
    svg.text(at(0.5, 0.0) + Vec2::new(0.0, 16.0), "boom: 0 (u →)", 10.0, "middle", INK);
    svg.text(at(0.55, 0.45) + Vec2::new(8.0, 0.0), "free edge: 0", 10.0, "start", INK);
    svg.text(at(0.0, 1.0) + Vec2::new(8.0, -4.0), "v ↑", 10.0, "start", INK);
    // From above, the bow up: the boat's frame, the wind and the section.
    let (centre, top) = (Vec2::new(470.0, 190.0), 28.0);
    let plan = |x: f32, z: f32| centre + Vec2::new(x, z) * top;
    let hull = [(0.0, -4.0), (1.1, -1.5), (1.2, 1.5), (1.0, 4.0), (-1.0, 4.0), (-1.2, 1.5), (-1.1, -1.5)];
    let outline: Vec<Vec2> = hull.iter().map(|&(x, z)| plan(x, z)).collect();
    svg.polygon(&outline, "#eef3f8", MUTED);
    svg.text(plan(0.0, -4.0) + Vec2::new(0.0, -8.0), "bow", 10.0, "middle", MUTED);
    // A wind from the port bow, blowing to starboard and aft (heading 0).
    let wind = Vec2::new(0.8, 0.6);
    let across = wind_across(0.0, wind);
    let from = plan(-3.4, -2.6);
    let tip = from + wind * 2.6 * top;
    svg.arrow(from, tip, BLUE);
    svg.text(from + Vec2::new(-6.0, 4.0), "wind", 11.0, "end", BLUE);
    let foot_of = Vec2::new(tip.x, from.y);
    svg.dashed(tip, foot_of, BLUE);
    svg.arrow(from, foot_of, ACCENT);
    svg.text(
        (from + foot_of) / 2.0 + Vec2::new(0.0, -10.0),
        &format!("across = {} (to starboard)", trim(across)),
        10.0,
        "middle",
        ACCENT,
    );
    // The section a third of the way up: from the mast aft, 2/3 of the foot.
    let v = 1.0 / 3.0;
    let (mast_z, steps) = (-0.92, 24);
    let flat: Vec<Vec2> = (0..=steps).map(|k| plan(0.0, mast_z + (1.0 - v) * foot * k as f32 / steps as f32)).collect();
    let full: Vec<Vec2> = (0..=steps)
        .map(|k| {
            let u = (1.0 - v) * k as f32 / steps as f32;
            plan(swell(u, v, across), mast_z + u * foot)
        })
        .collect();
    svg.polyline(&flat, MUTED, 1.0);
    svg.polyline(&full, ACCENT, 2.5);
    svg.circle(plan(0.0, mast_z), 3.5, INK);
    let deepest = swell(1.0 / 3.0, v, across);
    svg.text(
        plan(swell(1.0 / 3.0, v, across), mast_z + foot / 3.0) + Vec2::new(8.0, 4.0),
        &format!("{} m downwind", trim(deepest)),
        10.0,
        "start",
        ACCENT,
    );
    svg.text(Vec2::new(370.0, 330.0), "from above, to scale: the cloth a third of the way up", 10.0, "start", INK);
    svg.text(Vec2::new(20.0, 330.0), "from the side: belly(u, v), dark where deep", 10.0, "start", INK);
    svg.finish()
}
