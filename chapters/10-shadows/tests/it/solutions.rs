//! Worked solutions to the exercises of chapter 10's lessons, each named
//! by its lesson and its number there (the acne lesson's exercise 1 is
//! "Acne, exercise 1"). Each makes the change its exercise asks for and
//! asserts the figure the lesson's solution states, so that the solutions
//! are built and checked with the chapter.

use common::glam::{Mat4, Vec2, Vec3};
use common::headless::{OFFSCREEN_FORMAT, capture};
use common::{Camera, Chapter, Gpu, ShaderFile, Target, shader};
use shadows::game::{self, Controls, Game, JUMP_SPEED, PropKind, STEP};
use shadows::parallax::{LAYERS, Layer};
use shadows::point_shadow::CubeFace;
use shadows::shadow_map::{Bias, Cull, Filter, LightBox, ShadowSettings, fit_light};
use shadows::{CAMERA_DISTANCE, Settings, ShadowsChapter, Show, scene, side_camera, visible_part};
use textures::mesh::ModelInstance;

/// `file` with `edits` made to the text of `path` (the file itself or a
/// module it imports), composed with its imports and validated by naga.
/// Each edit's `before` must occur exactly once.
fn compiles_with(file: ShaderFile, path: &str, edits: &[(&str, &str)]) {
    file.compose_edited(path, edits).unwrap_or_else(|e| panic!("{e}"));
}

/// What the shadow map says in one picture of the `Show::Sunlit` kind
/// (red: the sun that arrives, green: whether the surface faces the sun).
#[derive(Clone, Copy, Debug)]
struct Sunlit {
    /// Pixels whose surface faces the sun…
    facing: usize,
    /// …and of those, the ones the map puts in shadow (under half the sun).
    facing_shadowed: usize,
    /// Pixels whose surface faces away from the sun that the map calls lit.
    away_lit: usize,
}

/// Counts what [`Sunlit`] says in a picture of the level at `time` with
/// `settings`, shown as `Show::Sunlit`.
fn sunlit(gpu: &Gpu, chapter: &mut ShadowsChapter, settings: Settings, time: f32) -> Sunlit {
    let target = Target { format: OFFSCREEN_FORMAT, width: 320, height: 180, samples: 1 };
    chapter.settings = Settings { show: Show::Sunlit, ..settings };
    let image = capture(gpu, chapter, target, (time, 0), Default::default()).unwrap();
    let pixels: Vec<_> = image.pixels().collect();
    Sunlit {
        facing: pixels.iter().filter(|p| p[1] > 128).count(),
        facing_shadowed: pixels.iter().filter(|p| p[1] > 128 && p[0] < 128).count(),
        away_lit: pixels.iter().filter(|p| p[1] <= 128 && p[0] >= 128).count(),
    }
}

// ANCHOR: bias_search
/// Acne, exercise 1: the acne is gone when no more sun-facing pixels are
/// in shadow than with the default bias, give or take this share of them
/// (per cent); then each bias found is raised this many times over.
const SAME_WITHIN_PERCENT: usize = 1;
const RAISED_BY: f32 = 64.0;

/// Acne, exercise 1: the smallest bias of one kind that removes the acne, the
/// other kind at zero. `bias(x)` makes the bias for a value `x`; the acne
/// is gone when no more sun-facing pixels are in shadow than with the
/// chapter's default bias, give or take `SAME_WITHIN_PERCENT` of them.
fn smallest_bias_without_acne(
    gpu: &Gpu,
    chapter: &mut ShadowsChapter,
    bias: impl Fn(f32) -> Bias,
    values: &[f32],
) -> (f32, Vec<(f32, usize)>) {
    let time = ShadowsChapter::SNAPSHOT_TIME;
    let reference = sunlit(gpu, chapter, Settings::hard_with(Bias::DEFAULT), time);
    let mut counts = Vec::new();
    for &value in values {
        let shadowed = sunlit(gpu, chapter, Settings::hard_with(bias(value)), time).facing_shadowed;
        counts.push((value, shadowed));
        if shadowed <= reference.facing_shadowed + reference.facing * SAME_WITHIN_PERCENT / 100 {
            return (value, counts);
        }
    }
    panic!("no value removed the acne: {counts:?}");
}
// ANCHOR_END: bias_search

