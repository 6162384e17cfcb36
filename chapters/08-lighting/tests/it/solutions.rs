//! Worked solutions to the exercises on chapter 08's lessons. Each makes
//! the change its exercise asks for and asserts the figure the lesson's
//! solution states, so that the solutions are built and checked with the
//! chapter; a test's name starts with its lesson's (`highlights_exercise_1_…`
//! is exercise 1 of highlights.md).
//! Changes to a shader are text edits of the real file, composed and
//! validated by naga as the chapter's loader does: an edit whose text is no
//! longer in the shader fails here instead of rotting on the page.

use std::collections::HashMap;
use std::f32::consts::PI;

use common::book_figures::Measured;
use common::glam::{Mat3, Mat4, Vec2, Vec3};
use common::headless::{OFFSCREEN_FORMAT, capture, read_floats};
use common::{Camera, Chapter, Gpu, ShaderFile, Target, chapter::view_index, image, shader};
use lighting::GpuInstance;
use lighting::city::{City, Material};
use lighting::clusters::{self, GRID};
use lighting::lights::{Light, LightKind, TimeOfDay, daylight};
use lighting::material_spheres;
use lighting::paths::{PausableClock, SegmentedPath};
use lighting::prefiltered_sky::PrefilteredSky;
use lighting::{LightCount, LightingChapter, MAX_LIGHTS, aerial_camera, beacons, frame_lights, sphere_camera};

/// `file` with `edits` made to the text of `path` (the file itself or a
/// module it imports), composed with its imports and validated by naga.
/// Each edit's `before` must occur exactly once.
fn compiles_with(file: ShaderFile, path: &str, edits: &[(&str, &str)]) {
    file.compose_edited(path, edits).unwrap_or_else(|e| panic!("{e}"));
}

/// The city's shader, with the light loop it imports.
const CITY: ShaderFile =
    shader!("lighting/city.wgsl", imports: ["lighting/brdf.wgsl", "lighting/sky_light.wgsl", "lighting/lights.wgsl"]);

/// Where the ray through the centre of pixel (x, y) of a `width` × `height`
/// picture from `camera` starts, and its direction.
fn pixel_ray(camera: &Camera, (x, y): (u32, u32), (width, height): (u32, u32)) -> (Vec3, Vec3) {
    let inverse = camera.view_projection().inverse();
    let ndc = Vec2::new((x as f32 + 0.5) / width as f32 * 2.0 - 1.0, 1.0 - (y as f32 + 0.5) / height as f32 * 2.0);
    let near = inverse.project_point3(ndc.extend(0.0));
    (near, (inverse.project_point3(ndc.extend(1.0)) - near).normalize())
}

// ANCHOR: blinn_match
/// Highlights, exercise 1: the shininess that makes Blinn's highlight on the glass
/// sphere closest (least squares over the pixels) to Phong's at
/// `phong_shininess`, as the `phong` view sees it in the morning sun.
/// Both highlights are normalised as lights.wgsl normalises them.
fn blinn_shininess_matching_phong(phong_shininess: f32) -> f32 {
    let city = City::new();
    let camera = sphere_camera(&city, 16.0 / 9.0);
    let (centre, radius) = (city.sphere_building + Vec3::Y * 24.0, 14.0);
    let l = daylight(TimeOfDay::Morning.phase(0.0, 1.0)).direction;
    // The normal and the direction to the eye at every lit pixel of the sphere.
    let mut points = Vec::new();
    for (x, y) in (0..90).flat_map(|y| (0..160).map(move |x| (x, y))) {
        let (origin, d) = pixel_ray(&camera, (x, y), (160, 90));
        let b = d.dot(origin - centre);
        let c = (origin - centre).length_squared() - radius * radius;
        if b * b - c > 0.0 {
            let n = (origin + d * (-b - (b * b - c).sqrt()) - centre).normalize();
            if n.dot(l) > 0.0 {
                points.push((n, -d));
            }
        }
    }
    let phong = |n: Vec3, v: Vec3, s: f32| {
        let r = 2.0 * n.dot(l) * n - l; // reflect(−l, n)
        (s + 2.0) / 2.0 * r.dot(v).max(0.0).powf(s) * n.dot(l)
    };
    let blinn = |n: Vec3, v: Vec3, s: f32| (s + 8.0) / 8.0 * n.dot((l + v).normalize()).max(0.0).powf(s) * n.dot(l);
    let error =
        |s: f32| points.iter().map(|&(n, v)| (phong(n, v, phong_shininess) - blinn(n, v, s)).powi(2)).sum::<f32>();
    (phong_shininess as u32..=12 * phong_shininess as u32)
        .step_by(4)
        .map(|s| s as f32)
        .min_by(|a, b| error(*a).total_cmp(&error(*b)))
        .unwrap()
}
// ANCHOR_END: blinn_match

#[test]
fn highlights_exercise_1_blinn_needs_about_four_times_phongs_shininess() {
    let blinn = blinn_shininess_matching_phong(96.0);
    println!("Blinn's highlight matches Phong's at 96 best at shininess {blinn} ({:.2} times)", blinn / 96.0);
    assert!((blinn - BLINN_MATCHING_96).abs() <= 8.0, "best match at {blinn}");
}

/// The best match the highlights lesson's exercise 1 states: derived here, from the
/// two highlights' formulas over the sphere as the view sees it.
const BLINN_MATCHING_96: f32 = 352.0;

// ANCHOR: city_falloff
/// Light casters, exercise 1: the city project's falloff, which never reaches zero…
fn city_project_falloff(distance: f32) -> f32 {
    1.0 / (1.0 + 0.09 * distance + 0.032 * distance * distance)
}

