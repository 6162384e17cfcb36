//! Worked solutions to the exercises of chapter 02's lessons, compiled and
//! checked with the chapter's other tests: the lessons include them by
//! anchor, and each test asserts the figure its solution states. A test's
//! name starts with its lesson's page (`transforms`, `fly_camera`,
//! `primitives`, `uniforms`, `depth`, `multisampling`) and the exercise's
//! number there.

use std::f32::consts::TAU;

use camera::{CameraChapter, Placement, Shape, scene, start_camera};
use common::glam::{Mat4, Quat, Vec3, Vec4};
use common::headless::{OFFSCREEN_FORMAT, Offscreen, capture};
use common::winit::keyboard::KeyCode;
use common::{Camera, Chapter, FlyController, Gpu, GpuNeeds, Input, MeshData, SceneTargets, Target, primitives};

// ANCHOR: edge_stretch
/// Model, view and projection, exercise 1: how many times wider a small sphere looks with its centre at
/// the left or right edge of the picture than at the centre, measured with
/// the camera's own view-projection matrix.
fn edge_stretch(fov_y_degrees: f32, aspect: f32) -> f32 {
    let camera = Camera { fov_y: fov_y_degrees.to_radians(), ..Camera::looking_at(Vec3::ZERO, Vec3::NEG_Z, aspect) };
    // The angle between the camera's axis and the picture's side edge.
    let edge = (aspect * (camera.fov_y / 2.0).tan()).atan();
    // A sphere of radius r at distance d fills the angles ± asin(r / d)
    // around its centre; where do those two rays land on the picture?
    let (r, d) = (0.01, 10.0);
    let screen_x = |angle: f32| {
        let clip = camera.view_projection() * Vec4::new(d * angle.sin(), 0.0, -d * angle.cos(), 1.0);
        clip.x / clip.w
    };
    let width = |centre: f32| screen_x(centre + (r / d).asin()) - screen_x(centre - (r / d).asin());
    width(edge) / width(0.0)
}
// ANCHOR_END: edge_stretch

// ANCHOR: telephoto
/// Model, view and projection, exercise 1, second half: the height on the picture (in clip units) of
/// something 1 m tall straight ahead at `distance`.
fn apparent_height(fov_y_degrees: f32, distance: f32) -> f32 {
    let camera = Camera { fov_y: fov_y_degrees.to_radians(), ..Camera::looking_at(Vec3::ZERO, Vec3::NEG_Z, 1.0) };
    let screen_y = |y: f32| {
        let clip = camera.view_projection() * Vec4::new(0.0, y, -distance, 1.0);
        clip.y / clip.w
    };
    screen_y(0.5) - screen_y(-0.5)
}
// ANCHOR_END: telephoto

/// Transforms, exercise 1: how much wider a small sphere at the picture's
/// side edge looks than at its centre, at 110° and at 25° (vertical) and
/// 16:9, worked by hand as 1 + tan²θ (tan θ = tan(fov / 2) · 16 / 9).
const WIDE_LENS_EDGE_STRETCH: f32 = 7.446;
const LONG_LENS_EDGE_STRETCH: f32 = 1.1553;

