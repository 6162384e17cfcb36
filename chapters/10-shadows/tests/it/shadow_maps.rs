//! Shadows against geometry: a box above a plane casts the shadow that
//! rays towards the sun say it must; taking the bias away makes lit faces
//! shadow themselves; the scripted run gives the same picture every time.
//! And the map itself: its size clamped, its Poisson disk, its box
//! snapped to whole texels.

use common::glam::{Quat, Vec2, Vec3};
use common::headless::{OFFSCREEN_FORMAT, Offscreen, capture, read_floats};
use common::{Camera, Chapter, Gpu, Target, primitives, wgpu};
use lighting::lights::{Daylight, daylight};
use lighting::{HDR_FORMAT, Highlight, LoopOptions, SceneLights};
use shadows::light_box::{SECTION_AT, SECTION_LIT_AT, through_box};
use shadows::shadow_map::{self, Bias, Filter, ShadowMap, ShadowSettings, fit_light};
use shadows::{ShadowedRenderer, ShadowsChapter, Show, game, scene};
use textures::materials::{Materials, Uploader};
use textures::mesh::{MaterialDesc, ModelData, ModelInstance};
use textures::mipmaps::MipMaker;
use textures::{Draw, DrawList, upload_model};

const WIDTH: u32 = 320;
const HEIGHT: u32 = 240;

/// The box: a metre cube floating with its bottom 1.5 m above the plane.
const BOX_MIN: Vec3 = Vec3::new(-0.5, 1.5, -0.5);
const BOX_MAX: Vec3 = Vec3::new(0.5, 2.5, 0.5);
/// The plane: y = 0, 12 m square.
const PLANE_HALF: f32 = 6.0;

/// Where the ray from `origin` along `direction` enters the box, if it does
/// (the slab test).
fn hits_box(origin: Vec3, direction: Vec3) -> Option<f32> {
    let inverse = direction.recip();
    let t0 = (BOX_MIN - origin) * inverse;
    let t1 = (BOX_MAX - origin) * inverse;
    let near = t0.min(t1).max_element();
    let far = t0.max(t1).min_element();
    (far >= near.max(0.0)).then_some(near)
}

/// What the plane point `p` is by geometry: in the box's shadow or not.
fn in_shadow(p: Vec3, towards_sun: Vec3) -> bool {
    hits_box(p, towards_sun).is_some()
}