/// …and the same in lights.wgsl, in place of the windowed inverse square.
const CITY_PROJECT_FALLOFF: (&str, &str) = (
    "    let ratio = distance / range;
    let window = clamp(1.0 - ratio * ratio * ratio * ratio, 0.0, 1.0);
    return window * window / (distance * distance + 1.0);",
    "    return 1.0 / (1.0 + 0.09 * distance + 0.032 * distance * distance);",
);

/// The range at which a light with `falloff` has fallen below one 8-bit
/// step (1/255) of what it gives at `reference` metres, to half a metre.
fn range_where_it_fades(falloff: impl Fn(f32) -> f32, reference: f32) -> f32 {
    (0..).map(|i| i as f32 * 0.5).find(|d| falloff(*d) < falloff(reference) / 255.0).unwrap()
}
// ANCHOR_END: city_falloff

// ANCHOR: lamp_entries

/// Clustered culling, exercise 3: how many cluster lists of the aerial view the first `count` street
/// lamps are in when each reaches `range` metres.
fn lamp_cluster_entries(count: usize, range: f32) -> usize {
    let city = City::new();
    let lamps: Vec<Light> = city
        .fixed_lights
        .iter()
        .filter(|l| matches!(l.kind, LightKind::Spot { .. }))
        .take(count)
        .map(|l| Light { range, ..*l })
        .collect();
    clusters::cull(&aerial_camera(16.0 / 9.0), &lamps).indices.len()
}
// ANCHOR_END: lamp_entries

/// Light casters, exercise 1: the city project's falloff at a lamp's 18 m of range, as a
/// share of what it gives the road 6.6 m straight below, worked by hand:
/// 1/(1 + 1.62 + 10.368) = 0.0770 over 1/(1 + 0.594 + 1.394) = 0.3347.
const UNDER_THE_LAMP_AT_18_M_PERCENT: f32 = 23.0;

#[test]
fn light_casters_exercise_1_the_city_projects_falloff_has_no_end() {
    compiles_with(CITY, "lighting/lights.wgsl", &[CITY_PROJECT_FALLOFF]);
    // A street lamp hangs 6.6 m above the road and reaches 18 m.
    let (below, at_range) = (city_project_falloff(6.6), city_project_falloff(18.0));
    let fades = range_where_it_fades(city_project_falloff, 6.6);
    println!(
        "the city project's falloff at 18 m: {at_range:.3} ({:.0} % of the light under the lamp); \
         below 1/255 of that at {fades} m",
        100.0 * at_range / below
    );
    assert!(
        (at_range - 0.077).abs() < 0.001 && (100.0 * at_range / below - UNDER_THE_LAMP_AT_18_M_PERCENT).abs() < 0.5
    );
    assert_eq!(fades, 153.0);
}

#[test]
fn culling_exercise_3_the_city_projects_range_puts_the_lamps_in_many_more_lists() {
    let fades = range_where_it_fades(city_project_falloff, 6.6);
    let (near, far) = (lamp_cluster_entries(16, 18.0), lamp_cluster_entries(16, fades));
    println!("16 lamps in {near} cluster lists at 18 m, {far} at {fades} m");
    measured::LAMP_ENTRIES_AT_18_M.check("the 16 lamps' cluster entries at 18 m", near as f64);
    measured::LAMP_ENTRIES_AT_153_M.check("the 16 lamps' cluster entries at 153 m", far as f64);
    measured::LAMP_LIST_GROWTH.check("how many times as many entries", far as f64 / near as f64);
}

// ANCHOR: torch
/// Clustered culling, exercise 1: a torch, a point light riding with the camera, added to a
/// frame's lights.
fn with_torch(mut lights: Vec<Light>, camera: &Camera) -> Vec<Light> {
    lights.push(Light { position: camera.position, colour: Vec3::splat(40.0), range: 25.0, kind: LightKind::Point });
    lights
}
// ANCHOR_END: torch

/// What a depth picture shows: for each pixel that shows the city (not
/// the sky), its column, its row and the view-space distance to it.
fn covered_pixels(camera: &Camera, depths: &[[f32; 4]], width: u32) -> Vec<(u32, u32, f32)> {
    let (near, far) = (camera.near, camera.far);
    depths
        .iter()
        .enumerate()
        .filter(|(_, d)| d[0] < 1.0)
        .map(|(i, d)| (i as u32 % width, i as u32 / width, near * far / (far - d[0] * (far - near))))
        .collect()
}

// ANCHOR: grid
/// Clustered culling, exercise 2: how many lights a fragment visits, on average over the
/// pixels of a depth picture, with the view cut into `grid` clusters
/// (across, down, deep), each listing the lights `cull` would list there:
/// its two tests, for any grid.
fn lights_visited(
    camera: &Camera,
    lights: &[Light],
    pixels: &[(u32, u32, f32)],
    size: (u32, u32),
    grid: [u32; 3],
) -> f64 {
    let (near, far) = (camera.near, camera.far);
    let view = camera.view();
    let spans: Vec<_> = lights.iter().map(|light| light_span(camera, light, grid)).collect();
    let mut listed: HashMap<[u32; 3], u32> = HashMap::new();
    let mut visited = 0u64;
    for &(x, y, distance) in pixels {
        let slice = ((distance / near).ln() / (far / near).ln() * grid[2] as f32).floor();
        let cluster = [x * grid[0] / size.0, y * grid[1] / size.1, slice.clamp(0.0, grid[2] as f32 - 1.0) as u32];
        visited += u64::from(*listed.entry(cluster).or_insert_with(|| {
            let (low, high) = cluster_box(camera, grid, cluster);
            let inside = |span: &Option<[std::ops::Range<u32>; 3]>| {
                span.as_ref().is_some_and(|s| (0..3).all(|axis| s[axis].contains(&cluster[axis])))
            };
            let centre = |light: &Light| view.transform_point3(light.position);
            let reaching =
                lights.iter().zip(&spans).filter(|(l, s)| inside(s) && reaches(&centre(l), l, &view, low, high));
            reaching.count() as u32
        }));
    }
    visited as f64 / pixels.len() as f64
}

