//! The sea on the GPU against the sea on the CPU: the vertex shader's
//! heights are the wave function's; the grid follows the boat without the
//! waves swimming; a million seconds in, the waves are still waves.

use common::glam::Vec2;
use common::headless::{OFFSCREEN_FORMAT, capture};
use common::{Chapter, Gpu, Target};
use voronoi_water::boat::Helm;
use voronoi_water::sea::{self, CELL, GRID_VERTICES};
use voronoi_water::{Play, VoronoiWaterChapter};

/// Renders a frame with the boat at `position` at `time`, then reads where
/// the vertex shader put each vertex of the grid: (x, height, z).
fn probe(gpu: &Gpu, chapter: &mut VoronoiWaterChapter, position: Vec2, time: f32) -> Vec<[f32; 4]> {
    chapter.play = Play::Keys(Helm { position, heading: 0.3, speed: 0.0 });
    let target = Target { format: OFFSCREEN_FORMAT, width: 64, height: 36, samples: 1 };
    capture(gpu, chapter, target, (time, 0), Default::default()).unwrap();
    chapter.sea.probe(gpu, &chapter.scene_lights, &chapter.atmosphere, &chapter.shadow_map).unwrap()
}

fn chapter(gpu: &Gpu) -> VoronoiWaterChapter {
    let target = Target { format: OFFSCREEN_FORMAT, width: 64, height: 36, samples: 1 };
    let mut chapter = common::chapter::create::<VoronoiWaterChapter>(gpu, target, &Default::default()).unwrap();
    chapter.select_view(0);
    chapter
}

// ANCHOR: cpu_gpu
/// The scene times the GPU's heights are checked at: early, and after
/// days at sea (where an f32 time would have too few digits left).
const EARLY_SECONDS: f32 = 20.0;
const LATE_SECONDS: f32 = 1_000_000.0;

#[test]
fn the_vertex_shader_lifts_the_grid_as_the_wave_function_says() {
    let gpu = Gpu::headless(VoronoiWaterChapter::gpu_needs()).unwrap();
    let mut chapter = chapter(&gpu);
    let waves = sea::sea_waves();
    let software = gpu.adapter.get_info().device_type == common::wgpu::DeviceType::Cpu;
    for (position, time) in [(Vec2::new(2048.0, 2048.0), EARLY_SECONDS), (Vec2::new(13.7, 4090.2), LATE_SECONDS)] {
        let points = probe(&gpu, &mut chapter, position, time);
        assert_eq!(points.len(), (GRID_VERTICES * GRID_VERTICES) as usize);
        let mut worst = 0.0f32;
        for p in &points {
            let cpu = sea::height(&waves, Vec2::new(p[0], p[2]), time);
            worst = worst.max((cpu - p[1]).abs());
        }
        println!("at {time} s: the GPU's heights are within {worst:.2e} m of the CPU's");
        // Lavapipe's sin and cos are LLVM's full-precision ones: the heights
        // (up to a few metres, where an f32 step is 2.4 × 10⁻⁷ m) agree to
        // 4.8 × 10⁻⁷ m, two steps; 10⁻⁶ m allows four. WGSL lets a GPU's
        // sin and cos be off by 2⁻¹¹ (absolute, for angles in −π..π): over
        // the eight waves' amplitudes (3.07 m in all), up to 1.5 × 10⁻³ m
        // on hardware.
        let allowed = if software { 1e-6 } else { 2e-3 };
        assert!(worst < allowed, "at {time} s a vertex is {worst} m from the wave function (allowed {allowed} m)");
        // Vertices sit on whole cells, around the boat.
        let first = Vec2::new(points[0][0], points[0][2]) / CELL;
        assert_eq!(first, sea::grid_origin(position, true));
    }
}
// ANCHOR_END: cpu_gpu