// ANCHOR: analytic
#[test]
fn a_box_above_a_plane_casts_the_shadow_geometry_predicts() {
    let gpu = Gpu::headless(ShadowsChapter::gpu_needs()).unwrap();
    let device = &gpu.device;
    // The scene, as chapter 09 models: a plane and a box, plain materials.
    let grey = MaterialDesc::plain("grey", Vec3::splat(0.5), 0.0, 1.0);
    let mut plane = ModelData::from_mesh(&primitives::plane(1), grey.clone());
    plane.vertices.iter_mut().for_each(|v| v.position = (Vec3::from(v.position) * 2.0 * PLANE_HALF).into());
    let mut cube = ModelData::from_mesh(&primitives::cube(), grey);
    let centre = (BOX_MIN + BOX_MAX) / 2.0;
    cube.vertices.iter_mut().for_each(|v| v.position = (Vec3::from(v.position) + centre).into());
    let mut mips = MipMaker::new(&gpu).unwrap();
    let mut up = Uploader::new(&gpu, &mut mips, &scene::read);
    let mut materials = Materials::new(&mut up);
    let plane = upload_model(&mut up, &mut materials, &plane, "plane");
    let cube = upload_model(&mut up, &mut materials, &cube, "box");
    up.finish();

    // A sun from the left, in front, 50° up; a camera above the shadow,
    // looking down at it.
    let towards_sun = Vec3::new(-0.55, 0.77, 0.32).normalize();
    let day = Daylight { direction: towards_sun, ..daylight(0.5) };
    let camera = Camera::looking_at(Vec3::new(1.4, 6.0, 3.0), Vec3::new(1.4, 0.0, -0.8), WIDTH as f32 / HEIGHT as f32);
    let corners = [-1.0, 1.0].map(|x| [-1.0, 1.0].map(|z| Vec3::new(x * PLANE_HALF, 0.0, z * PLANE_HALF)));
    let focus: Vec<Vec3> = corners.iter().flatten().copied().chain([BOX_MIN, BOX_MAX]).collect();
    let bounds = (Vec3::new(-PLANE_HALF, 0.0, -PLANE_HALF), Vec3::new(PLANE_HALF, BOX_MAX.y, PLANE_HALF));
    let settings = ShadowSettings { size: 1024, filter: Filter::Hard, bias: Bias::DEFAULT, ..Default::default() };
    let light = fit_light(towards_sun, &focus, bounds, settings.size);

    let mut lights = SceneLights::new(&gpu).unwrap();
    let options = LoopOptions { culling: false, highlight: Highlight::BlinnPhong, heat_map: false };
    lights.write(&gpu, &camera, &day, &[], &Default::default(), options);
    let mut shadow = ShadowMap::new(&gpu, settings.size).unwrap();
    let renderer = ShadowedRenderer::new(&gpu, &lights, &materials, &shadow, Default::default()).unwrap();
    let instances = wgpu::util::DeviceExt::create_buffer_init(
        device,
        &wgpu::util::BufferInitDescriptor {
            label: Some("instances"),
            contents: bytemuck::cast_slice(&[ModelInstance::new(common::glam::Mat4::IDENTITY, 1.0)]),
            usage: wgpu::BufferUsages::VERTEX,
        },
    );
    let list = DrawList {
        materials: &materials,
        instances: &instances,
        draws: vec![Draw { model: &plane, instances: 0..1 }, Draw { model: &cube, instances: 0..1 }],
    };
    let Offscreen { texture: target, view } =
        Offscreen::new(device, Target { format: HDR_FORMAT, width: WIDTH, height: HEIGHT, samples: 1 });
    let depth = common::texture::depth_view(device, WIDTH, HEIGHT);
    // The picture, lit by the sun towards `towards_sun`, with the map made
    // for a sun towards `map_sun`.
    let mut sunlit = |map_sun: Vec3| {
        shadow.write(&gpu, &fit_light(map_sun, &focus, bounds, settings.size), &settings);
        let mut encoder = device.create_command_encoder(&Default::default());
        let timer = common::PassTimer::off();
        shadow.render(&gpu, &mut encoder, &timer, &settings, &list);
        {
            let mut pass =
                common::chapter::scene_pass(&mut encoder, &timer, "sunlit", &view, wgpu::Color::BLACK, &depth);
            pass.set_bind_group(0, &lights.group, &[]);
            renderer.draw(&mut pass, &shadow, &list, true);
        }
        gpu.queue.submit([encoder.finish()]);
        read_floats(&gpu, &target).unwrap()
    };

    // Every pixel that shows the plane, checked against the ray towards
    // the sun from the point it shows. Within a few texels of the shadow's
    // edge either answer is fair: the map's texels are that coarse, and the
    // normal offset moves the lookup by one.
    let inverse = camera.view_projection().inverse();
    let margin = 3.0 * light.texel;
    let check = |pixels: &[[f32; 4]]| {
        let (mut checked, mut shadowed, mut wrong) = (0, 0, Vec::new());
        for y in 0..HEIGHT {
            for x in 0..WIDTH {
                let ndc = Vec2::new(
                    (x as f32 + 0.5) / WIDTH as f32 * 2.0 - 1.0,
                    1.0 - (y as f32 + 0.5) / HEIGHT as f32 * 2.0,
                );
                let near = inverse.project_point3(ndc.extend(0.0));
                let far = inverse.project_point3(ndc.extend(1.0));
                let direction = (far - near).normalize();
                let t = -near.y / direction.y;
                let p = near + direction * t;
                let on_plane = p.x.abs() < PLANE_HALF - margin && p.z.abs() < PLANE_HALF - margin;
                if !on_plane || hits_box(near, direction).is_some_and(|hit| hit < t) {
                    continue;
                }
                let expected = in_shadow(p, towards_sun);
                let near_edge = [Vec3::X, Vec3::NEG_X, Vec3::Z, Vec3::NEG_Z]
                    .iter()
                    .any(|d| in_shadow(p + *d * margin, towards_sun) != expected);
                if near_edge {
                    continue;
                }
                let sunlit = pixels[(y * WIDTH + x) as usize][0];
                checked += 1;
                shadowed += usize::from(expected);
                if (sunlit < 0.5) != expected {
                    wrong.push((x, y, p, sunlit));
                }
            }
        }
        (checked, shadowed, wrong)
    };
    let (checked, shadowed, wrong) = check(&sunlit(towards_sun));
    assert!(checked > 20_000 && shadowed > 1_000, "{checked} plane pixels checked, {shadowed} of them in shadow");
    assert!(
        wrong.is_empty(),
        "{} of {checked} pixels disagree with geometry, e.g. {:?}",
        wrong.len(),
        &wrong[..wrong.len().min(5)]
    );

    // The test can fail: the map made for a sun 7.7° lower (42.7° high
    // instead of 50.4°, nothing else changed) moves the shadow by 0.4 to
    // 0.6 m, and 757 of the 59,340 pixels checked disagree on lavapipe.
    // Which pixels fall between the two shadows is geometry; a rasteriser
    // changes only the map's texels along the edges: 5 % either way.
    let lower = Quat::from_axis_angle(Vec3::Y.cross(towards_sun).normalize(), 7.7f32.to_radians()) * towards_sun;
    let (_, _, wrong) = check(&sunlit(lower));
    eprintln!("with the map's sun 7.7° lower, {} of {checked} pixels disagree", wrong.len());
    assert_eq!(checked, 59_340);
    assert!(wrong.len().abs_diff(757) <= 38, "with the map's sun 7.7° lower, {} pixels disagree, not 757", wrong.len());
}
// ANCHOR_END: analytic