/// The clusters a light's sphere may touch (`light_span` in clusters.rs,
/// for any grid): the slices its depth spans, and the tiles its bounding
/// box projects to, cut off at the near plane.
fn light_span(camera: &Camera, light: &Light, grid: [u32; 3]) -> Option<[std::ops::Range<u32>; 3]> {
    let (near, far) = (camera.near, camera.far);
    let centre = camera.view().transform_point3(light.position);
    let (depth, r) = (-centre.z, light.range);
    if depth + r < near || depth - r > far {
        return None;
    }
    let slice =
        |d: f32| ((d / near).ln() / (far / near).ln() * grid[2] as f32).floor().clamp(0.0, grid[2] as f32 - 1.0) as u32;
    let (near_z, far_z) = ((centre.z + r).min(-near), centre.z - r);
    let (mut low, mut high) = (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY));
    for corner in 0..8 {
        let x = centre.x + if corner & 1 == 0 { -r } else { r };
        let y = centre.y + if corner & 2 == 0 { -r } else { r };
        let z = if corner & 4 == 0 { near_z } else { far_z };
        let ndc = camera.projection().project_point3(Vec3::new(x, y, z));
        (low, high) = (low.min(ndc), high.max(ndc));
    }
    if high.x < -1.0 || low.x > 1.0 || high.y < -1.0 || low.y > 1.0 {
        return None;
    }
    let tile = |v: f32, n: u32| ((v.clamp(0.0, 0.999_999) * n as f32) as u32).min(n - 1);
    let (x0, x1) = (tile((low.x + 1.0) * 0.5, grid[0]), tile((high.x + 1.0) * 0.5, grid[0]));
    let (y0, y1) = (tile((1.0 - high.y) * 0.5, grid[1]), tile((1.0 - low.y) * 0.5, grid[1]));
    Some([x0..x1 + 1, y0..y1 + 1, slice((depth - r).max(near))..slice((depth + r).min(far)) + 1])
}

/// A cluster's box in view space (`cluster_boxes` in clusters.rs, for any grid).
fn cluster_box(camera: &Camera, grid: [u32; 3], [x, y, z]: [u32; 3]) -> (Vec3, Vec3) {
    let tan_y = (camera.fov_y / 2.0).tan();
    let tan_x = tan_y * camera.aspect;
    let depth_at = |s: u32| camera.near * (camera.far / camera.near).powf(s as f32 / grid[2] as f32);
    let ndc = |i: u32, n: u32| -1.0 + 2.0 * i as f32 / n as f32;
    let (mut low, mut high) = (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY));
    for depth in [depth_at(z), depth_at(z + 1)] {
        for nx in [ndc(x, grid[0]), ndc(x + 1, grid[0])] {
            for ny in [-ndc(y, grid[1]), -ndc(y + 1, grid[1])] {
                let corner = Vec3::new(nx * depth * tan_x, ny * depth * tan_y, -depth);
                (low, high) = (low.min(corner), high.max(corner));
            }
        }
    }
    (low, high)
}

/// Whether `light`, at `centre` in view space, can reach the box from
/// `low` to `high` (`reaches` in clusters.rs).
fn reaches(centre: &Vec3, light: &Light, view: &common::glam::Mat4, low: Vec3, high: Vec3) -> bool {
    if centre.clamp(low, high).distance_squared(*centre) >= light.range * light.range {
        return false;
    }
    match light.kind {
        LightKind::Point => true,
        LightKind::Spot { direction, .. } => {
            let axis = view.transform_vector3(direction);
            axis.dot(Vec3::select(axis.cmpge(Vec3::ZERO), high, low) - *centre) > 0.0
        }
    }
}

/// The bench's culled 256-light frame over its one-light frame, predicted
/// for a grid whose fragments visit `visited` lights: a straight line
/// through the three grids the page's table measured.
fn predicted_cost(visited: f64) -> f64 {
    let measured = [(5.44, 2.40), (4.39, 2.17), (3.35, 1.91)];
    let (mx, my) = (measured.iter().map(|m| m.0).sum::<f64>() / 3.0, measured.iter().map(|m| m.1).sum::<f64>() / 3.0);
    let slope = measured.iter().map(|(x, y)| (x - mx) * (y - my)).sum::<f64>()
        / measured.iter().map(|(x, _)| (x - mx).powi(2)).sum::<f64>();
    my + slope * (visited - mx)
}
// ANCHOR_END: grid