/// The height of the drawn surface (the grid's triangles) at world point
/// `p`, from the probed vertices: the triangle under `p`, interpolated.
fn surface_height(points: &[[f32; 4]], p: Vec2) -> f32 {
    let n = GRID_VERTICES as usize;
    let first = Vec2::new(points[0][0], points[0][2]);
    let cell = (p - first) / CELL;
    let (i, j) = (cell.x.floor() as usize, cell.y.floor() as usize);
    let (fx, fz) = (cell.x - i as f32, cell.y - j as f32);
    let h = |i: usize, j: usize| points[j * n + i][1];
    // Each cell is two triangles split along its (i+1, j)–(i, j+1) diagonal.
    if fx + fz <= 1.0 {
        h(i, j) + fx * (h(i + 1, j) - h(i, j)) + fz * (h(i, j + 1) - h(i, j))
    } else {
        h(i + 1, j + 1) + (1.0 - fx) * (h(i, j + 1) - h(i + 1, j + 1)) + (1.0 - fz) * (h(i + 1, j) - h(i + 1, j + 1))
    }
}

// ANCHOR: no_swimming
#[test]
fn the_grid_follows_the_boat_without_the_waves_swimming() {
    let gpu = Gpu::headless(VoronoiWaterChapter::gpu_needs()).unwrap();
    let mut chapter = chapter(&gpu);
    let time = 20.0;
    let start = Vec2::new(2050.3, 2047.1);
    // Fixed world points near the boat.
    let fixed: Vec<Vec2> = (0..40).map(|k| start + Vec2::new(k as f32 * 1.37 - 27.0, k as f32 * 0.71 - 14.0)).collect();
    let mut change = |snap: bool| {
        chapter.settings.snap_grid = snap;
        let before = probe(&gpu, &mut chapter, start, time);
        // A fraction of a cell, and across into the next cells.
        let mut worst = 0.0f32;
        for shift in [Vec2::new(0.3 * CELL, 0.0), Vec2::new(1.3 * CELL, 0.6 * CELL)] {
            let after = probe(&gpu, &mut chapter, start + shift, time);
            for p in &fixed {
                worst = worst.max((surface_height(&before, *p) - surface_height(&after, *p)).abs());
            }
        }
        worst
    };
    let snapped = change(true);
    let swimming = change(false);
    println!("the surface at fixed points moves {snapped:.2e} m with snapping, {swimming:.3} m without");
    assert!(snapped < 1e-5, "snapped, the water moved {snapped} m under fixed points");
    assert!(swimming > 0.01, "without snapping it should swim, but moved only {swimming} m");
}
// ANCHOR_END: no_swimming

#[test]
fn a_million_seconds_in_the_waves_are_still_waves() {
    let gpu = Gpu::headless(VoronoiWaterChapter::gpu_needs()).unwrap();
    let mut chapter = chapter(&gpu);
    let spread = |points: &[[f32; 4]]| {
        let mean = points.iter().map(|p| p[1]).sum::<f32>() / points.len() as f32;
        (points.iter().map(|p| (p[1] - mean).powi(2)).sum::<f32>() / points.len() as f32).sqrt()
    };
    // Sailing a million seconds on the course; the boat is still on the
    // sea's first period.
    let helm = voronoi_water::boat::on_course(1e6);
    let early = spread(&probe(&gpu, &mut chapter, helm.position, 20.0));
    let late = probe(&gpu, &mut chapter, helm.position, 1e6);
    assert!(late.iter().all(|p| p.iter().all(|v| v.is_finite())));
    assert!((spread(&late) / early - 1.0).abs() < 0.2, "the waves' spread went from {early} to {}", spread(&late));
    // And the picture renders.
    chapter.play = Play::Course;
    let target = Target { format: OFFSCREEN_FORMAT, width: 64, height: 36, samples: 1 };
    let picture = capture(&gpu, &mut chapter, target, (1e6, 0), Default::default()).unwrap();
    assert!(picture.pixels().any(|p| p[2] > 40), "a sea at 10⁶ s");
}