/// The acne lesson's exercises 1, 2 and 3 on one chapter: the biases,
/// front faces, and the sun going down.
#[test]
fn acne_exercises_1_2_and_3_biases_culling_and_the_evening_sun() {
    let gpu = Gpu::headless(ShadowsChapter::gpu_needs()).unwrap();
    let target = Target { format: OFFSCREEN_FORMAT, width: 320, height: 180, samples: 1 };
    let mut chapter = ShadowsChapter::new(&gpu, target, ()).unwrap();
    let time = ShadowsChapter::SNAPSHOT_TIME;

    // Exercise 1.
    let values = [0.25, 0.5, 0.75, 1.0, 1.5, 2.0, 3.0, 4.0];
    let (offset, offsets) = smallest_bias_without_acne(
        &gpu,
        &mut chapter,
        |v| Bias { constant: 0, slope_scale: 0.0, normal_offset: v },
        &values,
    );
    let (slope, slopes) = smallest_bias_without_acne(
        &gpu,
        &mut chapter,
        |v| Bias { constant: 0, slope_scale: v, normal_offset: 0.0 },
        &values,
    );
    // Then each raised to `RAISED_BY` times that: how much of the real shadow goes.
    let default = sunlit(&gpu, &mut chapter, Settings::hard_with(Bias::DEFAULT), time).facing_shadowed;
    let lost = |bias: Bias, chapter: &mut ShadowsChapter| {
        let left = sunlit(&gpu, chapter, Settings::hard_with(bias), time).facing_shadowed;
        1.0 - left as f64 / default as f64
    };
    let offset_lost = lost(Bias { constant: 0, slope_scale: 0.0, normal_offset: RAISED_BY * offset }, &mut chapter);
    let slope_lost = lost(Bias { constant: 0, slope_scale: RAISED_BY * slope, normal_offset: 0.0 }, &mut chapter);
    println!(
        "default bias: {default} sun-facing pixels in shadow; normal offset alone: acne gone at {offset} texels \
         {offsets:?}; slope scale alone: at {slope} {slopes:?}; at {RAISED_BY} times those, {:.1} % and {:.1} % of the real \
         shadow is lost",
        offset_lost * 100.0,
        slope_lost * 100.0
    );
    assert_eq!((offset, slope), measured::ACNE_GONE_AT);
    let close = |count: usize, expected: usize| count.abs_diff(expected) <= expected / 50;
    let [with_default, first_offset, first_slope, second_slope] = measured::SHADOWED_PIXELS;
    assert!(
        close(default, with_default)
            && close(offsets[0].1, first_offset)
            && close(slopes[0].1, first_slope)
            && close(slopes[1].1, second_slope),
        "measured on an earlier run (a change detector): {:?}, now {default}, {offsets:?}, {slopes:?}",
        measured::SHADOWED_PIXELS
    );
    measured::OFFSET_LOSES.check("the share of the real shadow 64 times the offset loses", offset_lost);
    measured::SLOPE_LOSES.check("the share of the real shadow 64 times the slope scale loses", slope_lost);

    // Exercise 2: front faces culled, no bias at all.
    let front = front_faces_culled_without_bias();
    let culled_front = sunlit(&gpu, &mut chapter, front, time);
    let usual = sunlit(&gpu, &mut chapter, Settings::hard_with(Bias::DEFAULT), time);
    let acne = sunlit(&gpu, &mut chapter, Settings::hard_with(Bias::NONE), time);
    println!("front faces culled, no bias: {culled_front:?}; default: {usual:?}; no bias: {acne:?}");
    // With no lookup at all every surface is lit: the pixels facing away, counted.
    let away = sunlit(&gpu, &mut chapter, Settings::filtered(Filter::Off, 2048), time).away_lit;
    let share = |n: usize, of: usize| n as f64 / of as f64;
    println!(
        "faces turned away from the sun that the map calls lit: {:.1} % with front faces culled, {:.1} % usually",
        100.0 * share(culled_front.away_lit, away),
        100.0 * share(usual.away_lit, away)
    );
    measured::AWAY_LIT_FRONT
        .check("faces turned away called lit, front faces culled", share(culled_front.away_lit, away));
    measured::AWAY_LIT_DEFAULT.check("faces turned away called lit, usually", share(usual.away_lit, away));
    // Facing the sun: no acne, and every real shadow (the tree's among them) still there.
    assert!(culled_front.facing_shadowed.abs_diff(usual.facing_shadowed) <= usual.facing_shadowed / 100);
    let (culled, no_bias) = measured::SHADOWED_FRONT_CULLED_AND_WITHOUT_BIAS;
    assert!(close(culled_front.facing_shadowed, culled) && close(acne.facing_shadowed, no_bias), "a change detector");

    // Exercise 3: the acne view, and the default bias, as the sun goes down.
    let mut by_phase = Vec::new();
    for phase in [0.375, 0.7, 0.73] {
        let (elevation, texel_on_ground) = sun_on_the_ground(phase, time);
        let acne = sunlit(&gpu, &mut chapter, Settings { phase, ..Settings::hard_with(Bias::NONE) }, time);
        let biased = sunlit(&gpu, &mut chapter, Settings { phase, ..Settings::hard_with(Bias::DEFAULT) }, time);
        let (acne, biased) = (share(acne.facing_shadowed, acne.facing), share(biased.facing_shadowed, biased.facing));
        by_phase.push((phase, elevation, acne, biased, texel_on_ground));
    }
    println!(
        "phase, elevation, shadowed share of sun-facing pixels without bias and with, texel on the ground: {by_phase:?}"
    );
    for ((_, _, acne, biased, texel), (expected_acne, expected_biased, expected_texel)) in
        by_phase.iter().zip(measured::EVENING)
    {
        assert!((acne - expected_acne).abs() < 0.01 && (biased - expected_biased).abs() < 0.01, "{by_phase:?}");
        assert!((texel - expected_texel).abs() < 0.001, "{by_phase:?}");
    }
}