/// The fewest lights any grid could leave a fragment to visit: those that
/// really reach the point the pixel shows (every `step`-th pixel each way).
fn lights_reaching(camera: &Camera, lights: &[Light], pixels: &[(u32, u32, f32)], size: (u32, u32), step: u32) -> f64 {
    let sampled: Vec<_> = pixels.iter().filter(|(x, y, _)| x % step == 0 && y % step == 0).collect();
    let total: usize = sampled
        .iter()
        .map(|&&(x, y, distance)| {
            let (_, d) = pixel_ray(camera, (x, y), size);
            // `distance` is along the view axis; the ray is longer off-centre.
            let point = camera.position + d * (distance / d.dot(camera.forward()));
            lights.iter().filter(|l| l.reaching(point).max_element() > 0.0).count()
        })
        .sum();
    total as f64 / sampled.len() as f64
}

// ANCHOR: reinhard
/// HDR, tone mapping and bloom, exercise 1: Reinhard's operator in place of the ACES fit, in tonemap.wgsl.
const REINHARD: (&str, &str) = (
    "return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), vec3<f32>(0.0), vec3<f32>(1.0));",
    "return x / (1.0 + x);",
);
// ANCHOR_END: reinhard

/// An 8-bit sRGB pixel's luminance (Rec. 709 weights on the stored values)
/// and saturation ((max − min) / max).
fn luminance_and_saturation(p: &image::Rgba<u8>) -> (f32, f32) {
    let [r, g, b] = [p[0], p[1], p[2]].map(f32::from);
    let (max, min) = (r.max(g).max(b), r.min(g).min(b));
    (0.2126 * r + 0.7152 * g + 0.0722 * b, if max > 0.0 { (max - min) / max } else { 0.0 })
}

/// Three exercises on one night city (one chapter made, for all three):
/// clustered culling's two, a torch from the street and from the air, and
/// the grid's lights per fragment; and HDR's, the night under Reinhard's
/// curve.
#[test]
fn culling_exercises_1_and_2_and_hdr_exercise_1_on_the_night_city() {
    let root = shader::scratch_copy("lighting-solutions").unwrap();
    let gpu = Gpu::headless(LightingChapter::gpu_needs()).expect("an adapter (lavapipe will do)");
    gpu.read_shaders_from(Some(root.clone()));
    let size = (320, 180);
    let target = Target { format: OFFSCREEN_FORMAT, width: size.0, height: size.1, samples: 1 };
    let mut chapter = LightingChapter::new(&gpu, target, ()).unwrap();
    let time = LightingChapter::SNAPSHOT_TIME;
    let draw = |chapter: &mut LightingChapter, view: &str, camera: Camera| {
        let index = view_index::<LightingChapter>(view).unwrap();
        chapter.select_view(index);
        chapter.camera = camera;
        // The city alone, as these exercises ask about its lights: the
        // countryside adds pixels that none of them reaches.
        chapter.settings.countryside = false;
        let picture = capture(&gpu, chapter, target, (time, index), Default::default()).unwrap();
        let depths = read_floats(&gpu, chapter.post.hdr().depth_texture().expect("one sample a pixel")).unwrap();
        (picture, covered_pixels(&camera, &depths, size.0))
    };

    // Clustered culling, exercise 1: the share of the pixels whose cluster lists the torch:
    // measured from the street; from the air none, since the aerial camera
    // is 120 m up, farther from everything it sees than the torch reaches.
    let aspect = target.aspect();
    let from_the_air = aerial_camera(aspect);
    for (camera, expected) in
        [(lighting::street_camera(aspect), measured::TORCH_FROM_THE_STREET), (from_the_air, Measured::new(0.0, 0.0))]
    {
        let (_, pixels) = draw(&mut chapter, "night", camera);
        let torch = with_torch(Vec::new(), &camera);
        let share = lights_visited(&camera, &torch, &pixels, size, GRID);
        println!("the torch is in the list of {:.1} % of the pixels seen from {:?}", share * 100.0, camera.position);
        expected.check("the share of the pixels whose list holds the torch", share);
    }

    // Clustered culling, exercise 2: lights per fragment at 256 lights, by grid.
    let camera = aerial_camera(aspect);
    let (_, pixels) = draw(&mut chapter, "lights-256", camera);
    let traffic = chapter.city.traffic(chapter.clocks.cars.time(time), chapter.clocks.drones.time(time));
    let night = daylight(TimeOfDay::Night.phase(time, 1.0)).night;
    let lights = frame_lights(&chapter.city, &traffic, &beacons(MAX_LIGHTS as usize), LightCount::First(256), night);
    let stats = chapter.stats(&gpu);
    let chapters_own: f64 =
        stats.split("covered pixel: ").nth(1).and_then(|s| s.split(';').next()).unwrap().parse().unwrap();
    let chosen = lights_visited(&camera, &lights, &pixels, size, GRID);
    let coarse = lights_visited(&camera, &lights, &pixels, size, [16, 9, 24]);
    let finest = lights_reaching(&camera, &lights, &pixels, size, 2);
    println!(
        "lights visited per fragment at 256 lights: 64 × 36 × 48 {chosen:.2} (the chapter counts {chapters_own:.2}), \
         16 × 9 × 24 {coarse:.2}; lights that reach the point: {finest:.2}"
    );
    assert!((chosen - chapters_own).abs() < 0.01 * chapters_own, "{chosen} against the chapter's {chapters_own}");
    measured::VISITED_16_9_24.check("lights a fragment visits with a 16 × 9 × 24 grid", coarse);
    let cost = predicted_cost(coarse);
    println!("predicted: the 256-light frame {cost:.2} times the one-light frame (1.91 with the chapter's grid)");
    measured::PREDICTED_COST.check("the predicted cost of the 256-light frame", cost);
    measured::REACHING_256.check("lights that reach a visible point", finest);

    // HDR, exercise 1: the night under ACES, then under Reinhard.
    let camera = aerial_camera(aspect);
    let (aces, _) = draw(&mut chapter, "night", camera);
    let file = root.join("lighting/tonemap.wgsl");
    let source = std::fs::read_to_string(&file).unwrap();
    assert_eq!(source.matches(REINHARD.0).count(), 1);
    std::fs::write(&file, source.replacen(REINHARD.0, REINHARD.1, 1)).unwrap();
    assert!(gpu.reload_shaders(&["lighting/tonemap.wgsl"]).unwrap() >= 1);
    let (reinhard, _) = draw(&mut chapter, "night", camera);
    let pairs: Vec<_> =
        aces.pixels().map(luminance_and_saturation).zip(reinhard.pixels().map(luminance_and_saturation)).collect();
    let mean = |values: &mut dyn Iterator<Item = f32>| {
        let (sum, n) = values.fold((0.0, 0), |(s, n), v| (s + v, n + 1));
        sum / n as f32
    };
    // Dark streets: pixels ACES leaves below 24 of 255. Neon: the brightest
    // pixels (ACES luminance above 200), whose colour is the question.
    let dark = |(a, _): &&((f32, f32), (f32, f32))| a.0 < 24.0;
    let bright = |(a, _): &&((f32, f32), (f32, f32))| a.0 > 200.0;
    let dark_aces = mean(&mut pairs.iter().filter(dark).map(|(a, _)| a.0));
    let dark_reinhard = mean(&mut pairs.iter().filter(dark).map(|(_, r)| r.0));
    let neon_aces = mean(&mut pairs.iter().filter(bright).map(|(a, _)| a.1));
    let neon_reinhard = mean(&mut pairs.iter().filter(bright).map(|(_, r)| r.1));
    let neon_brightness = mean(&mut pairs.iter().filter(bright).map(|(_, r)| r.0));
    let neon_brightness_aces = mean(&mut pairs.iter().filter(bright).map(|(a, _)| a.0));
    println!(
        "dark streets: {dark_aces:.1} of 255 under ACES, {dark_reinhard:.1} under Reinhard; the brightest pixels \
         (above 200 under ACES): saturation {neon_aces:.2} under ACES, {neon_reinhard:.2} under Reinhard, \
         brightness {neon_brightness_aces:.0} under ACES, {neon_brightness:.0} under Reinhard"
    );
    measured::DARK_ACES.check("the dark streets under ACES", dark_aces);
    measured::DARK_REINHARD.check("the dark streets under Reinhard", dark_reinhard);
    measured::NEON_SATURATION_ACES.check("the brightest pixels' saturation under ACES", neon_aces);
    measured::NEON_SATURATION_REINHARD.check("the brightest pixels' saturation under Reinhard", neon_reinhard);
    measured::NEON_BRIGHTNESS_ACES.check("the brightest pixels' brightness under ACES", neon_brightness_aces);
    measured::NEON_BRIGHTNESS_REINHARD.check("the brightest pixels' brightness under Reinhard", neon_brightness);
    let _ = std::fs::remove_dir_all(&root);
}