/// Pixels whose surface faces the sun and yet get less than half its light.
fn shadowed_lit_faces(gpu: &Gpu, view: &str) -> (usize, usize) {
    let target = Target { format: OFFSCREEN_FORMAT, width: 480, height: 270, samples: 1 };
    let mut chapter = ShadowsChapter::new(gpu, target, ()).unwrap();
    let index = common::chapter::view_index::<ShadowsChapter>(view).unwrap();
    chapter.settings = shadows::Settings { show: Show::Sunlit, ..shadows::VIEW_TABLE[index].settings };
    let image = capture(gpu, &mut chapter, target, (ShadowsChapter::SNAPSHOT_TIME, index), Default::default()).unwrap();
    let facing = image.pixels().filter(|p| p[1] > 128).count();
    let dark = image.pixels().filter(|p| p[1] > 128 && p[0] < 128).count();
    (dark, facing)
}

// ANCHOR: acne
#[test]
fn without_bias_lit_faces_shadow_themselves() {
    let gpu = Gpu::headless(ShadowsChapter::gpu_needs()).unwrap();
    let (acne, facing) = shadowed_lit_faces(&gpu, "acne");
    let (biased, facing_too) = shadowed_lit_faces(&gpu, "default");
    assert_eq!(facing, facing_too, "the same surfaces face the sun in both");
    eprintln!("shadowed pixels on faces towards the sun: {acne} without bias, {biased} with, of {facing}");
    // Real shadows fall on sunward faces too (the ground behind a wall),
    // so the biased count is not zero; acne adds its stripes on top.
    assert!(acne as f64 > 1.5 * biased as f64 + 1000.0, "acne: {acne}, biased: {biased}, of {facing}");
}
// ANCHOR_END: acne