#[test]
fn transforms_exercise_1_wide_angles_stretch_the_edges_and_long_lenses_flatten_depth() {
    // At the edge, the angle θ off the axis stretches a small object by
    // 1 / cos²θ along the picture's radius. At 110° (vertical) and 16:9 the
    // side edge is θ = 68.5° off the axis: 7.4 times as wide. At 25°,
    // θ = 21.5°: 1.16 times.
    let (wide, narrow) = (edge_stretch(110.0, 16.0 / 9.0), edge_stretch(25.0, 16.0 / 9.0));
    eprintln!("a sphere at the side edge looks {wide:.2}× as wide at 110°, {narrow:.3}× at 25°");
    assert!((wide - WIDE_LENS_EDGE_STRETCH).abs() < 0.005, "{wide}");
    assert!((narrow - LONG_LENS_EDGE_STRETCH).abs() < 0.0005, "{narrow}");

    // The rows stand 6 m apart (z = 2 and z = −4). At 110°, 2 m from the
    // front row; at 25°, step back until the front row is as tall on the
    // picture: 2 · tan 55° / tan 12.5° = 12.9 m. The back row, 6 m beyond,
    // is then a quarter of the front row's size at 110°, two thirds at 25°.
    let far_back = 2.0 * 55f32.to_radians().tan() / 12.5f32.to_radians().tan();
    assert!((apparent_height(110.0, 2.0) - apparent_height(25.0, far_back)).abs() < 1e-4);
    let back_over_front = |fov, distance| apparent_height(fov, distance + 6.0) / apparent_height(fov, distance);
    let (close, stepped_back) = (back_over_front(110.0, 2.0), back_over_front(25.0, far_back));
    eprintln!("stepped back to {far_back:.1} m: back row / front row {close:.3} at 110°, {stepped_back:.3} at 25°");
    assert!((close - 0.25).abs() < 1e-3 && (stepped_back - 0.682).abs() < 1e-3);
}

// ANCHOR: rts
/// Primitives, exercise 1: `Placement::model` with the order swapped to R · T · S. The
/// rotation now comes after the move, so it turns the object's position
/// about the origin too.
fn model_rts(placement: &Placement, time: f32) -> Mat4 {
    let rotation = placement.rotation * Quat::from_rotation_y(placement.spin * time);
    Mat4::from_quat(rotation) * Mat4::from_translation(placement.position) * Mat4::from_scale(placement.scale)
}
// ANCHOR_END: rts

#[test]
fn primitives_exercise_1_rts_swings_the_spinning_row_around_the_origin() {
    let spinning: Vec<Placement> = scene().into_iter().filter(|p| p.spin > 0.0).collect();
    assert_eq!(spinning.len(), 6);
    for placement in &spinning {
        let centre = |model: Mat4| model.transform_point3(Vec3::ZERO);
        // T · R · S: the centre stays where it was put, at every time.
        assert!(centre(placement.model(2.0)).distance(placement.position) < 1e-5);
        // R · T · S: the centre keeps its distance from the origin but moves.
        let swung = centre(model_rts(placement, 2.0));
        assert!((swung.length() - placement.position.length()).abs() < 1e-4);
        assert!(swung.distance(placement.position) > 1.0, "{:?} stays at {swung}", placement.shape);
    }
    // The cube at the back left, at (−5.5, 1.2, −4), spins about y at
    // 0.4 rad/s: with R · T · S it circles the y axis at 6.8 m, and by the
    // snapshot time, t = 2 s, it has swung 2 · 6.8 · sin 0.4 = 5.3 m.
    let cube = spinning[0];
    assert_eq!(cube.shape, Shape::Cube);
    let moved = model_rts(&cube, 2.0).transform_point3(Vec3::ZERO).distance(cube.position);
    assert!((moved - 5.30).abs() < 0.01, "{moved}");
    // The other three are tipped on their side, a quarter turn about x:
    // R · T · S turns their circles upright too, and at t = 2 s all three
    // centres are under the ground.
    let tipped: Vec<f32> = spinning.iter().skip(1).step_by(2).map(|p| model_rts(p, 2.0).w_axis.y).collect();
    assert!(tipped.iter().all(|&y| y < -1.0), "{tipped:?}");
}

/// The angle in degrees between two directions.
fn degrees_between(a: Vec3, b: Vec3) -> f32 {
    a.normalize().dot(b.normalize()).clamp(-1.0, 1.0).acos().to_degrees()
}

// ANCHOR: wrong_normals
/// Uniforms and the shaders, exercise 1: the largest angle, over a mesh's vertices, between the
/// normal the model matrix gives and the true one, which the normal matrix
/// (the model's inverse transpose) gives.
fn worst_normal_error(mesh: &MeshData, model: Mat4) -> f32 {
    let normal_matrix = model.inverse().transpose();
    mesh.vertices
        .iter()
        .map(|v| {
            let n = Vec3::from(v.normal);
            degrees_between(model.transform_vector3(n), normal_matrix.transform_vector3(n))
        })
        .fold(0.0, f32::max)
}
// ANCHOR_END: wrong_normals