/// Measured: what the exercises of light casters, clustered culling and
/// HDR got by running the chapter's culling and drawing the night city at
/// 320 × 180, the city alone (its countryside switched off), copied with
/// the lessons' solutions, which say they are measured
/// (`common::book_figures::Measured`: change detectors).
mod measured {
    use common::book_figures::Measured;

    /// Clustered culling, exercise 3: the first 16 street lamps' entries in the aerial
    /// view's cluster lists, at 18 m and at 153 m of range, and the ratio.
    pub const LAMP_ENTRIES_AT_18_M: Measured = Measured::new(475.0, 5.0);
    pub const LAMP_ENTRIES_AT_153_M: Measured = Measured::new(35_891.0, 360.0);
    pub const LAMP_LIST_GROWTH: Measured = Measured::new(75.6, 3.8);
    /// Clustered culling, exercise 1: the share of the street view's pixels whose cluster lists the torch.
    pub const TORCH_FROM_THE_STREET: Measured = Measured::new(0.496, 0.02);
    /// Clustered culling, exercise 2: lights a fragment visits at 256 lights with a 16 × 9 ×
    /// 24 grid, what the bench's grids predict that costs, and the lights
    /// that really reach a visible point.
    pub const VISITED_16_9_24: Measured = Measured::new(9.16, 0.18);
    pub const PREDICTED_COST: Measured = Measured::new(3.28, 0.05);
    pub const REACHING_256: Measured = Measured::new(0.70, 0.02);
    /// HDR, exercise 1: dark streets (under 24 of 255 with ACES), their mean;
    /// the brightest pixels (over 200 with ACES), their saturation and brightness.
    pub const DARK_ACES: Measured = Measured::new(18.7, 0.5);
    pub const DARK_REINHARD: Measured = Measured::new(30.4, 0.5);
    pub const NEON_SATURATION_ACES: Measured = Measured::new(0.20, 0.02);
    pub const NEON_SATURATION_REINHARD: Measured = Measured::new(0.33, 0.02);
    pub const NEON_BRIGHTNESS_ACES: Measured = Measured::new(239.0, 3.0);
    pub const NEON_BRIGHTNESS_REINHARD: Measured = Measured::new(208.0, 3.0);
}

// ANCHOR: facet_weighted
/// Physically based shading, exercise 1: what a white non-metal of roughness 0.2, seen at n·v = 0.1,
/// sends back of an even white sky when its diffuse part is weighted by
/// Fresnel at the facet, (1 − F(v·h)), instead of by what Fresnel lets in
/// and out, (1 − F(n·l))(1 − F(n·v)) as brdf.wgsl does.
const FACET_WEIGHTED_FURNACE: f32 = 1.43;
const COUPLED_FURNACE: f32 = 0.85;

