//! Worked solutions to the exercises of chapter 11's lessons. Each makes
//! the change its exercise asks for and asserts the figure the lesson's
//! solution states, so that the solutions are built and checked with the
//! chapter. A test's name starts with its lesson's page (`cones`,
//! `jump_flooding`, `water_texture`, `endless_sea`, `boat`, `sunset`) and
//! the exercise's number there.

use common::book_figures::median_ms;
use common::glam::{Vec2, Vec3};
use common::headless::read_bytes;
use common::{Chapter, Gpu, PassTimer, ShaderFile, shader};
use voronoi_water::boat::{self, Helm, Pose};
use voronoi_water::boat_shadow::{SHADOW_REACH, shadow_focus};
use voronoi_water::sea::{self, CELL, GRID_VERTICES, TILE_METRES};
use voronoi_water::sites::{self, nearest, torus_offset};
use voronoi_water::voronoi::{Method, Voronoi, VoronoiSettings};
use voronoi_water::{DayClock, Settings, VoronoiWaterChapter, atmosphere};

/// `file` with `edits` made to the text of `path` (the file itself or a
/// module it imports), composed with its imports and validated by naga.
/// Each edit's `before` must occur exactly once.
fn compiles_with(file: ShaderFile, path: &str, edits: &[(&str, &str)]) {
    file.compose_edited(path, edits).unwrap_or_else(|e| panic!("{e}"));
}

/// The diagram of `sites` at `width` × `height` (the tile stretched over
/// it), made on the GPU by `settings`, read back: a site index per pixel.
fn diagram(gpu: &Gpu, sites: &[Vec2], (width, height): (u32, u32), settings: &VoronoiSettings) -> Vec<u32> {
    let mut voronoi = Voronoi::new(gpu, width, height).unwrap();
    let mut encoder = gpu.device.create_command_encoder(&Default::default());
    voronoi.render(gpu, &mut encoder, &PassTimer::off(), sites, (width, height), settings);
    gpu.queue.submit([encoder.finish()]);
    read_bytes(gpu, voronoi.ids_texture(), 4)
        .unwrap()
        .chunks_exact(4)
        .map(|b| u32::from_le_bytes(b.try_into().unwrap()))
        .collect()
}

/// The centre of pixel `i` of a `width` × `height` diagram, in tile units.
fn centre(i: usize, (width, height): (u32, u32)) -> Vec2 {
    Vec2::new(((i as u32 % width) as f32 + 0.5) / width as f32, ((i as u32 / width) as f32 + 0.5) / height as f32)
}

// ANCHOR: segments
/// The cones lesson, exercise 1: how a diagram by cones of `segments` sides
/// differs from the exact one: the pixels that hold another site than their
/// nearest, and the worst of them, in pixels (how much nearer the true site
/// is).
fn cone_errors(ids: &[u32], exact: &[usize], sites: &[Vec2], size: (u32, u32)) -> (usize, f32) {
    let pixel = 1.0 / size.0.min(size.1) as f32;
    let mut wrong = 0;
    let mut worst = 0.0f32;
    for (i, (&id, &best)) in ids.iter().zip(exact).enumerate() {
        if id as usize != best {
            let p = centre(i, size);
            let error = torus_offset(p, sites[id as usize]).length() - torus_offset(p, sites[best]).length();
            wrong += 1;
            worst = worst.max(error / pixel);
        }
    }
    (wrong, worst)
}

/// The scene time whose sites the diagrams are drawn for.
const CONES_SECONDS: f32 = 3.0;
// ANCHOR_END: segments