#[test]
fn the_scripted_run_gives_the_same_bytes_however_it_was_reached() {
    let gpu = Gpu::headless(ShadowsChapter::gpu_needs()).unwrap();
    let target = Target { format: OFFSCREEN_FORMAT, width: 320, height: 180, samples: 1 };
    let picture = |times: &[f32]| {
        let mut chapter = ShadowsChapter::new(&gpu, target, ()).unwrap();
        let mut last = None;
        for &time in times {
            last = Some(capture(&gpu, &mut chapter, target, (time, 0), Default::default()).unwrap());
        }
        last.unwrap()
    };
    let fresh = picture(&[5.7]);
    assert_eq!(fresh.as_raw(), picture(&[5.7]).as_raw(), "two fresh runs to 5.7 s");
    // A window plays the demo forward frame by frame, and a rewound clock
    // replays it from the start: either way, the same picture.
    assert_eq!(fresh.as_raw(), picture(&[1.0, 3.3, 5.7]).as_raw(), "stepped on from earlier frames");
    assert_eq!(fresh.as_raw(), picture(&[9.0, 5.7]).as_raw(), "after going back in time");
    assert_ne!(fresh.as_raw(), picture(&[5.9]).as_raw(), "a fifth of a second later, the player has moved");
}

#[test]
fn a_bad_shadow_map_size_is_named_and_a_huge_one_is_clamped_with_a_note() {
    let run = |size: &str| {
        let out = std::env::temp_dir().join(format!("shadows-flag-{}-{size}.png", std::process::id()));
        let output = std::process::Command::new(env!("CARGO_BIN_EXE_shadows"))
            .args(["--screenshot", out.to_str().unwrap(), "--size", "64x36", "--shadow-map-size", size])
            .output()
            .unwrap();
        let _ = std::fs::remove_file(&out);
        (output.status.code(), String::from_utf8_lossy(&output.stderr).into_owned())
    };
    let (code, stderr) = run("lots");
    assert_eq!(code, Some(2), "{stderr}");
    assert!(stderr.contains("--shadow-map-size") && stderr.contains("'lots'"), "{stderr}");
    let (code, stderr) = run("100000");
    assert_eq!(code, Some(0), "{stderr}");
    assert!(stderr.contains("using 4096²"), "{stderr}");
}

#[test]
fn a_key_takes_over_from_the_demo_and_every_key_at_once_breaks_nothing() {
    use common::Input;
    use common::winit::keyboard::KeyCode;
    let gpu = Gpu::headless(ShadowsChapter::gpu_needs()).unwrap();
    let target = Target { format: OFFSCREEN_FORMAT, width: 160, height: 90, samples: 1 };
    let mut chapter = ShadowsChapter::new(&gpu, target, ()).unwrap();
    let demo = capture(&gpu, &mut chapter, target, (0.0, 0), Default::default()).unwrap();
    let mut input = Input::default();
    chapter.update(&input, 1.0 / 60.0);
    assert!(chapter.played_by_keys().is_none(), "no key, still the demo");
    input.key_down(KeyCode::KeyD);
    for _ in 0..60 {
        chapter.update(&input, 1.0 / 60.0);
        input.end_frame();
    }
    let game = *chapter.played_by_keys().expect("D took over");
    assert!(game.player.aabb.min.x > game::level().spawn.x + 2.0, "ran right: {:?}", game.player.aabb);
    assert_ne!(
        demo.as_raw(),
        capture(&gpu, &mut chapter, target, (0.0, 0), Default::default()).unwrap().as_raw(),
        "the camera followed"
    );
    // Every key at once, frames of every length, a window hidden for an hour.
    for key in [KeyCode::KeyA, KeyCode::ArrowLeft, KeyCode::ArrowRight, KeyCode::Space, KeyCode::KeyW, KeyCode::ArrowUp]
    {
        input.key_down(key);
    }
    for dt in [0.0, 1e-7, 1.0 / 30.0, 3600.0, f32::NAN, -1.0] {
        chapter.update(&input, dt);
        input.end_frame();
    }
    // Let go: the player comes to rest on whatever it landed on.
    input.release_all();
    for _ in 0..240 {
        chapter.update(&input, 1.0 / 60.0);
    }
    let rest = chapter.played_by_keys().unwrap().player;
    assert_eq!(rest.velocity, Vec2::ZERO, "{rest:?}");
    let solids = game::level().solids();
    assert!(shadows::physics::standing(&rest.aabb, &solids), "{rest:?}");
}