#[test]
fn microfacets_exercise_1_weighting_the_diffuse_by_the_facets_fresnel_makes_light() {
    use lighting::pbr::{self, Physical};
    let white = Physical { base_colour: Vec3::ONE, metallic: 0.0, roughness: 0.2 };
    let facet_weighted = |v: Vec3, l: Vec3| {
        let h = (v + l).normalize();
        let alpha = pbr::ggx_alpha(white.roughness);
        let f = pbr::fresnel_schlick(Vec3::splat(pbr::DIELECTRIC_F0), v.dot(h)).x;
        let specular = f * pbr::ggx_distribution(h.z, alpha) * pbr::smith_visibility(v.z, l.z, alpha);
        (1.0 - f) + specular * std::f32::consts::PI
    };
    let naive = crate::pbr::reflected_of_even_sky(0.1, facet_weighted);
    let coupled = crate::pbr::reflected_of_even_sky(0.1, |v, l| pbr::cook_torrance(Vec3::Z, v, l, white).x);
    eprintln!("white furnace at n·v 0.1: facet-weighted {naive:.4}, coupled {coupled:.4}");
    assert!((naive - FACET_WEIGHTED_FURNACE).abs() < 0.005, "{naive}");
    assert!((coupled - COUPLED_FURNACE).abs() < 0.005, "{coupled}");
}
// ANCHOR_END: facet_weighted

// ANCHOR: morning_sun
/// Light arriving, exercise 1: the share of the morning sun's light that a
/// face with `normal` receives, Lambert's n · l clamped at zero.
fn morning_sunlight(normal: Vec3) -> f32 {
    let sun = daylight(TimeOfDay::Morning.phase(0.0, 1.0)).direction;
    normal.dot(sun).max(0.0)
}
// ANCHOR_END: morning_sun

#[test]
fn light_arriving_exercise_1_the_morning_sun_on_roofs_and_walls() {
    // By hand: chapter 06's sunrise, (0.958, 0, 0.287), turned 21.6° about z.
    let sun = daylight(TimeOfDay::Morning.phase(0.0, 1.0)).direction;
    let by_hand = Vec3::new(0.958 * 21.6f32.to_radians().cos(), 0.958 * 21.6f32.to_radians().sin(), 0.287);
    assert!(sun.distance(by_hand) < 2e-3, "the morning sun is {sun}, by hand {by_hand}");
    assert!(sun.distance(Vec3::new(0.891, 0.353, 0.287)) < 1e-3, "{sun}");
    assert!((sun.y.asin().to_degrees() - 20.6).abs() < 0.05, "the sun's elevation");
    for (face, normal, share) in
        [("roof", Vec3::Y, 0.353), ("east", Vec3::X, 0.891), ("south", Vec3::Z, 0.287), ("west", Vec3::NEG_X, 0.0)]
    {
        let got = morning_sunlight(normal);
        println!("the morning sun on a {face}-facing face: {got:.3} of its light");
        assert!((got - share).abs() < 1e-3, "{face}: {got} against {share}");
    }
    // A face turned 60° from the sun gets half.
    let tilt = common::glam::Quat::from_axis_angle(sun.cross(Vec3::Y).normalize(), 60f32.to_radians());
    assert!((morning_sunlight(tilt * sun) - 0.5).abs() < 1e-5);
}

// ANCHOR: scaled_normal
/// Where the loop runs, exercise 1: the normal at the unit sphere's point
/// (1, 1, 0)/√2 after a scale of (2, 1, 1), turned by the model matrix and
/// by the normal matrix `GpuInstance` carries (the inverse transpose).
fn egg_normals() -> (Vec3, Vec3) {
    let model = Mat4::from_scale(Vec3::new(2.0, 1.0, 1.0));
    let normal = Vec3::new(1.0, 1.0, 0.0).normalize();
    let columns = GpuInstance::new(model, Material::Glass).normal.map(|c| Vec3::new(c[0], c[1], c[2]));
    let normal_matrix = Mat3::from_cols(columns[0], columns[1], columns[2]);
    (model.transform_vector3(normal).normalize(), (normal_matrix * normal).normalize())
}
// ANCHOR_END: scaled_normal

#[test]
fn where_the_loop_runs_exercise_1_an_eggs_normal_needs_the_inverse_transpose() {
    let (by_model, by_normal_matrix) = egg_normals();
    // The egg is x²/4 + y² + z² = 1; its normal is the gradient (x/2, 2y, 2z)
    // at the point the sphere's (1, 1, 0)/√2 went to.
    let point = Vec3::new(2.0, 1.0, 0.0) / 2f32.sqrt();
    let gradient = Vec3::new(point.x / 2.0, 2.0 * point.y, 2.0 * point.z).normalize();
    println!("the egg's normal: {by_model} by the model matrix, {by_normal_matrix} by its inverse transpose");
    assert!(by_normal_matrix.distance(gradient) < 1e-5, "{by_normal_matrix} against the gradient {gradient}");
    assert!(by_normal_matrix.distance(Vec3::new(0.447, 0.894, 0.0)) < 1e-3);
    assert!(by_model.distance(Vec3::new(0.894, 0.447, 0.0)) < 1e-3);
    let apart = by_model.dot(by_normal_matrix).acos().to_degrees();
    assert!((apart - 36.9).abs() < 0.05, "{apart}° apart");
}