#[test]
fn cones_exercise_1_few_segments_make_wavy_edges_and_64_still_miss_the_exact_diagram() {
    let gpu = Gpu::headless(VoronoiWaterChapter::gpu_needs()).unwrap();
    // The `cells` view's size and its test's time.
    let size = (400, 240);
    let sites = sites::positions(CONES_SECONDS);
    let exact: Vec<usize> =
        (0..(size.0 * size.1) as usize).map(|i| nearest(&sites, centre(i, size)).unwrap()).collect();
    let mut found = Vec::new();
    for segments in [3, 8, 64] {
        let settings = VoronoiSettings { method: Method::Cones, segments, ..Default::default() };
        let (wrong, worst) = cone_errors(&diagram(&gpu, &sites, size, &settings), &exact, &sites, size);
        println!("cones of {segments} segments: {wrong} pixels hold another site, at worst {worst:.2} pixels nearer");
        found.push((segments, wrong, worst));
    }
    for ((segments, wrong, worst), (_, expected, expected_worst)) in found.iter().zip(measured::CONE_ERRORS) {
        assert!(wrong.abs_diff(expected) <= expected / 50 + 2, "{segments} segments: {wrong} pixels");
        assert!((worst - expected_worst).abs() < 0.1, "{segments} segments: {worst} pixels");
    }
}

// ANCHOR: crossover
/// The jump flooding lesson, exercise 1: each method's pass time at `size`²
/// as a straight line in the site count, (milliseconds at no sites,
/// milliseconds per site), through the bench's medians at 1,024 and 16,384
/// sites: the cones', then jump flooding's.
fn cost_lines(table: &str, size: u32) -> [(f64, f64); 2] {
    let median = |view: String, pass: &str| median_ms(table, &view, &format!("GPU: {pass}")).unwrap();
    let line = |method: &str, pass: &str| {
        let (a, b) = (median(format!("{method}-1024-{size}"), pass), median(format!("{method}-16384-{size}"), pass));
        let slope = (b - a) / (16_384.0 - 1024.0);
        (a - slope * 1024.0, slope)
    };
    [line("cones", "voronoi cones pass"), line("jfa", "jump flooding pass")]
}

/// The site count where the two lines cross, if jump flooding's grows
/// more slowly than the cones'.
fn crossover([cones, flood]: [(f64, f64); 2]) -> Option<f64> {
    (cones.1 > flood.1).then(|| (flood.0 - cones.0) / (cones.1 - flood.1))
}
// ANCHOR_END: crossover

#[test]
fn jump_flooding_exercise_1_jump_flooding_wins_past_a_crossover_that_moves_with_the_size() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../book/src/bench/voronoi-water.md");
    let table = std::fs::read_to_string(path).unwrap();
    let (lines_512, lines_1024) = (cost_lines(&table, 512), cost_lines(&table, 1024));
    let microseconds = |lines: [(f64, f64); 2]| lines.map(|(_, per_site)| per_site * 1e3);
    let (at_512, at_1024) = (crossover(lines_512), crossover(lines_1024));
    println!(
        "µs per site, cones and jump flooding: {:?} at 512², {:?} at 1024²; crossovers {at_512:?} and {at_1024:?}",
        microseconds(lines_512),
        microseconds(lines_1024)
    );
    // Jump flooding's cost grows more slowly with the sites at 512²: the
    // lines cross, past the slider's 16,384.
    assert!(at_512.is_some_and(|n| n > 16_384.0), "{at_512:?}");
    // At 1024² they cross too, but far later: jump flooding's passes cover
    // four times the pixels. The page works the same figures out from the
    // table when the book is built ({{#figure}}), by its own arithmetic;
    // this is the listed Rust, on the same table.
    assert!(at_1024.zip(at_512).is_some_and(|(late, early)| late > 4.0 * early), "{at_1024:?} against {at_512:?}");
    // The 256² figure on the page was one measurement, not a test: timings
    // belong in `cargo xtask bench`, never in a test that can fail on a
    // busy machine.
}

// ANCHOR: two_cells
/// The endless sea lesson, exercise 1: where the grid's first vertex is
/// when the grid moves in steps of `step` whole cells (the chapter's
/// snapping is 1; 0 does not snap at all), for a boat at `boat`.
fn grid_origin_in_steps(boat: Vec2, step: u32) -> Vec2 {
    let cells = boat / CELL;
    let half = (GRID_VERTICES / 2 - 1) as f32;
    if step == 0 { cells - half } else { (cells / step as f32).floor() * step as f32 - half }
}