// ANCHOR: front_faces
/// Acne, exercise 2: the shadow pass keeps the far sides of solids (it culls the
/// faces towards the sun), with no bias of either kind, hard shadows.
fn front_faces_culled_without_bias() -> Settings {
    let no_bias = Settings::hard_with(Bias::NONE);
    Settings { shadow: ShadowSettings { cull: Cull::Front, ..no_bias.shadow }, ..no_bias }
}
// ANCHOR_END: front_faces

// ANCHOR: evening
/// Acne, exercise 3: the sun's height at `phase`, degrees, and how much ground a
/// texel of the map covers there (the texel across the box, over the sine
/// of the sun's height: a grazing sun stretches it).
fn sun_on_the_ground(phase: f32, time: f32) -> (f32, f32) {
    let sun = scene::sun_at(phase).direction;
    let elevation = sun.y.asin();
    let level = game::level();
    let texel = fit_light(sun, &visible_at(time), scene::level_bounds(&level), 2048).texel;
    (elevation.to_degrees(), texel / elevation.sin())
}
// ANCHOR_END: evening

// ANCHOR: tight_fit
/// The sun's box, exercise 1: the sun's box fitted to the smallest rectangle around the
/// `focus` points in the light's own space, rather than a sphere. Its depth
/// is `fit_light`'s; a square map takes the rectangle's longer side.
fn fit_light_tightly(towards_sun: Vec3, focus: &[Vec3], caster_bounds: (Vec3, Vec3), size: u32) -> LightBox {
    let sphere = fit_light(towards_sun, focus, caster_bounds, size);
    let up = if towards_sun.y.abs() > 0.99 { Vec3::Z } else { Vec3::Y };
    let rotation = Mat4::look_to_rh(Vec3::ZERO, -towards_sun, up);
    let in_light = focus.iter().map(|p| rotation.transform_point3(*p));
    let (low, high) = in_light.fold((Vec3::MAX, Vec3::MIN), |(lo, hi), p| (lo.min(p), hi.max(p)));
    // A texel of margin on each side: snapping moves the box by up to half of one.
    let texel = (high - low).truncate().max_element() / (size - 2) as f32;
    let side = texel * size as f32;
    // Snapped to whole texels, as fit_light's box is.
    let centre = ((low + high) / 2.0).truncate();
    let centre = (centre / texel).round() * texel;
    // The depth range is the sphere fit's: recover it from its matrix.
    let (near, far) = depth_range(&sphere, &rotation);
    let projection = Mat4::orthographic_rh(
        centre.x - side / 2.0,
        centre.x + side / 2.0,
        centre.y - side / 2.0,
        centre.y + side / 2.0,
        near,
        far,
    );
    LightBox { view_proj: projection * rotation, texel, depth: far - near }
}

/// The near and far distances of `light`'s box along the sun's direction.
fn depth_range(light: &LightBox, rotation: &Mat4) -> (f32, f32) {
    let corners = light.corners().map(|c| -rotation.transform_point3(c).z);
    corners.iter().fold((f32::MAX, f32::MIN), |(n, f), d| (n.min(*d), f.max(*d)))
}
// ANCHOR_END: tight_fit

/// The points the chapter fits its box to at scene time `time`.
fn visible_at(time: f32) -> [Vec3; 8] {
    let level = game::level();
    let game = game::demo_at(&level, &level.solids(), time);
    let camera = side_camera(game.player.aabb.centre(), CAMERA_DISTANCE, 16.0 / 9.0);
    visible_part(&camera, scene::level_bounds(&level).1.z)
}