// ANCHOR: lap
/// Lights that move, exercise 1: a car on a 60 × 40 m rounded rectangle
/// with corners of 10 m, at 10 m/s, leaving the origin facing −z…
fn exercise_path() -> SegmentedPath {
    let segments = SegmentedPath::rounded_rectangle(60.0, 40.0, 10.0, true);
    SegmentedPath { start: Vec2::ZERO, height: 0.0, heading: 0.0, segments, speed: 10.0 }
}

/// …and its clock, paused at `PAUSED_AT` seconds of scene time and resumed at `RESUMED_AT`.
fn paused_clock() -> PausableClock {
    let mut clock = PausableClock::default();
    clock.set_paused(true, PAUSED_AT);
    clock.set_paused(false, RESUMED_AT);
    clock
}

/// The exercise's times (seconds), which the page writes from here: the car's pose is asked
/// after `LAP_POSE_AFTER`, its clock paused and resumed, then read at `READ_AT`.
const LAP_POSE_AFTER: f32 = 5.0;
const PAUSED_AT: f32 = 10.0;
const RESUMED_AT: f32 = 14.0;
const READ_AT: f32 = 19.0;
// ANCHOR_END: lap

/// What the page's solution states: a lap of 182.83 m at 10 m/s, and the clock's reading.
const LAP_SECONDS: f32 = 18.28;
const CLOCK_READS: f32 = 15.0;

#[test]
fn moving_lights_exercise_1_a_lap_a_pose_and_a_pause() {
    let path = exercise_path();
    let pose = path.at(LAP_POSE_AFTER);
    println!(
        "a lap of {} m in {} s; after 5 s at {} facing {} rad",
        path.length(),
        path.period(),
        pose.position,
        pose.heading
    );
    // By hand: straights of 40, 20, 40 and 20 m and four quarter turns of 10 m.
    assert!((path.length() - (120.0 + 4.0 * 10.0 * std::f32::consts::FRAC_PI_2)).abs() < 1e-3);
    assert!((path.length() - 182.83).abs() < 0.005 && (path.period() - LAP_SECONDS).abs() < 0.005);
    // 40 m to (0, −40), then 10 m, one radian, round the turn's centre at (−10, −40).
    let by_hand = Vec3::new(-10.0 + 10.0 * 1f32.cos(), 0.0, -40.0 - 10.0 * 1f32.sin());
    assert!(pose.position.distance(by_hand) < 1e-3, "{} against {by_hand}", pose.position);
    assert!(pose.position.distance(Vec3::new(-4.60, 0.0, -48.41)) < 0.01);
    assert!((pose.heading - 1.0).abs() < 1e-4);
    // By hand: paused for 4 s, the clock reads 4 s behind scene time.
    assert_eq!(paused_clock().time(READ_AT), READ_AT - (RESUMED_AT - PAUSED_AT));
    assert_eq!(paused_clock().time(READ_AT), CLOCK_READS);
}

// ANCHOR: fxaa_edges
/// FXAA, exercise 1: a staircase between two greys given by their
/// lightness (the square root of luminance, as fxaa.wgsl measures it): a
/// straight edge of slope 0.4 drawn at one sample a pixel, `dark` below
/// it and `light` above, in linear light.
fn staircase(dark: f32, light: f32) -> Vec<f32> {
    let (width, height) = crate::fxaa::SIZE;
    let below =
        move |x: u32, y: u32| y as f32 + 0.5 > height as f32 / 2.0 + 0.4 * (x as f32 + 0.5 - width as f32 / 2.0);
    let pixels = (0..height).flat_map(move |y| (0..width).map(move |x| (x, y)));
    pixels.map(|(x, y)| if below(x, y) { dark * dark } else { light * light }).collect()
}
// ANCHOR_END: fxaa_edges

#[test]
fn fxaa_exercise_1_which_steps_between_greys_are_edges() {
    let gpu = Gpu::headless(common::GpuNeeds::default()).expect("an adapter (lavapipe will do)");
    let level = |g: f32| (common::texture::linear_to_srgb(g) * 255.0).round() as u8;
    for (name, dark, light, edge) in
        [("a", 0.50, 0.60, true), ("b", 0.80, 0.88, false), ("c", 0.10, 0.125, false), ("d", 0.10, 0.14, true)]
    {
        // By hand: the spread against max(0.0312, 0.125 × the brightest).
        assert_eq!(light - dark >= f32::max(0.0312, 0.125 * light), edge, "({name}) by hand");
        let picture = staircase(dark, light);
        let smoothed = crate::fxaa::fxaa(&gpu, &picture);
        let changed = picture.iter().zip(&smoothed).filter(|(a, b)| level(**a) != level(**b)).count();
        println!("({name}) lightness {dark} against {light}: FXAA changes {changed} pixels");
        if edge {
            assert!(changed >= 100, "({name}) is an edge, but FXAA changed {changed} pixels");
        } else {
            assert_eq!(changed, 0, "({name}) is no edge, but FXAA changed {changed} pixels");
        }
    }
}

// ANCHOR: monte_carlo
/// The sky as a light, exercise 1: the i-th of n Hammersley points, as
/// brdf.wgsl's `hammersley` makes them…
fn hammersley(i: u32, n: u32) -> (f32, f32) {
    (i as f32 / n as f32, i.reverse_bits() as f32 * 2.328_306_4e-10)
}