/// The height of the drawn sea at world point `p`: the waves at the grid's
/// vertices, interpolated across the triangle under `p` (each cell split
/// along its (i+1, j)–(i, j+1) diagonal, as the sea's index buffer does).
fn drawn_height(origin: Vec2, p: Vec2, time: f32) -> f32 {
    let waves = sea::sea_waves();
    let cell = p / CELL - origin;
    let (i, j) = (cell.x.floor(), cell.y.floor());
    let (fx, fz) = (cell.x - i, cell.y - j);
    let h = |di: f32, dj: f32| sea::height(&waves, (origin + Vec2::new(i + di, j + dj)) * CELL, time);
    if fx + fz <= 1.0 {
        h(0.0, 0.0) + fx * (h(1.0, 0.0) - h(0.0, 0.0)) + fz * (h(0.0, 1.0) - h(0.0, 0.0))
    } else {
        h(1.0, 1.0) + (1.0 - fx) * (h(0.0, 1.0) - h(1.0, 1.0)) + (1.0 - fz) * (h(1.0, 0.0) - h(1.0, 1.0))
    }
}
// ANCHOR_END: two_cells

#[test]
fn endless_sea_exercise_1_a_grid_snapped_to_two_cells_does_not_swim_either() {
    // The sea test's fixed points and moves: a fraction of a cell, then across.
    let start = Vec2::new(2050.3, 2047.1);
    let fixed: Vec<Vec2> = (0..40).map(|k| start + Vec2::new(k as f32 * 1.37 - 27.0, k as f32 * 0.71 - 14.0)).collect();
    let moved = |step: u32| {
        let before = grid_origin_in_steps(start, step);
        let mut worst = 0.0f32;
        for shift in [Vec2::new(0.3 * CELL, 0.0), Vec2::new(1.3 * CELL, 0.6 * CELL)] {
            let after = grid_origin_in_steps(start + shift, step);
            for p in &fixed {
                worst = worst.max((drawn_height(before, *p, 20.0) - drawn_height(after, *p, 20.0)).abs());
            }
        }
        worst
    };
    let (free, one, two) = (moved(0), moved(1), moved(2));
    println!(
        "the drawn sea moves at fixed points by {free:.3} m unsnapped, {one:.1e} m snapped to a cell, {two:.1e} m to two"
    );
    measured::UNSNAPPED_MOVE.check("how far the unsnapped sea moves at a fixed point, m", free);
    assert!(one < 1e-5 && two < 1e-5);
}

// ANCHOR: gaussian
/// The water texture lesson, exercise 1: process.wgsl's blur as a Gaussian
/// whose standard deviation is the box's, √(r (r + 1) / 3), out to three of
/// them: run twice like the box, the same width as the tent the two boxes
/// make.
const GAUSSIAN_BLUR: (&str, &str) = (
    "    let r = i32(process.options.y);
    var sum = vec4<f32>(0.0);
    for (var i = -r; i <= r; i++) {
        let there = ((pixel + direction * i) % size + size) % size;
        sum += textureLoad(picture, there, 0);
    }
    return sum / f32(2 * r + 1);",
    "    let r = f32(process.options.y);
    let sigma = sqrt(r * (r + 1.0) / 3.0);
    let reach = i32(ceil(3.0 * sigma));
    var sum = vec4<f32>(0.0);
    var weights = 0.0;
    for (var i = -reach; i <= reach; i++) {
        let there = ((pixel + direction * i) % size + size) % size;
        let weight = exp(-f32(i * i) / (2.0 * sigma * sigma));
        sum += weight * textureLoad(picture, there, 0);
        weights += weight;
    }
    return sum / weights;",
);

/// One direction of a blur by `kernel` (taps from −reach to reach) over a
/// `size` × `size` picture that wraps, across (`across` true) or down.
fn blur(picture: &[f32], size: usize, kernel: &[f32], across: bool) -> Vec<f32> {
    let reach = (kernel.len() / 2) as i64;
    (0..size * size)
        .map(|i| {
            let (x, y) = ((i % size) as i64, (i / size) as i64);
            let tap = |k: i64| {
                let (x, y) = if across { (x + k, y) } else { (x, y + k) };
                picture[(y.rem_euclid(size as i64) * size as i64 + x.rem_euclid(size as i64)) as usize]
            };
            (-reach..=reach).map(|k| kernel[(k + reach) as usize] * tap(k)).sum()
        })
        .collect()
}