/// The `vs_main` line the exercise edits, and the edit.
const NORMAL_LINE: &str = "out.normal = (object.normal_matrix * vec4<f32>(in.normal, 0.0)).xyz;";
const WRONG_NORMAL_LINE: &str = "out.normal = (object.model * vec4<f32>(in.normal, 0.0)).xyz;";

#[test]
fn uniforms_exercise_1_the_model_matrix_tilts_the_stretched_rows_normals_by_up_to_43_degrees() {
    // The middle row is stretched 1.6 / 0.7 = 2.29 times more along y than
    // across. The model matrix tilts its normals towards y by that factor,
    // the true normal away from y by it: at 45° the two are
    // atan 2.29 − atan (1 / 2.29) = 66.4° − 23.6° = 42.7° apart.
    let middle_row: Vec<Placement> = scene().into_iter().filter(|p| p.scale.y > 1.5).collect();
    assert_eq!(middle_row.len(), 6);
    let errors: Vec<f32> = middle_row.iter().map(|p| worst_normal_error(&p.shape.mesh(), p.model(0.0))).collect();
    eprintln!("worst normal error per shape of the middle row, degrees: {errors:?}");
    let sphere = errors[Shape::ALL.iter().position(|&s| s == Shape::Sphere).unwrap()];
    assert!((sphere - 42.74).abs() < 0.05, "{sphere}");
    assert!(errors.iter().all(|&e| e <= 42.75));
    // Uniformly scaled rows keep their normals' directions: no error there.
    for p in scene().iter().filter(|p| p.scale.y < 1.5) {
        assert!(worst_normal_error(&p.shape.mesh(), p.model(2.0)) < 0.1, "{:?}", p.shape);
    }

    // The same, seen in the `normals` view: render it with the shader as
    // it is and with the edit, and read the normals back from the colours.
    let gpu = Gpu::headless(GpuNeeds::default()).expect("an adapter (lavapipe will do)");
    let target = Target { format: OFFSCREEN_FORMAT, width: 320, height: 180, samples: 1 };
    let normals = camera::VIEW_TABLE.iter().position(|row| row.view.name == "normals").unwrap();
    let render = |gpu: &Gpu| {
        let mut chapter: CameraChapter = common::chapter::create(gpu, target, &Default::default()).unwrap();
        chapter.select_view(normals);
        capture(gpu, &mut chapter, target, (CameraChapter::SNAPSHOT_TIME, normals), Default::default()).unwrap()
    };
    let right = render(&gpu);
    let root = common::shader::scratch_copy("camera-uniforms-exercise-1").unwrap();
    let scene_wgsl = root.join("camera/scene.wgsl");
    let original = std::fs::read_to_string(&scene_wgsl).unwrap();
    assert!(original.contains(NORMAL_LINE), "scene.wgsl changed: update NORMAL_LINE");
    std::fs::write(&scene_wgsl, original.replace(NORMAL_LINE, WRONG_NORMAL_LINE)).unwrap();
    gpu.read_shaders_from(Some(root.clone()));
    let wrong = render(&gpu);
    std::fs::remove_dir_all(root).unwrap();
    // The view writes pow(n · 0.5 + 0.5, 2.2) into an sRGB target.
    let decode = |byte: u8| {
        let c = f32::from(byte) / 255.0;
        let linear = if c <= 0.04045 { c / 12.92 } else { ((c + 0.055) / 1.055).powf(2.4) };
        linear.powf(1.0 / 2.2) * 2.0 - 1.0
    };
    let normal = |p: &common::image::Rgba<u8>| Vec3::new(decode(p[0]), decode(p[1]), decode(p[2]));
    let angles: Vec<f32> =
        right.pixels().zip(wrong.pixels()).map(|(a, b)| degrees_between(normal(a), normal(b))).collect();
    let worst = angles.iter().copied().fold(0.0, f32::max);
    let changed = angles.iter().filter(|&&a| a > 2.0).count() as f32 / angles.len() as f32;
    eprintln!("normals view: worst change {worst:.1}°, {:.1} % of the pixels change by more than 2°", changed * 100.0);
    assert!((40.5..44.0).contains(&worst), "{worst}");
    assert!((0.006..0.013).contains(&changed), "{changed}");
}