/// …and ∫ n·l dω over the hemisphere estimated from the first n of them:
/// each sample's cos θ divided by the density of its direction, averaged.
/// Evenly: cos θ = 1 − u₂, density 1/2π. Cosine-weighted: cos θ = √(1 − u₂),
/// density cos θ / π. (The angle round the normal, 2π u₁, changes neither.)
fn cosine_integral(n: u32, cosine_weighted: bool) -> f32 {
    let sample = |i| {
        let (_, u2) = hammersley(i, n);
        let (cos_theta, density) =
            if cosine_weighted { ((1.0 - u2).sqrt(), (1.0 - u2).sqrt() / PI) } else { (1.0 - u2, 1.0 / (2.0 * PI)) };
        cos_theta / density
    };
    (0..n).map(sample).sum::<f32>() / n as f32
}
// ANCHOR_END: monte_carlo

#[test]
fn sky_light_exercise_1_monte_carlo_and_importance_sampling() {
    // The same points as the shader's.
    let brdf =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../shaders/lighting/brdf.wgsl")).unwrap();
    assert!(brdf.contains("vec2<f32>(f32(i) / f32(n), f32(reverseBits(i)) * 2.3283064365386963e-10)"));
    let (even, even_1024) = (cosine_integral(16, false), cosine_integral(1024, false));
    println!(
        "∫ n·l dω = π: evenly {even:.4} (16 points), {even_1024:.4} (1,024); cosine-weighted {}",
        cosine_integral(16, true)
    );
    // By hand: the second coordinates are 0, 1/16, …, 15/16 once each.
    assert!((even - 2.0 * PI * 17.0 / 32.0).abs() < 1e-5 && (even - 3.338).abs() < 5e-4);
    assert!((even_1024 - 2.0 * PI * 1025.0 / 2048.0).abs() < 1e-4 && (even_1024 - 3.145).abs() < 5e-4);
    for n in [1, 16, 1024] {
        assert!((cosine_integral(n, true) - PI).abs() < 1e-4, "{n} cosine-weighted points");
    }
}

// ANCHOR: cube_level
/// The sky as a mirror, exercise 1: the level of the prefiltered cube a
/// surface of `roughness` reads (`sky_light` in lights.wgsl), and the two
/// levels trilinear filtering blends for it, with the share of the second.
fn cube_levels(roughness: f32) -> (f32, u32, u32, f32) {
    let level = roughness.clamp(0.0, 1.0) * (PrefilteredSky::LEVELS - 1) as f32;
    let below = (level.floor() as u32).min(PrefilteredSky::LEVELS - 1);
    let above = (below + 1).min(PrefilteredSky::LEVELS - 1);
    (level, below, above, level - below as f32)
}
// ANCHOR_END: cube_level

#[test]
fn prefiltered_sky_exercise_1_the_levels_a_sphere_reads() {
    let lights =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../shaders/lighting/lights.wgsl")).unwrap();
    assert!(lights.contains("let level = clamp(surface.roughness, 0.0, 1.0) * f32(textureNumLevels(sky_cube) - 1u);"));
    let roughness = material_spheres::ROUGHNESS[2];
    let (level, below, above, share) = cube_levels(roughness);
    println!(
        "roughness {roughness}: level {level}, {:.0} % of level {below} and {:.0} % of level {above}",
        100.0 * (1.0 - share),
        100.0 * share
    );
    assert!((level - 1.2).abs() < 1e-5 && (below, above) == (1, 2) && (share - 0.2).abs() < 1e-5);
    assert_eq!((PrefilteredSky::SIZE >> below, PrefilteredSky::SIZE >> above), (32, 16));
    let blurred_for = [below, above].map(PrefilteredSky::roughness_of);
    assert!((blurred_for[0] - 1.0 / 3.0).abs() < 1e-6 && (blurred_for[1] - 2.0 / 3.0).abs() < 1e-6);
    assert!(((1.0 - share) * blurred_for[0] + share * blurred_for[1] - roughness).abs() < 1e-6);
    // The last sphere reads the last level alone.
    let (level, below, _, share) = cube_levels(material_spheres::ROUGHNESS[5]);
    assert!(level == 3.0 && below == 3 && share == 0.0);
    assert_eq!((PrefilteredSky::SIZE >> below, PrefilteredSky::roughness_of(below)), (8, 1.0));
}

// ANCHOR: bright_by_hand
/// Bloom, exercise 1: what blooms of two lamps, worked by hand from the knee's formula
/// (threshold 1, knee 0.5): above 1.5 the excess over 1, inside the knee (b − 0.5)² / 2,
/// the whole colour scaled alike.
const BRIGHT_LAMP: ([f32; 3], [f32; 3]) = ([3.0, 1.5, 0.6], [2.0, 1.0, 0.4]);
const KNEE_LAMP: ([f32; 3], [f32; 3]) = ([1.2, 0.6, 0.24], [0.245, 0.1225, 0.049]);
// ANCHOR_END: bright_by_hand

#[test]
fn bloom_exercise_1_what_blooms_of_two_lamps() {
    let settings = lighting::bloom::BloomSettings::DEFAULT;
    assert_eq!((settings.threshold, settings.knee), (1.0, 0.5), "the exercise states these settings");
    for (lamp, by_hand) in [BRIGHT_LAMP, KNEE_LAMP] {
        let blooms = settings.bright_part(lamp);
        println!("{lamp:?} blooms {blooms:?}, by hand {by_hand:?}");
        // 1e-4: the formula's 1e-5 guards against dividing by zero.
        assert!((0..3).all(|c| (blooms[c] - by_hand[c]).abs() < 1e-4), "{lamp:?}: {blooms:?} against {by_hand:?}");
    }
}