/// The box of radius `r`, and the Gaussian with its standard deviation.
fn kernels(r: usize) -> (Vec<f32>, Vec<f32>) {
    let boxed = vec![1.0 / (2 * r + 1) as f32; 2 * r + 1];
    let sigma = ((r * (r + 1)) as f32 / 3.0).sqrt();
    let reach = (3.0 * sigma).ceil() as i64;
    let weights: Vec<f32> = (-reach..=reach).map(|i| (-(i * i) as f32 / (2.0 * sigma * sigma)).exp()).collect();
    let total: f32 = weights.iter().sum();
    (boxed, weights.iter().map(|w| w / total).collect())
}

/// Two passes each way by `kernel`, as the chapter runs its blur.
fn blurred_twice(picture: &[f32], size: usize, kernel: &[f32]) -> Vec<f32> {
    let mut p = picture.to_vec();
    for _ in 0..2 {
        p = blur(&blur(&p, size, kernel, true), size, kernel, false);
    }
    p
}
// ANCHOR_END: gaussian

/// The brightness process.wgsl's colour pass gives cell `site`, in linear
/// light (its hash and the sea's shades, then Sobel's weights).
fn cell_brightness(site: u32) -> f32 {
    let x = site.wrapping_mul(747_796_405).wrapping_add(2_891_336_453);
    let mix = |h: u32| {
        let h = (h ^ (h >> 16)).wrapping_mul(0x45d_9f3b);
        ((h ^ (h >> 16)) & 0xffff) as f32 / 65535.0
    };
    let (hx, hy) = (mix(x), mix(x.wrapping_mul(277_803_737)));
    let deep = [0.008, 0.09, 0.36];
    let teal = [0.02, 0.24, 0.46];
    let shade: Vec<f32> = (0..3).map(|c| (deep[c] + (teal[c] - deep[c]) * hx) * (0.8 + 0.4 * hy)).collect();
    0.299 * shade[0] + 0.587 * shade[1] + 0.114 * shade[2]
}

/// Linear light to an 8-bit sRGB value.
fn encoded(linear: f32) -> f32 {
    let c = linear.clamp(0.0, 1.0);
    255.0 * if c <= 0.003_130_8 { 12.92 * c } else { 1.055 * c.powf(1.0 / 2.4) - 0.055 }
}

// ANCHOR: worley
/// The water texture lesson, exercise 2: F2 − F1 at `p`, the distance to
/// the second-nearest site less the distance to the nearest (Worley 1996):
/// zero on the cells' edges, growing into them. As the shader below works
/// it out.
fn f2_minus_f1(sites: &[Vec2], p: Vec2) -> f32 {
    let (mut f1, mut f2) = (f32::MAX, f32::MAX);
    for site in sites {
        let d = torus_offset(p, *site).length();
        (f1, f2) = if d < f1 { (d, f1) } else { (f1, f2.min(d)) };
    }
    f2 - f1
}

/// A pass after the diagram that writes F2 − F1 for each texel, for the
/// water pass to lay foam where it is small instead of where Sobel's
/// gradient is large. With 64 sites every texel can look at all of them;
/// with thousands, jump flooding would carry the two nearest per texel.
const F2_MINUS_F1: &str = "
@group(0) @binding(0) var<storage, read> sites: array<vec2<f32>>;
@group(0) @binding(1) var<uniform> size: vec4<f32>;

@fragment
fn fs_f2_minus_f1(@builtin(position) position: vec4<f32>) -> @location(0) f32 {
    let p = position.xy / size.xy;
    var f1 = 1e9;
    var f2 = 1e9;
    for (var i = 0u; i < arrayLength(&sites); i++) {
        let offset = sites[i] - p;
        let d = length(offset - round(offset));
        if d < f1 {
            f2 = f1;
            f1 = d;
        } else {
            f2 = min(f2, d);
        }
    }
    return f2 - f1;
}
";
// ANCHOR_END: worley