#[test]
fn sizes_are_clamped_to_the_chapter_and_the_adapter_with_a_note() {
    assert_eq!(shadow_map::clamp_size(2048, 8192), (2048, None));
    let (size, note) = shadow_map::clamp_size(16384, 8192);
    assert_eq!(size, 4096);
    assert!(note.unwrap().contains("using 4096²"));
    assert_eq!(shadow_map::clamp_size(100, 8192).0, 512);
    // WebGL 2 promises only 2048.
    let (size, note) = shadow_map::clamp_size(4096, 2048);
    assert_eq!(size, 2048);
    assert!(note.unwrap().contains("at most 2048²"));
}

#[test]
fn the_poisson_disk_is_sixteen_well_spread_points_in_the_unit_disk() {
    let source = include_str!("../../../../shaders/shadows/shadow.wgsl");
    let table = source.split("const POISSON").nth(1).unwrap().split(");").next().unwrap();
    let points: Vec<[f32; 2]> = table
        .split("vec2<f32>(")
        .skip(1)
        .map(|p| {
            let numbers: Vec<f32> =
                p.split(')').next().unwrap().split(',').map(|n| n.trim().parse().unwrap()).collect();
            [numbers[0], numbers[1]]
        })
        .collect();
    assert_eq!(points.len(), 16);
    let mut closest = f32::MAX;
    for (i, a) in points.iter().enumerate() {
        assert!(a[0].hypot(a[1]) <= 1.0, "{a:?} is outside the unit disk");
        for b in &points[i + 1..] {
            closest = closest.min((a[0] - b[0]).hypot(a[1] - b[1]));
        }
    }
    assert!(closest >= 0.43, "two points only {closest} apart");
}

// ANCHOR: snapping_test
#[test]
fn sliding_the_view_moves_the_box_by_whole_texels_and_keeps_its_size() {
    let towards_sun = Vec3::new(-0.7, 0.58, 0.41).normalize();
    let view = [Vec3::new(-18.0, -9.0, 4.0), Vec3::new(18.0, 10.0, 4.0), Vec3::new(-22.0, -11.0, -4.0)];
    let bounds = (Vec3::new(-5.0, -6.0, -4.0), Vec3::new(125.0, 9.0, 4.0));
    let first = fit_light(towards_sun, &view, bounds, 2048);
    for slide in [0.013, 0.5, 7.31, 40.77] {
        let moved: Vec<Vec3> = view.iter().map(|p| *p + Vec3::new(slide, slide * 0.3, 0.0)).collect();
        let next = fit_light(towards_sun, &moved, bounds, 2048);
        assert_eq!(next.texel, first.texel, "the texel's size changed after sliding {slide} m");
        // A world point lands on the map a whole number of texels from
        // where it landed before: texel edges stay put on the ground.
        let p = Vec3::new(3.0, 0.0, 1.0);
        let shift = (next.view_proj.project_point3(p) - first.view_proj.project_point3(p)) * 1024.0;
        for axis in [shift.x, shift.y] {
            assert!((axis - axis.round()).abs() < 0.02, "moved {axis} texels after sliding {slide} m");
        }
    }
}
// ANCHOR_END: snapping_test