// ANCHOR: paraboloid
/// Primitives, exercise 2: the paraboloid y = x² + z² over the disc r ≤ 0.5, as a
/// `primitives::surface`. u goes around, v out from the centre (so that
/// ∂P/∂v × ∂P/∂u points up, into the bowl). The surface is where
/// F = x² + z² − y is 0, and F's gradient (2x, −1, 2z) is perpendicular to
/// it: turned to point up, (−2x, 1, −2z), normalised, is the normal.
pub fn paraboloid(segments: u32, rings: u32) -> MeshData {
    primitives::surface(segments, rings, |u, v| {
        let radius = 0.5 * v;
        let (sin, cos) = (TAU * u).sin_cos();
        let (x, z) = (radius * sin, radius * cos);
        let normal = Vec3::new(-2.0 * x, 1.0, -2.0 * z).normalize();
        (Vec3::new(x, x * x + z * z, z), normal)
    })
}
// ANCHOR_END: paraboloid

#[test]
fn primitives_exercise_2_the_paraboloid_winds_towards_its_normals_which_lean_45_degrees_at_the_rim() {
    let mesh = paraboloid(32, 8);
    // The centre's row of 33 copies of one point loses its zero-area triangles.
    assert_eq!(mesh.indices.len(), 3 * (32 + 2 * 32 * 7));
    for triangle in mesh.indices.chunks_exact(3) {
        let [a, b, c] = [0, 1, 2].map(|i| mesh.vertices[triangle[i] as usize]);
        let [pa, pb, pc] = [a, b, c].map(|v| Vec3::from(v.position));
        let face = (pb - pa).cross(pc - pa);
        // Counter-clockwise seen from the side the normals point to…
        for v in [a, b, c] {
            assert!(face.dot(v.normal.into()) > 0.0, "triangle {triangle:?} winds away from its normals");
        }
    }
    for v in &mesh.vertices {
        let (p, n) = (Vec3::from(v.position), Vec3::from(v.normal));
        // …and each normal is perpendicular to the surface: along the two
        // directions in it, around (−z, 0, x) and outwards (x, 2r², z).
        let around = Vec3::new(-p.z, 0.0, p.x);
        let outwards = Vec3::new(p.x, 2.0 * (p.x * p.x + p.z * p.z), p.z);
        assert!(n.dot(around).abs() < 1e-5 && n.dot(outwards).abs() < 1e-5, "{p} {n}");
    }
    // At the rim the slope is 2r = 1: the normal leans 45° from vertical.
    let rim = mesh.vertices.last().unwrap();
    assert!((Vec3::from(rim.position).length() - 0.5f32.hypot(0.25)).abs() < 1e-5);
    assert!((degrees_between(rim.normal.into(), Vec3::Y) - 45.0).abs() < 1e-3);
}

// ANCHOR: hundred_cubes
/// Uniforms and the shaders, exercise 2: a hundred cubes in a 10 × 10 grid, 1.5 m apart, each
/// spinning at its own rate. Returned in place of `scene()` in `new`, they
/// are drawn like the primitives: one uniform slot and one draw call each.
pub fn hundred_cubes() -> Vec<Placement> {
    (0..100)
        .map(|i| Placement {
            shape: Shape::Cube,
            position: Vec3::new((i % 10) as f32 * 1.5 - 6.75, 0.5, 2.0 - (i / 10) as f32 * 1.5),
            rotation: Quat::IDENTITY,
            scale: Vec3::splat(0.8),
            spin: 0.2 + 0.03 * i as f32,
            color: [0.3 + 0.006 * i as f32, 0.45, 0.9 - 0.006 * i as f32],
        })
        .collect()
}
// ANCHOR_END: hundred_cubes