#[test]
fn sun_box_exercise_1_a_rectangle_in_the_lights_space_has_smaller_texels_and_keeps_its_size() {
    let level = game::level();
    let bounds = scene::level_bounds(&level);
    let towards_sun = scene::sun_at(Settings::DEFAULT.phase).direction;
    let focus = visible_at(ShadowsChapter::SNAPSHOT_TIME);
    let sphere = fit_light(towards_sun, &focus, bounds, 2048);
    let tight = fit_light_tightly(towards_sun, &focus, bounds, 2048);
    // Every focus point still falls inside the tight box.
    for p in focus {
        let q = tight.view_proj.project_point3(p);
        assert!(q.x.abs() <= 1.0 && q.y.abs() <= 1.0 && (0.0..=1.0).contains(&q.z), "{p} falls outside: {q}");
    }
    println!("texel: {:.2} cm fitted to a sphere, {:.2} cm to a rectangle", sphere.texel * 100.0, tight.texel * 100.0);
    measured::SPHERE_TEXEL_CM.check("a texel fitted to a sphere, cm", sphere.texel * 100.0);
    measured::TIGHT_TEXEL_CM.check("a texel fitted to a rectangle, cm", tight.texel * 100.0);
    assert!(tight.texel < sphere.texel, "the rectangle is no larger than the sphere's square");
    // While the player runs the demo (the camera only slides) the rectangle
    // keeps its size; with the sun moving, it does not.
    let sizes = |moving_sun: bool| {
        (0..=210)
            .map(|i| {
                let time = i as f32 * 0.1;
                let phase = Settings::DEFAULT.phase + if moving_sun { time / shadows::DAY_SECONDS } else { 0.0 };
                fit_light_tightly(scene::sun_at(phase).direction, &visible_at(time), bounds, 2048).texel
            })
            .fold((f32::MAX, f32::MIN), |(lo, hi), t| (lo.min(t), hi.max(t)))
    };
    let (still, moving) = (sizes(false), sizes(true));
    println!("texel over the demo: {still:?} with the sun still, {moving:?} with it moving");
    assert!(still.1 - still.0 < 1e-4 * still.0, "the texel changes while the player runs: {still:?}");
    measured::MOVING_SUN_TEXELS.0.check("the smallest texel with the sun moving, m", moving.0);
    measured::MOVING_SUN_TEXELS.1.check("the largest texel with the sun moving, m", moving.1);
}

// ANCHOR: cascades
/// The sun's box, exercise 2: the part of the view nearer than `distance` metres along
/// each corner ray, between the level's front face (z = `half_depth`) and
/// its back: the focus of the near cascade.
fn near_part(camera: &Camera, half_depth: f32, distance: f32) -> Vec<Vec3> {
    let far_points = visible_part(camera, half_depth);
    let mut points = Vec::new();
    for corner in 0..4 {
        let (front, back) = (far_points[corner], far_points[corner + 4]);
        let along = (back - camera.position).normalize();
        let near_end = camera.position + along * distance;
        // Where the ray is 10 m out, or the back face if that is nearer.
        let end = if near_end.z > back.z { near_end } else { back };
        points.extend([front, end]);
    }
    points
}

/// Which cascade a world point reads: the near one wherever its box has
/// the point (inside by a texel's margin), else the far one.
fn cascade_for(point: Vec3, near: &LightBox) -> usize {
    let q = near.view_proj.project_point3(point);
    let margin = 2.0 * near.texel / (near.corners()[1] - near.corners()[0]).length();
    if q.x.abs() < 1.0 - margin && q.y.abs() < 1.0 - margin && (0.0..=1.0).contains(&q.z) { 0 } else { 1 }
}