/// The sun's box in the chapter's default picture (the demo at
/// `ShadowsChapter::SNAPSHOT_TIME`, the game's camera at 16:9, the default
/// sun, a 2048² map) and over the demo: the figures the lessons on the two
/// passes, the sun's box and acne write from these constants. The test
/// below works each out a second way, from distances along the sun's
/// direction (dot products, not `fit_light`'s matrices), checks that
/// `fit_light`'s box agrees, and that the constant is what it found.
mod sun_box {
    /// Metres from the box's near face to its far face, in the default
    /// picture, and the most over the demo (the player stopped at its end).
    pub const DEFAULT_DEPTH_M: f32 = 112.74;
    pub const DEEPEST_M: f32 = 119.81;
    /// Seconds into the demo when the box first grows deeper than in the
    /// default picture (to the 60th of a second the test steps by).
    pub const DEEPENS_FROM_S: f32 = 19.43;
    /// The box's sides: the farthest of the eight visible points from their
    /// bounding box's middle, metres, and the square's width around the
    /// sphere of that radius rounded up to half a metre.
    pub const REACH_M: f32 = 22.11;
    pub const WIDTH_M: f32 = 45.0;
    /// The map's column both points of the shadow test's section land in.
    pub const SECTION_COLUMN: u32 = 901;
    /// The shadow test's section (`light_box::SECTION_AT`, drawn by
    /// `diagrams/src/shadows.rs`): A's depth in the map (its texel holds
    /// the same), what B's texel holds (the third platform's top), and B's
    /// own depth.
    pub const LIT_DEPTH: f32 = 0.2407;
    pub const BLOCKER_DEPTH: f32 = 0.2462;
    pub const SHADOWED_DEPTH: f32 = 0.2768;
    /// The depth in the map of the rock beside the player (the foot of the
    /// one at x = 28 m; the player stands at 31 m).
    pub const ROCK_DEPTH: f32 = 0.296;
}