#[test]
fn uniforms_exercise_2_a_hundred_cubes_are_a_hundred_draws_and_a_hundred_uniform_slots() {
    let cubes = hundred_cubes();
    assert_eq!(cubes.len(), 100);
    assert!(cubes.iter().all(|c| c.shape == Shape::Cube && c.spin > 0.0));
    // Every frame: one draw call per object plus the ground, and one
    // 256-byte slot each in the objects' buffer (`object_stride` on a
    // device whose `min_uniform_buffer_offset_alignment` is WebGPU's
    // default, 256), of which `ObjectUniform` uses 144.
    assert_eq!(size_of::<camera::uniforms::ObjectUniform>(), 144, "the size the page gives");
    let per_frame = |objects: usize| (objects + 1, (objects + 1) * 256);
    assert_eq!(per_frame(cubes.len()), (101, 25_856));
    // A hundred thousand: 100,001 draw calls and 25.6 MB of uniforms
    // written every frame. (Chapter 05 draws that many rocks in one call,
    // from 32 bytes of instance data each: 3.2 MB.)
    assert_eq!(per_frame(100_000), (100_001, 25_600_256));
}

// ANCHOR: reversed_projection
/// The depth buffer, exercise 1: reversed depth. The camera's projection with near and far
/// swapped puts the near plane at depth 1 and the far plane at 0; the
/// pipeline then keeps the fragment whose depth is `Greater`, and the pass
/// clears the depth buffer to 0.0 instead of 1.0.
fn reversed_projection(camera: &Camera) -> Mat4 {
    Mat4::perspective_rh(camera.fov_y, camera.aspect, camera.far, camera.near)
}
// ANCHOR_END: reversed_projection

// ANCHOR: depth_step
/// The smallest change in distance, straight ahead at `distance`, that a
/// 32-bit float depth buffer can store as a different depth under
/// `projection`: the depth the GPU stores there (z / w, an `f32`), the next
/// `f32` towards the far plane, and the distance that depth stands for.
fn depth_step(projection: Mat4, distance: f32, reversed: bool) -> f64 {
    let clip = projection * Vec4::new(0.0, 0.0, -distance, 1.0);
    let stored = clip.z / clip.w;
    let next = if reversed { stored.next_down() } else { stored.next_up() };
    // Depth is a + b / d for a perspective projection (w = d): solve for d.
    let (a, b) = (f64::from(projection.z_axis.z), f64::from(projection.w_axis.z));
    let distance_of = |depth: f32| b / (f64::from(depth) + a);
    distance_of(next) - distance_of(stored)
}
// ANCHOR_END: depth_step

/// Depth, exercise 1: how many times finer reversed depth stores distances
/// at 100 m than the standard mapping, near 0.01 m and far 2,000 m (the
/// page's "about", to within 15 %).
const REVERSED_DEPTH_FINER_AT_100_M: f64 = 8000.0;