/// Sobel's gradient of `brightness` at every pixel (process.wgsl's `sobel`).
fn sobel(brightness: &[f32], size: usize) -> Vec<f32> {
    let at =
        |x: i64, y: i64| brightness[y.rem_euclid(size as i64) as usize * size + x.rem_euclid(size as i64) as usize];
    (0..size * size)
        .map(|i| {
            let (x, y) = ((i % size) as i64, (i / size) as i64);
            let across = (at(x + 1, y - 1) + 2.0 * at(x + 1, y) + at(x + 1, y + 1))
                - (at(x - 1, y - 1) + 2.0 * at(x - 1, y) + at(x - 1, y + 1));
            let down = (at(x - 1, y + 1) + 2.0 * at(x, y + 1) + at(x + 1, y + 1))
                - (at(x - 1, y - 1) + 2.0 * at(x, y - 1) + at(x + 1, y - 1));
            across.hypot(down)
        })
        .collect()
}

/// The water texture lesson's exercises 1 and 2 on the sea's texture at the
/// snapshot time: the Gaussian against the two boxes, and F2 − F1 foam
/// against Sobel's.
#[test]
fn water_texture_exercises_1_and_2_a_gaussian_blur_and_worleys_foam() {
    compiles_with(
        shader!("voronoi-water/process.wgsl", imports: ["common/fullscreen.wgsl"]),
        "voronoi-water/process.wgsl",
        &[GAUSSIAN_BLUR],
    );
    common::shader::validate(F2_MINUS_F1, "f2_minus_f1.wgsl").unwrap_or_else(|e| panic!("{e}"));
    let gpu = Gpu::headless(VoronoiWaterChapter::gpu_needs()).unwrap();
    // The sea's texture: 512², 64 sites, at the snapshot time.
    let size = 512;
    let sites = sites::positions(voronoi_water::SNAPSHOT_TIME);
    // By jump flooding with its extra pass: every pixel's id is its nearest site.
    let flooding = VoronoiSettings { method: Method::JumpFlooding, extra_pass: true, ..Default::default() };
    let ids = diagram(&gpu, &sites, (size as u32, size as u32), &flooding);
    let brightness: Vec<f32> = ids.iter().map(|&id| cell_brightness(id)).collect();

    // Exercise 1: both blurs, compared as 8-bit brightness.
    let (boxed, gaussian) = kernels(4);
    let (by_boxes, by_gaussian) =
        (blurred_twice(&brightness, size, &boxed), blurred_twice(&brightness, size, &gaussian));
    let differences: Vec<f32> =
        by_boxes.iter().zip(&by_gaussian).map(|(a, b)| (encoded(*a) - encoded(*b)).abs()).collect();
    let mean = differences.iter().sum::<f32>() / differences.len() as f32;
    let worst = differences.iter().copied().fold(0.0, f32::max);
    println!("box twice against Gaussian twice: {mean:.3} of 255 on average, {worst:.2} at worst");
    measured::GAUSSIAN_MEAN.check("box twice against Gaussian twice, the mean difference", mean);
    measured::GAUSSIAN_WORST.check("box twice against Gaussian twice, the worst difference", worst);

    // Exercise 2: on the cells' edges, foam where F2 − F1 is under 0.005
    // of the tile (16 cm), against Sobel's foam (past half its ramp).
    let edge =
        |i: usize| ids[i] != ids[(i / size) * size + (i + 1) % size] || ids[i] != ids[(i + size) % (size * size)];
    let edges: Vec<usize> = (0..size * size).filter(|&i| edge(i)).collect();
    let gradient = sobel(&by_boxes, size);
    let (low, high) = voronoi_water::water_texture::Processing::DEFAULT.foam;
    let sobel_foam = edges.iter().filter(|&&i| gradient[i] > (low + high) / 2.0).count();
    let any_sobel_foam = edges.iter().filter(|&&i| gradient[i] > low).count();
    let worley_foam =
        edges.iter().filter(|&&i| f2_minus_f1(&sites, centre(i, (size as u32, size as u32))) < 0.005).count();
    println!(
        "of {} edge pixels, Sobel's foam covers {:.1} % at half strength or more ({:.1} % at all), F2 − F1's {:.1} %",
        edges.len(),
        100.0 * sobel_foam as f64 / edges.len() as f64,
        100.0 * any_sobel_foam as f64 / edges.len() as f64,
        100.0 * worley_foam as f64 / edges.len() as f64
    );
    // Derived: on an edge between two cells the two nearest sites are as
    // near, so F2 − F1 puts foam on every edge pixel.
    assert_eq!(worley_foam, edges.len());
    assert_eq!(edges.len(), measured::EDGE_PIXELS, "a change detector");
    let share = |n: usize| n as f64 / edges.len() as f64;
    measured::SOBEL_COVERS.check("the edge pixels Sobel's foam covers at half strength", share(sobel_foam));
    measured::SOBEL_TOUCHES.check("the edge pixels Sobel's foam touches", share(any_sobel_foam));
}