/// The same choice in shadow.wgsl: a second map and box, looked up where
/// the point falls inside the near box.
const SECOND_CASCADE: [(&str, &str); 2] = [
    (
        "@group(3) @binding(3) var<storage, read> shadow: Shadow;",
        "@group(3) @binding(3) var<storage, read> shadow: Shadow;
@group(3) @binding(7) var near_map: texture_depth_2d;
// The near cascade's box, world to its clip space.
@group(3) @binding(8) var<storage, read> near_box: mat4x4<f32>;

fn near_cascade(world: vec3<f32>) -> f32 {
    let clip = near_box * vec4<f32>(world, 1.0);
    let uv = vec2<f32>(clip.x * 0.5 + 0.5, 0.5 - clip.y * 0.5);
    if any(abs(clip.xy) > vec2<f32>(0.99)) || clip.z < 0.0 || clip.z > 1.0 {
        return -1.0;
    }
    return textureSampleCompareLevel(near_map, compare_nearest, uv, clip.z);
}",
    ),
    (
        "    let texel = 1.0 / f32(shadow.options.y);\n    switch mode {",
        "    let texel = 1.0 / f32(shadow.options.y);
    let near = near_cascade(lifted);
    if near >= 0.0 {
        return near;
    }
    switch mode {",
    ),
];
// ANCHOR_END: cascades

#[test]
fn sun_box_exercise_2_a_near_cascade_halves_the_texel_where_the_view_is_close() {
    compiles_with(
        shader!(
            "shadows/scene.wgsl",
            imports: ["lighting/brdf.wgsl", "lighting/sky_light.wgsl", "lighting/lights.wgsl", "textures/surface.wgsl", "shadows/shadow.wgsl", "shadows/point_shadow.wgsl"]
        ),
        "shadows/shadow.wgsl",
        &SECOND_CASCADE,
    );
    let level = game::level();
    let bounds = scene::level_bounds(&level);
    let towards_sun = scene::sun_at(Settings::DEFAULT.phase).direction;
    let game = game::demo_at(&level, &level.solids(), ShadowsChapter::SNAPSHOT_TIME);
    let camera = side_camera(game.player.aabb.centre(), CAMERA_DISTANCE, 16.0 / 9.0);
    let far = fit_light(towards_sun, &visible_part(&camera, bounds.1.z), bounds, 2048);
    let near_points = near_part(&camera, bounds.1.z, 10.0);
    let near = fit_light(towards_sun, &near_points, bounds, 2048);
    println!("texels: {:.2} cm in the near cascade, {:.2} cm in the far one", near.texel * 100.0, far.texel * 100.0);
    measured::NEAR_TEXEL_CM.check("a texel of the near cascade, cm", near.texel * 100.0);
    assert!(near.texel < far.texel, "the near cascade's texels are the finer");
    // The near points' middle reads the near map; the far end of the level the far one.
    let middle = near_points.iter().sum::<Vec3>() / near_points.len() as f32;
    let far_corners = visible_part(&camera, bounds.1.z);
    let choices: Vec<usize> = far_corners.iter().map(|p| cascade_for(*p, &near)).collect();
    println!("the far box's corners read cascades {choices:?}");
    assert_eq!(cascade_for(middle, &near), 0);
    assert_eq!(choices, measured::FAR_CORNERS_READ, "a change detector");
}

// ANCHOR: double_jump
/// Collisions, exercise 1: the game with one more jump in the air, taken by pressing
/// jump again (not by holding it) before landing.
struct DoubleJump {
    game: Game,
    air_jump_left: bool,
    jump_held: bool,
}

impl DoubleJump {
    fn new(level: &game::Level) -> Self {
        Self { game: Game::new(level), air_jump_left: true, jump_held: false }
    }

    fn step(&mut self, solids: &[shadows::physics::Aabb], controls: Controls) {
        let pressed = controls.jump && !self.jump_held;
        self.jump_held = controls.jump;
        if self.game.on_floor {
            self.air_jump_left = true;
        } else if pressed && self.air_jump_left {
            self.game.player.velocity.y = JUMP_SPEED;
            self.air_jump_left = false;
        }
        self.game.step(solids, controls);
    }
}

/// Collisions, exercise 1: the second press comes at the top of the first
/// jump, v / g after take-off, to the hundredth of a second.
const SECOND_PRESS_AT: f32 = 0.42;

/// The first test to write: pressing jump three times in one flight lifts
/// the player twice as high as one jump (2 × v² / 2g), and no higher.
#[test]
fn collisions_exercise_1_a_second_jump_in_the_air_lifts_the_player_once() {
    let level = game::level();
    let solids = level.solids();
    let mut player = DoubleJump::new(&level);
    let ground = player.game.player.aabb.min.y;
    // Presses of 0.1 s at 0, at the top of the first jump and twice that.
    assert!((SECOND_PRESS_AT - JUMP_SPEED / game::GRAVITY).abs() < 0.005, "the first jump's top moved");
    let pressed = |t: f32| [0.0f32, SECOND_PRESS_AT, 2.0 * SECOND_PRESS_AT].iter().any(|&at| t >= at && t < at + 0.1);
    let mut highest = 0.0f32;
    for _ in 0..(2.0 / STEP) as u32 {
        let time = player.game.time();
        player.step(&solids, Controls { jump: pressed(time), ..Controls::default() });
        highest = highest.max(player.game.player.aabb.min.y - ground);
    }
    let one_jump = JUMP_SPEED * JUMP_SPEED / (2.0 * game::GRAVITY);
    println!("one jump rises {one_jump:.2} m; with the double jump the player reached {highest:.2} m");
    // Derived: two jumps' rise, less what the fixed steps lose at each top.
    assert!((highest - 2.0 * one_jump).abs() < 0.1, "{highest} against twice {one_jump}");
    measured::DOUBLE_JUMP_HEIGHT.check("the double jump's height, m", highest);
    assert!(player.game.on_floor, "and landed");
}
// ANCHOR_END: double_jump

// ANCHOR: cube_culling
/// Which casters the lantern's passes leave out.
#[derive(Clone, Copy, PartialEq)]
enum CubeCulling {
    /// None: what `PointShadow::render` draws.
    Nothing,
    /// Every instance whose box lies beyond the lantern's range.
    BeyondRange,
    /// Those, and in each face's pass every instance whose box lies
    /// wholly outside that face's frustum.
    BeyondRangeOrFace,
}

/// The lantern, exercise 1: the triangles the lantern's six passes draw in the
/// `lantern` view (the demo at the snapshot time), culling instance by
/// instance with the boxes of their models' vertices.
fn cube_triangles(culling: CubeCulling) -> u64 {
    let level = game::level();
    let light = scene::lantern_light(&level);
    let game = game::demo_at(&level, &level.solids(), ShadowsChapter::SNAPSHOT_TIME);
    let read: textures::obj::ReadFile = &scene::read;
    let load = |path: &str| textures::obj::load(std::path::Path::new(path), read).unwrap().model;
    // Every caster's model with its instances; the level's blocks are one
    // model with one instance, always drawn.
    let mut casters = vec![(scene::level_model(&level), vec![ModelInstance::new(Mat4::IDENTITY, 1.0)])];
    for kind in PropKind::ALL {
        casters.push((load(scene::prop_model(kind)), scene::prop_instances(&level, kind)));
    }
    casters.push((load(scene::PLAYER_MODEL), vec![scene::player_instance(&game)]));
    let mut triangles = 0;
    for face in CubeFace::ALL {
        let axes = face.axes();
        // The frustum's four sides, as normals pointing into it: a point d
        // from the light is inside where d · major ≥ |d · s| and |d · t|.
        let sides = [axes.major - axes.s, axes.major + axes.s, axes.major - axes.t, axes.major + axes.t];
        for (model, instances) in &casters {
            for instance in instances {
                let at = Mat4::from_cols_array_2d(&instance.model);
                let (low, high) = model.vertices.iter().fold((Vec3::MAX, Vec3::MIN), |(lo, hi), v| {
                    let p = at.transform_point3(Vec3::from(v.position)) - light.position;
                    (lo.min(p), hi.max(p))
                });
                let beyond = Vec3::ZERO.clamp(low, high).length() >= light.range;
                let corners = (0..8).map(|i| {
                    Vec3::new(
                        if i & 1 == 0 { low.x } else { high.x },
                        if i & 2 == 0 { low.y } else { high.y },
                        if i & 4 == 0 { low.z } else { high.z },
                    )
                });
                let outside = sides.iter().any(|n| corners.clone().all(|c| n.dot(c) < 0.0));
                let culled = match culling {
                    CubeCulling::Nothing => false,
                    CubeCulling::BeyondRange => beyond,
                    CubeCulling::BeyondRangeOrFace => beyond || outside,
                };
                if !culled {
                    triangles += model.indices.len() as u64 / 3;
                }
            }
        }
    }
    triangles
}
// ANCHOR_END: cube_culling

#[test]
fn lantern_exercise_1_culling_the_lanterns_casters_by_range_and_face() {
    let all = cube_triangles(CubeCulling::Nothing);
    let in_range = cube_triangles(CubeCulling::BeyondRange);
    let in_face = cube_triangles(CubeCulling::BeyondRangeOrFace);
    println!(
        "the lantern's six passes: {all} triangles, {in_range} within its range, {in_face} in a face's frustum too"
    );
    // The same count as the passes' own counter (`CubeCost`).
    assert_eq!(all, measured::CUBE_TRIANGLES, "a change detector");
    assert_eq!((in_range, in_face), measured::CULLED_TRIANGLES, "a change detector");
    assert!(in_face <= in_range && in_range <= all, "culling more never draws more");
}

// ANCHOR: linear_depth
/// Two passes, exercise 1: two points `gap` metres apart along the sun's
/// rays, projected into the sun's `light` box: how far apart their stored
/// depths are.
fn depth_apart(light: &LightBox, towards_sun: Vec3, point: Vec3, gap: f32) -> f32 {
    let farther = point - towards_sun * gap;
    light.view_proj.project_point3(farther).z - light.view_proj.project_point3(point).z
}
// ANCHOR_END: linear_depth

#[test]
fn two_passes_exercise_1_orthographic_depth_is_linear_in_distance() {
    // A sun looking straight down −z, and casters from z = −`reach` to
    // `reach`: the box runs a metre beyond them at each end.
    let towards_sun = Vec3::Z;
    let box_for = |reach: f32| {
        let bounds = (Vec3::new(-1.0, -1.0, -reach), Vec3::new(1.0, 1.0, reach));
        let focus = [bounds.0, bounds.1];
        fit_light(towards_sun, &focus, bounds, 2048)
    };
    for (reach, by_hand) in [(49.0, 0.0345), (99.0, 0.01725)] {
        let light = box_for(reach);
        assert!((light.depth - 2.0 * (reach + 1.0)).abs() < 1e-3, "a box {} m deep", light.depth);
        // Near the sun's face, in the middle, near the far face.
        for z in [reach - 3.0, 0.0, -reach + 4.0] {
            let apart = depth_apart(&light, towards_sun, Vec3::new(0.5, -0.5, z), 3.45);
            assert!((apart - by_hand).abs() < 1e-5, "{} m deep, at z = {z}: {apart} against {by_hand}", light.depth);
        }
    }
    // The default picture's box, whatever its depth: a gap over the depth.
    let level = game::level();
    let towards_sun = scene::sun_at(Settings::DEFAULT.phase).direction;
    let focus = visible_at(ShadowsChapter::SNAPSHOT_TIME);
    let light = fit_light(towards_sun, &focus, scene::level_bounds(&level), 2048);
    for point in focus {
        let apart = depth_apart(&light, towards_sun, point, 3.45);
        assert!((apart - 3.45 / light.depth).abs() < 1e-5, "at {point}: {apart}");
    }
}

// ANCHOR: pcf_5x5
/// Soft edges, exercise 1: the 3 × 3 filter widened to 5 × 5, as edits of
/// shadow.wgsl.
const PCF_5X5: [(&str, &str); 3] = [
    ("    for (var y = -1; y <= 1; y++) {", "    for (var y = -2; y <= 2; y++) {"),
    ("        for (var x = -1; x <= 1; x++) {", "        for (var x = -2; x <= 2; x++) {"),
    ("    return sum / 9.0;", "    return sum / 25.0;"),
];
// ANCHOR_END: pcf_5x5

/// Pixels of a `Show::Sunlit` picture that get some of the sun but not
/// all (the soft band), and that get all of it.
fn partly_and_fully_lit(image: &common::image::RgbaImage) -> (usize, usize) {
    let partly = image.pixels().filter(|p| (16..240).contains(&p[0])).count();
    let fully = image.pixels().filter(|p| p[0] >= 250).count();
    (partly, fully)
}

#[test]
fn soft_edges_exercise_1_a_5x5_filter_widens_the_soft_band() {
    // By hand: the filter views' box is 45 m wide, so a texel of their
    // 512² map is 45 / 512 m; the chapter's box says the same.
    let level = game::level();
    let towards_sun = scene::sun_at(Settings::DEFAULT.phase).direction;
    let focus = visible_at(ShadowsChapter::SNAPSHOT_TIME);
    let light = fit_light(towards_sun, &focus, scene::level_bounds(&level), 512);
    assert!((light.texel - 45.0 / 512.0).abs() < 1e-6, "a texel of {} m", light.texel);

    // The edit made to a copy of the shaders, which the chapter reloads.
    let root = shader::scratch_copy("shadows-pcf-5x5").unwrap();
    let file = root.join("shadows/shadow.wgsl");
    let original = std::fs::read_to_string(&file).unwrap();
    let gpu = Gpu::headless(ShadowsChapter::gpu_needs()).unwrap();
    gpu.read_shaders_from(Some(root.clone()));
    let target = Target { format: OFFSCREEN_FORMAT, width: 320, height: 180, samples: 1 };
    let mut chapter = ShadowsChapter::new(&gpu, target, ()).unwrap();
    let index = common::chapter::view_index::<ShadowsChapter>("pcf-3x3").unwrap();
    let picture = |chapter: &mut ShadowsChapter| {
        chapter.settings = Settings { show: Show::Sunlit, ..shadows::VIEW_TABLE[index].settings };
        capture(&gpu, chapter, target, (ShadowsChapter::SNAPSHOT_TIME, index), Default::default()).unwrap()
    };
    let three = partly_and_fully_lit(&picture(&mut chapter));
    let mut edited = original.clone();
    for (before, after) in PCF_5X5 {
        assert_eq!(edited.matches(before).count(), 1, "{before}");
        edited = edited.replace(before, after);
    }
    std::fs::write(&file, edited).unwrap();
    let rebuilt = gpu.reload_shaders(&["shadows/shadow.wgsl"]).unwrap();
    assert!(rebuilt >= 1, "nothing was built from the edited shadow.wgsl");
    let five = partly_and_fully_lit(&picture(&mut chapter));
    let _ = std::fs::remove_dir_all(&root);
    println!("partly and fully lit pixels: {three:?} with 3 × 3, {five:?} with 5 × 5");
    // A wider band between sun and shadow, taken from both sides of it.
    assert!(five.0 > three.0, "the soft band did not widen: {three:?} then {five:?}");
    assert!(five.1 < three.1, "the band took no fully lit pixels: {three:?} then {five:?}");
}

// ANCHOR: fourth_layer
/// Parallax, exercise 1: a fourth layer, 201 m from the camera, its
/// picture twice the far layer's height (and its bottom twice as low) so
/// that it fills the screen as that one does.
const FOURTH_LAYER: Layer = Layer { picture: "layers/far.png", z: -190.0, height: 120.0, bottom: -50.0, haze: 0.7 };
// ANCHOR_END: fourth_layer

/// How far a point of the plane z = `z` on the side camera's central ray
/// moves across the screen when the camera slides a metre, over how far
/// a point of the level (z = 0) does: the share of the level's speed.
fn slide_share(z: f32) -> f32 {
    let aspect = 16.0 / 9.0;
    let before = side_camera(Vec2::ZERO, CAMERA_DISTANCE, aspect);
    let after = side_camera(Vec2::X, CAMERA_DISTANCE, aspect);
    // The camera looks at the player, at the origin: the central ray.
    let along = -before.position.normalize();
    let on_ray = |z: f32| before.position + along * ((z - before.position.z) / along.z);
    let moved = |p: Vec3| after.view_projection().project_point3(p).x - before.view_projection().project_point3(p).x;
    moved(on_ray(z)) / moved(on_ray(0.0))
}

#[test]
fn parallax_exercise_1_a_plane_201_m_away_slides_at_11_over_201() {
    // By hand: the camera stands 11 m from the level, the layer 201 m.
    let by_hand = CAMERA_DISTANCE / (CAMERA_DISTANCE - FOURTH_LAYER.z);
    assert!((by_hand - 11.0 / 201.0).abs() < 1e-6 && (by_hand - 0.055).abs() < 5e-4);
    let share = slide_share(FOURTH_LAYER.z);
    println!("the fourth layer slides at {share:.4} of the level's speed (by hand {by_hand:.4})");
    assert!((share - by_hand).abs() < 1e-4, "{share} against {by_hand}");
    // And the chapter's three layers at 0.44, 0.24 and 0.11.
    for (layer, expected) in LAYERS.iter().zip([0.44, 0.24, 0.11]) {
        let share = slide_share(layer.z);
        assert!((share - expected).abs() < 0.005, "{}: {share}", layer.picture);
    }
}

/// Measured: what these tests got by running the chapter (its renders,
/// `fit_light`, the game's physics, the lantern's casters) and copied with
/// chapter 10's solutions, which say they are measured
/// (`common::book_figures::Measured`: change detectors, not derivations).
mod measured {
    use common::book_figures::Measured;

    /// Acne, exercise 1: the smallest normal offset and slope scale that remove
    /// the acne on their own; the sun-facing pixels in shadow with the
    /// default bias, the first offset and the first two slope scales; the
    /// share of the real shadows lost at 64 times those (below zero: gained).
    pub const ACNE_GONE_AT: (f32, f32) = (0.5, 0.75);
    pub const SHADOWED_PIXELS: [usize; 4] = [3057, 9003, 10_821, 4029];
    pub const OFFSET_LOSES: Measured = Measured::new(-0.085, 0.01);
    pub const SLOPE_LOSES: Measured = Measured::new(0.085, 0.01);
    /// Acne, exercise 2: the share of the faces turned away from the sun that read
    /// as lit with front faces culled and no bias, and usually; sun-facing
    /// pixels in shadow with front faces culled, and with no bias at all.
    pub const AWAY_LIT_FRONT: Measured = Measured::new(0.593, 0.02);
    pub const AWAY_LIT_DEFAULT: Measured = Measured::new(0.404, 0.02);
    pub const SHADOWED_FRONT_CULLED_AND_WITHOUT_BIAS: (usize, usize) = (3051, 18_248);
    /// Acne, exercise 3: at phases 0.375, 0.7 and 0.73, the share of sun-facing
    /// pixels in shadow without bias and with the default one, and the
    /// ground a shadow-map texel covers, metres.
    pub const EVENING: [(f64, f64, f32); 3] = [(0.548, 0.092, 0.0379), (0.582, 0.166, 0.0868), (0.611, 0.221, 0.2140)];
    /// The sun's box, exercise 1: a texel of the 2048² map fitted to a sphere and to the
    /// rectangle, cm; the rectangle's smallest and largest texel, m, over
    /// the demo with the sun moving.
    pub const SPHERE_TEXEL_CM: Measured = Measured::new(2.20, 0.01);
    pub const TIGHT_TEXEL_CM: Measured = Measured::new(1.59, 0.01);
    pub const MOVING_SUN_TEXELS: (Measured, Measured) = (Measured::new(0.0143, 0.0001), Measured::new(0.0190, 0.0001));
    /// The sun's box, exercise 2: a texel of the near cascade's map, cm, and which cascade
    /// each corner of the visible part reads.
    pub const NEAR_TEXEL_CM: Measured = Measured::new(1.03, 0.01);
    pub const FAR_CORNERS_READ: [usize; 8] = [0, 0, 0, 0, 1, 0, 1, 1];
    /// Collisions, exercise 1: the highest the double jump takes the player, m (one jump: 2.08 m).
    pub const DOUBLE_JUMP_HEIGHT: Measured = Measured::new(4.08, 0.02);
    /// The lantern, exercise 1: the lantern's casters' triangles over its six passes; left
    /// within its range, and within a face's frustum too.
    pub const CUBE_TRIANGLES: u64 = 24_468;
    pub const CULLED_TRIANGLES: (u64, u64) = (3_960, 2_008);
}