#[test]
fn depth_exercise_1_reversed_depth_stores_far_distances_thousands_of_times_finer() {
    // The overlay's near and far planes at the ends of their sliders, where
    // the depth lesson suggests looking for z-fighting.
    let camera = Camera { near: 0.01, far: 2000.0, ..Camera::looking_at(Vec3::ZERO, Vec3::NEG_Z, 16.0 / 9.0) };
    let (standard, reversed) = (camera.projection(), reversed_projection(&camera));
    // The reversed projection maps near to 1 and far to 0.
    let depth = |m: Mat4, d: f32| {
        let clip = m * Vec4::new(0.0, 0.0, -d, 1.0);
        clip.z / clip.w
    };
    assert!((depth(reversed, camera.near) - 1.0).abs() < 1e-6 && depth(reversed, camera.far).abs() < 1e-6);
    assert!(depth(standard, camera.near).abs() < 1e-6 && (depth(standard, camera.far) - 1.0).abs() < 1e-6);
    // At 100 m: about 6 cm, and about 7 µm.
    let (before, after) = (depth_step(standard, 100.0, false), depth_step(reversed, 100.0, true));
    eprintln!(
        "at 100 m: {:.1} mm standard, {:.4} mm reversed, {:.0} times finer",
        before * 1e3,
        after * 1e3,
        before / after
    );
    assert!((0.055..0.065).contains(&before), "{before}");
    assert!((5e-6..1e-5).contains(&after), "{after}");
    assert!(
        (before / after / REVERSED_DEPTH_FINER_AT_100_M - 1.0).abs() < 0.15,
        "{} times finer, the page says about {REVERSED_DEPTH_FINER_AT_100_M}",
        before / after
    );
    // Standard depth's step grows with the square of the distance (its
    // depths crowd just below 1, where floats are 2⁻²⁴ apart). Reversed
    // depth stores about n / d, and a float's spacing is a fixed share of
    // its size, 2⁻²⁴ to 2⁻²³: the step is that share of the distance, times
    // (1 − d / far), finer still towards the far plane.
    for d in [1.0, 10.0, 100.0, 1000.0, 1900.0] {
        let (standard_step, reversed_step) = (depth_step(standard, d, false), depth_step(reversed, d, true));
        let relative = reversed_step / f64::from(d);
        eprintln!(
            "{d} m: standard {standard_step:.3e} m, reversed {reversed_step:.3e} m ({relative:.2e} of the distance)"
        );
        let share = 1.0 - f64::from(d / camera.far);
        assert!(
            (2f64.powi(-24) * share * 0.99..2f64.powi(-23) * share * 1.01).contains(&relative),
            "{d} m: {relative}"
        );
        let expected = 2f64.powi(-24) * f64::from(d * d) / f64::from(camera.near);
        assert!((standard_step / expected - 1.0).abs() < 0.05, "{d} m: {standard_step} against {expected}");
    }
}

/// The primitives lesson says what the primitives' volume check catches: a mesh wound
/// inside out changes its sign, but one flipped triangle of chapter 02's
/// sphere (32 × 16) moves it by at most 0.3 %, inside the test's 3 %; the
/// check of each triangle's winding against its normals is what catches that.
/// The most one flipped triangle of the 32 × 16 sphere moves its volume,
/// as a share of the whole (the page's figure, to within 0.0005).
const ONE_FLIP_MOVES_THE_VOLUME_AT_MOST: f32 = 0.003;

#[test]
fn one_flipped_triangle_hides_in_the_volume_check_a_mesh_inside_out_does_not() {
    let sphere = primitives::uv_sphere(32, 16);
    let volume = |triangles: &mut dyn Iterator<Item = [Vec3; 3]>| -> f32 {
        triangles.map(|[a, b, c]| a.dot(b.cross(c)) / 6.0).sum()
    };
    let whole = volume(&mut sphere.triangles());
    let flipped_alone: Vec<f32> = (0..sphere.indices.len() / 3)
        .map(|flipped| {
            let mut triangles =
                sphere.triangles().enumerate().map(|(i, [a, b, c])| if i == flipped { [a, c, b] } else { [a, b, c] });
            1.0 - volume(&mut triangles) / whole
        })
        .collect();
    let (least, most) = flipped_alone.iter().fold((f32::MAX, 0.0f32), |(l, m), &v| (l.min(v), m.max(v)));
    eprintln!(
        "one flipped triangle of {}: the volume moves by {:.3} to {:.3} %",
        flipped_alone.len(),
        least * 100.0,
        most * 100.0
    );
    assert!((most - ONE_FLIP_MOVES_THE_VOLUME_AT_MOST).abs() < 0.0005 && least > 0.0, "{least} {most}");
    let inside_out = volume(&mut sphere.triangles().map(|[a, b, c]| [a, c, b]));
    assert!((inside_out + whole).abs() < 1e-6);
}