// ANCHOR: wake
/// The boat lesson, exercise 1: a wake, two arms of sites spreading behind
/// the boat at Kelvin's 19.5° from its track: where the boat was each
/// `spacing` seconds over the last `count` of them, pushed out to either
/// side by tan 19.5° of how far behind it is now. In tile coordinates (the
/// water texture repeats every 32 m), to join the wandering sites.
fn wake_sites(time: f32, count: u32, spacing: f32) -> Vec<Vec2> {
    let mut sites = Vec::new();
    for k in 1..=count {
        let then = boat::on_course(time - k as f32 * spacing);
        let behind = then.speed * k as f32 * spacing;
        let across = boat::forward(then.heading).perp() * behind * 19.5f32.to_radians().tan();
        for side in [then.position + across, then.position - across] {
            sites.push((side / TILE_METRES).fract());
        }
    }
    sites
}

/// The wake's sites: where the boat was every this many seconds…
const WAKE_SPACING_SECONDS: f32 = 0.2;
/// …this many times back.
const WAKE_STEPS: u32 = 16;
// ANCHOR_END: wake

#[test]
fn boat_exercise_1_a_wake_of_small_cells_behind_the_boat() {
    let gpu = Gpu::headless(VoronoiWaterChapter::gpu_needs()).unwrap();
    let time = voronoi_water::SNAPSHOT_TIME;
    let mut all = sites::positions(time);
    let wandering = all.len();
    all.extend(wake_sites(time, WAKE_STEPS, WAKE_SPACING_SECONDS));
    let size = 256;
    let ids = diagram(&gpu, &all, (size, size), &VoronoiSettings::default());
    let mut area = vec![0usize; all.len()];
    for id in &ids {
        area[*id as usize] += 1;
    }
    let mean = |cells: &[usize]| cells.iter().sum::<usize>() as f64 / cells.len() as f64;
    let (sea_cells, wake_cells) = (mean(&area[..wandering]), mean(&area[wandering..]));
    println!("a wandering site's cell: {sea_cells:.0} pixels on average; a wake site's: {wake_cells:.0}");
    assert!(area[wandering..].iter().all(|a| *a > 0), "every wake site owns pixels: {:?}", &area[wandering..]);
    measured::SEA_CELL.check("a wandering site's cell, pixels", sea_cells);
    measured::WAKE_CELL.check("a wake site's cell, pixels", wake_cells);
    measured::WAKE_CELLS_SMALLER.check("how many times smaller a wake cell is", sea_cells / wake_cells);
}

// ANCHOR: shadow_reach
/// The sunset lesson, exercise 1: how far along the sun's rays (towards
/// `towards_sun`) the shadow of a point `height` metres above the lowest
/// water runs before it reaches that water, were `shadow_focus` not to
/// stop it at `SHADOW_REACH`; and the sun's height, in degrees, below
/// which the cap cuts it short.
fn uncapped_run(height: f32, towards_sun: Vec3) -> (f32, f32) {
    (height / towards_sun.y, (height / SHADOW_REACH).asin().to_degrees())
}
// ANCHOR_END: shadow_reach