#[test]
fn the_sun_boxs_figures_on_the_pages_are_the_boxs_of_the_default_picture_and_the_demo() {
    use shadows::{CAMERA_DISTANCE, Settings, side_camera, visible_part};
    let level = game::level();
    let bounds = scene::level_bounds(&level);
    let towards_sun = scene::sun_at(Settings::DEFAULT.phase).direction;
    let (low, high) = bounds;
    let corners: Vec<Vec3> = (0..8)
        .map(|i| Vec3::new([low.x, high.x][i & 1], [low.y, high.y][(i >> 1) & 1], [low.z, high.z][i >> 2]))
        .collect();
    // Each picture's box, and its depth and near face worked out by hand: a
    // metre beyond the farthest of the level's corners and the visible
    // points along the sun's direction, at either end.
    let fitted_at = |time: f32| {
        let player = game::demo_at(&level, &level.solids(), time).player.aabb.centre();
        let focus = visible_part(&side_camera(player, CAMERA_DISTANCE, 16.0 / 9.0), bounds.1.z);
        let along: Vec<f32> = corners.iter().chain(&focus).map(|p| p.dot(towards_sun)).collect();
        let nearest_the_sun = along.iter().copied().fold(f32::MIN, f32::max) + 1.0;
        let farthest = along.iter().copied().fold(f32::MAX, f32::min) - 1.0;
        let light = fit_light(towards_sun, &focus, bounds, shadow_map::DEFAULT_SIZE);
        (light, nearest_the_sun, nearest_the_sun - farthest)
    };
    let near = |value: f32, expected: f32, within: f32, what: &str| {
        assert!((value - expected).abs() <= within, "{what} is {value}, where the pages have {expected}");
    };
    let (light, face, depth) = fitted_at(ShadowsChapter::SNAPSHOT_TIME);
    // The sides: a sphere around the visible points, a square around it.
    let player = game::demo_at(&level, &level.solids(), ShadowsChapter::SNAPSHOT_TIME).player.aabb.centre();
    let focus = visible_part(&side_camera(player, CAMERA_DISTANCE, 16.0 / 9.0), bounds.1.z);
    let (lowest, highest) = focus.iter().fold((Vec3::MAX, Vec3::MIN), |(lo, hi), p| (lo.min(*p), hi.max(*p)));
    let reach = focus.iter().map(|p| p.distance((lowest + highest) / 2.0)).fold(0.0, f32::max);
    near(reach, sun_box::REACH_M, 0.005, "the farthest visible point from the middle, m");
    let width = light.texel * shadow_map::DEFAULT_SIZE as f32;
    assert_eq!(width, 2.0 * (reach * 2.0).ceil() / 2.0, "the square is not the rounded sphere's");
    near(width, sun_box::WIDTH_M, 1e-4, "the box's width, m");
    assert!((light.depth - depth).abs() < 1e-3, "fit_light's box is {} m deep, by hand {depth} m", light.depth);
    near(depth, sun_box::DEFAULT_DEPTH_M, 0.005, "the default picture's box depth, m");
    // There both its ends come from the level's corners, not the view's.
    let along_corners = corners.iter().map(|p| p.dot(towards_sun));
    let spread = along_corners.clone().fold(f32::MIN, f32::max) - along_corners.fold(f32::MAX, f32::min);
    assert!((spread + 2.0 - depth).abs() < 1e-3, "the view reaches beyond the level's corners");
    // A point's depth in the map: its distance from the near face over the
    // box's depth, by hand and through fit_light's box.
    let by_hand = |p: Vec3| (face - p.dot(towards_sun)) / depth;
    let in_map = |p: Vec3| light.view_proj.project_point3(p).z;

    // Over the demo, frame by frame at 60 Hz, until the player has stopped.
    let mut deepest = depth;
    let mut deepens_from = None;
    for frame in 0..=22 * 60 {
        let time = frame as f32 / 60.0;
        let (_, _, d) = fitted_at(time);
        deepest = deepest.max(d);
        if deepens_from.is_none() && d > depth + 1e-3 {
            deepens_from = Some(time);
        }
    }
    near(deepest, sun_box::DEEPEST_M, 0.005, "the deepest box over the demo, m");
    near(deepens_from.expect("the box deepens"), sun_box::DEEPENS_FROM_S, 0.5 / 60.0, "when it deepens, s");

    // The shadow test's section: A's ray meets no block before A; B's
    // meets the platform's top, 3.45 m nearer the sun.
    let along_ground = Vec3::new(towards_sun.x, 0.0, towards_sun.z).normalize();
    let shadowed = Vec3::new(SECTION_AT, 0.0, 0.0);
    let lit = shadowed + along_ground * SECTION_LIT_AT;
    let first_surface = |p: Vec3| {
        let t = level
            .blocks
            .iter()
            .filter_map(|b| through_box(p, towards_sun, (b.aabb.min.extend(-b.depth), b.aabb.max.extend(b.depth))))
            .map(|(_, out)| out)
            .fold(0.0, f32::max);
        p + towards_sun * t
    };
    assert_eq!(first_surface(lit), lit, "A's ray meets a block");
    let column = |p: Vec3| ((light.view_proj.project_point3(p).x * 0.5 + 0.5) * shadow_map::DEFAULT_SIZE as f32) as u32;
    assert_eq!(
        (column(lit), column(shadowed)),
        (sun_box::SECTION_COLUMN, sun_box::SECTION_COLUMN),
        "the section's column"
    );
    let blocker = first_surface(shadowed);
    near(blocker.distance(shadowed), 3.45, 0.005, "B's distance behind its blocker, m");
    for (point, expected, what) in [
        (lit, sun_box::LIT_DEPTH, "A's depth"),
        (blocker, sun_box::BLOCKER_DEPTH, "the depth B's texel holds"),
        (shadowed, sun_box::SHADOWED_DEPTH, "B's depth"),
    ] {
        assert!(
            (in_map(point) - by_hand(point)).abs() < 1e-5,
            "{what}: {} in the map, {} by hand",
            in_map(point),
            by_hand(point)
        );
        near(by_hand(point), expected, 0.00005, what);
    }
    // The rock beside the player, in the range [0.25, 0.5) where a step of
    // a 32-bit float is 2⁻²⁵, as the acne lesson says.
    let rock = level
        .props
        .iter()
        .filter(|p| p.kind == game::PropKind::Rock)
        .min_by(|a, b| (a.base.x - player.x).abs().total_cmp(&(b.base.x - player.x).abs()))
        .expect("the level has rocks");
    near(by_hand(rock.base), sun_box::ROCK_DEPTH, 0.0005, "the rock's depth");
    assert!((0.25..0.5).contains(&in_map(rock.base)), "the rock's depth left [0.25, 0.5)");
}