// ANCHOR: fly_diagonal
/// A fly camera, exercise 1, worked by hand: W and E held together for
/// half a second at 8 m/s from the start camera. The direction is the
/// level part of the view direction plus straight up, made one unit long,
/// so the camera goes 4 m along the diagonal between them: 4 / √2 = 2.83 m
/// up and as far across the ground, towards where the camera looks.
fn fly_diagonal_by_hand() -> Vec3 {
    let (eye, target) = (Vec3::new(-3.0, 4.0, 9.0), Vec3::new(0.0, 0.5, -1.0));
    let across = (target - eye).with_y(0.0).normalize();
    eye + (across + Vec3::Y).normalize() * 8.0 * 0.5
}
// ANCHOR_END: fly_diagonal

#[test]
fn fly_camera_exercise_1_w_and_e_go_four_metres_along_the_diagonal_whatever_the_pitch() {
    let by_hand = fly_diagonal_by_hand();
    assert!(by_hand.distance(Vec3::new(-2.19, 6.83, 6.29)) < 0.005, "{by_hand}");
    let controller = FlyController::default();
    assert_eq!(controller.speed, 8.0, "the default speed the exercise gives");
    let mut keys = Input::default();
    keys.key_down(KeyCode::KeyW);
    keys.key_down(KeyCode::KeyE);
    let start = start_camera(16.0 / 9.0);
    let looking_down = Camera { pitch: start.pitch - 30f32.to_radians(), ..start };
    for camera in [start, looking_down] {
        // At 30 frames a second, and in one frame of half a second.
        for (frames, dt) in [(15, 1.0 / 30.0), (1, 0.5)] {
            let mut flown = camera;
            for _ in 0..frames {
                controller.update(&mut flown, &keys, dt);
            }
            eprintln!("pitch {:.1}°, {frames} frames: {}", camera.pitch.to_degrees(), flown.position);
            assert!(flown.position.distance(by_hand) < 1e-4, "{} against {by_hand}", flown.position);
        }
    }
}

// ANCHOR: sample_bytes
/// Smooth edges, exercise 1, worked by hand: the bytes of the scene's
/// colour samples and depth buffer for a 1280 × 720 picture, at four
/// samples a pixel and at one (where the scene is drawn straight into the
/// picture, and only the depth buffer is the scene's own). A colour of
/// `Rgba8UnormSrgb` and a depth of `Depth32Float` are 4 bytes each.
const PIXELS: u64 = 1280 * 720;
const FOUR_SAMPLES: u64 = 4 * 4 * PIXELS + 4 * 4 * PIXELS;
const ONE_SAMPLE: u64 = 4 * PIXELS;
// ANCHOR_END: sample_bytes

#[test]
fn multisampling_exercise_1_four_samples_cost_the_bytes_worked_out_by_hand() {
    assert_eq!(FOUR_SAMPLES - ONE_SAMPLE, 25_804_800, "25.8 MB, as the lesson says");
    let gpu = Gpu::headless(GpuNeeds::default()).expect("an adapter (lavapipe will do)");
    let bytes = || common::memory::gpu_bytes(&gpu.device).unwrap_or(0);
    let target = Target { format: OFFSCREEN_FORMAT, width: 1280, height: 720, samples: 1 };
    // The picture exists whatever the samples: made before counting.
    let picture = Offscreen::new(&gpu.device, target);
    // Each scene is kept until the end, so that none is freed while
    // another is counted.
    let scene_bytes = |samples: u32| {
        let before = bytes();
        let scene = SceneTargets::new(&gpu, Target { samples, ..target });
        assert_eq!(scene.samples(), samples, "the adapter multisamples the format");
        // The colour samples are made for the first picture they resolve into.
        let _attachment = scene.colour_attachment(&picture.view);
        (bytes() - before, scene)
    };
    let ((four, _four_samples), (one, _one_sample)) = (scene_bytes(4), scene_bytes(1));
    eprintln!("by wgpu's count: {four} bytes with four samples, {one} with one");
    assert!(four > 0, "the device counts no memory");
    assert_eq!((four, one), (FOUR_SAMPLES, ONE_SAMPLE));
}