#[test]
fn sunset_exercise_1_the_mast_tops_shadow_would_run_132_m_at_sunset() {
    // Worked by hand: the mast top is 8.2 − 0.5 = 7.7 m above the mean
    // water for a boat on level water, and the lowest water, every wave in
    // a trough, is 276.5 / 90 = 3.07 m below it (the amplitudes are 1/90
    // of wavelengths summing to 276.5 m): 10.77 m in all.
    let height = boat::MAST_TOP - boat::DRAFT + sea::sea_waves().iter().map(|w| w.amplitude).sum::<f32>();
    assert!((height - 10.772).abs() < 1e-3, "{height}");
    // The default view's sun at the snapshot: phase 0.735, where sin of
    // the sun's height is cos 30° · sin(2π · 0.485) = 0.0815, 4.67°.
    let phase = DayClock::default().phase(&Settings::SUNSET, voronoi_water::SNAPSHOT_TIME);
    let sunset = atmosphere::sun_direction(phase);
    assert!((sunset.y.asin().to_degrees() - 4.67).abs() < 0.01, "{}", sunset.y.asin().to_degrees());
    // 10.77 m / 0.0815 = 132 m of ray; the cap cuts below asin(10.77 / 40).
    let (run, cap_below) = uncapped_run(height, sunset);
    println!("the mast top's shadow would run {run:.1} m; the cap cuts it below {cap_below:.1}°");
    assert!((run - 132.2).abs() < 0.2, "{run}");
    assert!((cap_below - 15.6).abs() < 0.05, "{cap_below}");
    // The chapter's own function, for a level boat: its mast-top corner
    // (the third of the eight) is followed 40 m at sunset, and at noon
    // the whole 10.77 / cos 30° = 12.44 m.
    let helm = Helm { position: Vec2::new(2048.0, 2048.0), heading: 0.0, speed: 0.0 };
    let level = Pose { helm, heave: 0.0, pitch: 0.0, roll: 0.0 };
    let followed = |towards: Vec3| {
        let (focus, _) = shadow_focus(&level, &sea::sea_waves(), towards);
        (focus[8 + 2] - focus[2]).length()
    };
    assert!((followed(sunset) - SHADOW_REACH).abs() < 1e-3, "{}", followed(sunset));
    assert!((followed(atmosphere::sun_direction(0.5)) - 12.44).abs() < 0.01);
}

/// Measured: what these tests got by running the chapter (its Voronoi
/// diagrams, its sea's grid) and copied with chapter 11's solutions, which
/// say they are measured (`common::book_figures::Measured`: change
/// detectors, not derivations).
mod measured {
    use common::book_figures::Measured;

    /// The cones lesson's exercise 1: cones of 3, 8 and 64 segments at
    /// 3 s: pixels of 96,000 given the wrong site, and the worst error,
    /// pixels.
    pub const CONE_ERRORS: [(u32, usize, f32); 3] = [(3, 21_892, 22.9), (8, 2533, 2.33), (64, 42, 0.01)];
    /// The endless sea lesson's exercise 1: how far the drawn sea moves
    /// at a fixed point when the grid follows the boat unsnapped, m.
    pub const UNSNAPPED_MOVE: Measured = Measured::new(0.054, 0.002);
    /// The water texture lesson's exercise 1: box twice against
    /// Gaussian twice, mean and worst difference in 8-bit levels.
    pub const GAUSSIAN_MEAN: Measured = Measured::new(0.057, 0.005);
    pub const GAUSSIAN_WORST: Measured = Measured::new(0.90, 0.05);
    /// The water texture lesson's exercise 2: the cells' edge pixels,
    /// and the share Sobel's foam covers at half strength or more, and
    /// at all.
    pub const EDGE_PIXELS: usize = 8931;
    pub const SOBEL_COVERS: Measured = Measured::new(0.059, 0.005);
    pub const SOBEL_TOUCHES: Measured = Measured::new(0.447, 0.01);
    /// The boat lesson's exercise 1: a wandering site's cell and a wake
    /// site's, pixels on average, and how many times smaller the wake's
    /// is.
    pub const SEA_CELL: Measured = Measured::new(873.0, 9.0);
    pub const WAKE_CELL: Measured = Measured::new(302.0, 4.0);
    pub const WAKE_CELLS_SMALLER: Measured = Measured::new(2.89, 0.087);
}
