//! Worked solutions to the exercises of chapter 05's lessons, compiled and
//! checked with the chapter's own tests: the lessons include them by
//! anchor, and each test asserts the figure it states. The tests that draw
//! share one device (`test_gpu`), so the terrain and the million rocks are
//! made once for all of them (`Gpu::cached`).

use std::ops::Range;

use crate::rock_culling::{dispatch_size, list_bytes};
use crate::{
    Grading, InstancingChapter, MAX_ROCKS, Picture, RockCulling, RockGroup, RockInstance, RockRuns, RockSource,
    WORKGROUP_SIZE, plain_camera, rock_mesh, scatter, visible_runs,
};
use common::glam::{Mat4, Quat, Vec3, Vec4};
use common::headless::{OFFSCREEN_FORMAT, Offscreen, capture, read_texture};
use common::wgpu::util::DeviceExt as _;
use common::{Camera, Chapter, Gpu, MeshData, PassTimer, Target, Vertex, image, shader, wgpu};
use fog::{FogBinding, FogSettings};
use terrain::chunks::Aabb;
use terrain::culling::Frustum;
use terrain::heightfield::{HeightField, TerrainSettings};
use terrain::{KEEP_ALL, SKY, Sun, TerrainData, TerrainRenderer};

/// One device for every test of the chapter that draws, with the plain's
/// needs (`gpu_needs`: chapter 03's, and indirect draws for the
/// `multi-draw` view): the terrain and the rocks are made once on it and
/// shared.
pub(crate) fn test_gpu() -> &'static Gpu {
    static GPU: std::sync::OnceLock<Gpu> = std::sync::OnceLock::new();
    GPU.get_or_init(|| Gpu::headless(crate::gpu_needs()).expect("an adapter (lavapipe will do)"))
}

#[test]
fn one_draw_exercise_1_one_call_per_rock_draws_the_same_picture() {
    let gpu = test_gpu();
    let target = Target { format: OFFSCREEN_FORMAT, width: 320, height: 180, samples: 1 };
    let mut chapter: InstancingChapter = common::chapter::create(gpu, target, &Default::default()).unwrap();
    let mut picture = |view: &str| {
        let view = common::chapter::view_index::<InstancingChapter>(view).unwrap();
        chapter.select_view(view);
        let picture = capture(gpu, &mut chapter, target, (0.0, view), Default::default()).unwrap();
        (picture, chapter.draw_calls.rocks)
    };
    // The two bench views: 10,000 rocks without the terrain, one call each
    // and all in one call.
    let ((one_by_one, calls), (instanced, one_call)) = (picture("naive-10k"), picture("rocks-10k"));
    assert_eq!((calls, one_call), (10_000, 1));
    assert_eq!(one_by_one, instanced, "the same rocks, byte for byte");

    // What the extra 9,999 calls cost is on the page, computed from the
    // bench tables by `{{#figure}}` when the book is built (and its claim
    // that the slider's calls do not halve the frame by a `{{#check}}`).
}

/// A rock's model matrix as the shader builds it, with a tilt about its
/// own x axis before the yaw: scale, tilt, turn, move.
fn tilted_model(rock: &RockInstance, tilt: f32) -> Mat4 {
    Mat4::from_translation(rock.position.into())
        * Mat4::from_rotation_y(rock.yaw)
        * Mat4::from_rotation_x(tilt)
        * Mat4::from_scale(rock.scale.into())
}

// ANCHOR: tilted_normal
/// Exercise 2: the normal of a tilted rock. The rotations are the same
/// for the normal as for the position (a rotation is its own inverse
/// transpose); only the scale is inverted, as before.
fn tilted_normal(rock: &RockInstance, tilt: f32, normal: Vec3) -> Vec3 {
    let turn = Quat::from_rotation_y(rock.yaw) * Quat::from_rotation_x(tilt);
    (turn * (normal / Vec3::from(rock.scale))).normalize()
}
// ANCHOR_END: tilted_normal

/// `rocks.wgsl`'s model transform, and the tilted one that replaces it.
const ROCK_TRANSFORM: &str = "    let world = turn(position * rock.scale_shade.xyz, yaw) + rock.position_yaw.xyz;";
const ROCK_NORMAL: &str = "    out.normal = turn(normal / rock.scale_shade.xyz, yaw);";
// ANCHOR: tilted_wgsl
/// Exercise 2, in `rocks.wgsl`: `rock_vertex`'s position, tilted…
const TILTED_TRANSFORM: &str = "    // Exercise 2: a tilt about the rock's own x axis (here from its
    // shade, −0.4 to 0.4 rad), between the scale and the turn.
    let tilt = 0.8 * rock.scale_shade.w - 0.4;
    let world = turn(tip(position * rock.scale_shade.xyz, tilt), yaw) + rock.position_yaw.xyz;";
/// …its normal, tilted the same way…
const TILTED_NORMAL: &str = "    // The same two rotations, after the inverse scale.
    out.normal = turn(tip(normal / rock.scale_shade.xyz, tilt), yaw);";
/// …and the tilt itself, a new function.
const TIP: &str = "
// Turns v about x by `angle` radians.
fn tip(v: vec3<f32>, angle: f32) -> vec3<f32> {
    let s = sin(angle);
    let c = cos(angle);
    return vec3<f32>(v.x, c * v.y - s * v.z, s * v.y + c * v.z);
}
";
// ANCHOR_END: tilted_wgsl

#[test]
fn one_draw_exercise_2_a_tilted_rock_tilts_its_normal_by_the_same_rotation() {
    let field = HeightField::generate(TerrainSettings { chunks_per_side: 16, ..Default::default() });
    let (rocks, mesh) = (scatter(&field, 200, 5), rock_mesh(5));
    let (mut worst_right, mut worst_forgotten) = (0.0f32, 0.0f32);
    for rock in &rocks {
        let tilt = 0.8 * rock.shade - 0.4;
        let normal_matrix = tilted_model(rock, tilt).inverse().transpose();
        for v in &mesh.vertices {
            let n = Vec3::from(v.normal);
            let truth = normal_matrix.transform_vector3(n).normalize();
            let angle = |m: Vec3| truth.dot(m).clamp(-1.0, 1.0).acos().to_degrees();
            worst_right = worst_right.max(angle(tilted_normal(rock, tilt, n)));
            // Forgetting the tilt: the chapter's normal, yaw and scale only.
            worst_forgotten = worst_forgotten.max(angle(tilted_normal(rock, 0.0, n)));
        }
    }
    eprintln!("normal error with the tilt: {worst_right:.3}°; without it: {worst_forgotten:.1}°");
    assert!(worst_right < 0.05, "{worst_right}");
    // Forgotten, the light is off by as much as the tilt itself, 0.4 rad.
    assert!((worst_forgotten - 0.4f32.to_degrees()).abs() < 1.5, "{worst_forgotten}");

    // The WGSL edit is valid against the real modules.
    let rocks_wgsl =
        shader!("instancing/rocks.wgsl", imports: ["terrain/terrain.wgsl", "fog/fog.wgsl", "instancing/rock.wgsl"]);
    let mut edited = rocks_wgsl.embedded.to_string();
    for (from, to) in [(ROCK_TRANSFORM, TILTED_TRANSFORM), (ROCK_NORMAL, TILTED_NORMAL)] {
        assert!(edited.contains(from), "rocks.wgsl changed: update the exercise's edit");
        edited = edited.replacen(from, to, 1);
    }
    edited.push_str(TIP);
    let imports: Vec<(&str, String)> = rocks_wgsl.imports.iter().map(|i| (i.path, i.embedded.to_string())).collect();
    common::shader::compose(&edited, rocks_wgsl.path, &imports).unwrap();
}

/// Rocks drawn by a test, with chapter 05's shader, pipeline layout and
/// instance layout: meshes and instance ranges of the solution's choosing,
/// from the plain's camera, in the haze, without the terrain.
struct RockLab {
    terrain: TerrainRenderer,
    air: FogBinding,
    pipeline: wgpu::RenderPipeline,
    camera: Camera,
    target: Target,
}

impl RockLab {
    fn new(gpu: &Gpu) -> Self {
        let target = Target { format: OFFSCREEN_FORMAT, width: 400, height: 225, samples: 1 };
        let terrain = TerrainRenderer::new(gpu, TerrainData::get(gpu, TerrainSettings::default()));
        let air = FogBinding::new(&gpu.device);
        air.write(&gpu.queue, FogSettings::HAZE);
        let layout = gpu.device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: None,
            bind_group_layouts: &[Some(&terrain.bind_group_layout), Some(&air.layout)],
            immediate_size: 0,
        });
        let rocks =
            shader!("instancing/rocks.wgsl", imports: ["terrain/terrain.wgsl", "fog/fog.wgsl", "instancing/rock.wgsl"]);
        let module = rocks.module(gpu).unwrap();
        let buffers = [Some(Vertex::LAYOUT), Some(RockInstance::LAYOUT)];
        let pipeline = common::pipeline::mesh_pipeline(
            &gpu.device,
            &layout,
            &module,
            ("vs_instanced", "fs_main"),
            &buffers,
            target.format.into(),
            Default::default(),
        );
        let camera = Camera { far: FogSettings::HAZE.far_plane(), ..plain_camera(terrain.field(), target.aspect()) };
        Self { terrain, air, pipeline, camera, target }
    }

    /// Draws `rocks`: for each (mesh, range), the rocks in `range` with
    /// that mesh, in one instanced call. Returns the picture.
    fn draw(&self, gpu: &Gpu, rocks: &[RockInstance], calls: &[(&MeshData, Range<u32>)]) -> image::RgbaImage {
        let device = &gpu.device;
        let instances = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("rocks"),
            contents: bytemuck::cast_slice(rocks),
            usage: wgpu::BufferUsages::VERTEX,
        });
        let meshes: Vec<_> = calls.iter().map(|(mesh, _)| mesh.upload(device, "rock")).collect();
        let mut viewpoint = self.terrain.viewpoint(device);
        self.terrain.aim(
            gpu,
            &mut viewpoint,
            &self.camera,
            terrain::Detail::lod(self.target.height),
            Sun::AFTERNOON,
            KEEP_ALL,
        );
        let offscreen = Offscreen::new(device, self.target);
        let depth = common::texture::depth_view(device, self.target.width, self.target.height);
        let mut encoder = device.create_command_encoder(&Default::default());
        {
            let mut pass =
                common::pipeline::scene_pass(&mut encoder, &PassTimer::off(), "rocks", &offscreen.view, SKY, &depth);
            pass.set_pipeline(&self.pipeline);
            self.terrain.bind(&mut pass, &viewpoint);
            pass.set_bind_group(1, &self.air.group, &[]);
            pass.set_vertex_buffer(1, instances.slice(..));
            for (mesh, (_, range)) in meshes.iter().zip(calls) {
                pass.set_vertex_buffer(0, mesh.vertex_buffer.slice(..));
                pass.set_index_buffer(mesh.index_buffer.slice(..), wgpu::IndexFormat::Uint32);
                pass.draw_indexed(0..mesh.index_count, 0, range.clone());
            }
        }
        gpu.queue.submit([encoder.finish()]);
        read_texture(gpu, &offscreen.texture).unwrap()
    }
}

// ANCHOR: variety
/// Exercise 3: `kinds` rock meshes from different seeds, and the instance
/// range each draws: the scatter is random, so consecutive blocks of it
/// are as good a mix as any. One instanced call per mesh.
fn varied_rocks(kinds: u32, rocks: u32) -> Vec<(MeshData, Range<u32>)> {
    let block = rocks.div_ceil(kinds);
    (0..kinds).map(|k| (rock_mesh(100 + u64::from(k)), k * block..((k + 1) * block).min(rocks))).collect()
}
// ANCHOR_END: variety

#[test]
fn one_draw_exercise_3_four_rock_meshes_cost_three_more_calls() {
    let gpu = test_gpu();
    let lab = RockLab::new(gpu);
    let rocks = scatter(lab.terrain.field(), 20_000, 5);
    let varied = varied_rocks(4, rocks.len() as u32);
    assert_eq!(varied.len(), 4, "one call per mesh");
    assert_eq!(varied.iter().map(|(_, r)| r.len()).sum::<usize>(), rocks.len(), "every rock once");
    let calls: Vec<(&MeshData, Range<u32>)> = varied.iter().map(|(m, r)| (m, r.clone())).collect();
    let one_mesh = rock_mesh(5);
    let (four, one) = (lab.draw(gpu, &rocks, &calls), lab.draw(gpu, &rocks, &[(&one_mesh, 0..rocks.len() as u32)]));
    let sky = *one.get_pixel(0, 0);
    let rock_pixels = |picture: &image::RgbaImage| picture.pixels().filter(|&&p| p != sky).count();
    eprintln!("rock pixels with one mesh {}, with four {}", rock_pixels(&one), rock_pixels(&four));
    assert_ne!(four, one);
    // Three more calls where there was one, and the meshes take
    // 3 × 60 vertices × 32 bytes = 5,760 bytes more.
    assert_eq!(3 * one_mesh.vertices.len() * size_of::<Vertex>(), 5_760);
}

// ANCHOR: near_and_far
/// Exercise 1 of the chunk lesson: the runs the chapter draws, split by
/// distance: the groups whose box comes nearer than `near` metres to the
/// eye keep the full rock, the others are drawn with a coarse one. Each
/// half is a list of runs of its own, one instanced call each, as before.
fn near_and_far(groups: &[RockGroup], count: u32, frustum: &Frustum, eye: Vec3, near: f32) -> (RockRuns, RockRuns) {
    // The nearest point of a box to the eye is the eye clamped into it.
    let distance = |b: &Aabb| eye.clamp(b.min, b.max).distance(eye);
    let (close, far): (Vec<RockGroup>, Vec<RockGroup>) =
        groups.iter().cloned().partition(|group| distance(&group.bounds) < near);
    (visible_runs(&close, count, Some(frustum)), visible_runs(&far, count, Some(frustum)))
}
// ANCHOR_END: near_and_far

/// Exercise 1 of the chunk lesson: the distance, metres, past which a group
/// is drawn with the coarse rock, and the share of the vertices that saves,
/// per cent (the page's figures; the test counts the vertices itself).
const NEAR_GROUPS_METRES: f32 = 300.0;
const COARSE_SAVES_PERCENT: f64 = 58.6;

#[test]
fn chunks_exercise_1_far_rocks_with_a_coarse_mesh_save_three_fifths_of_the_vertices() {
    let gpu = test_gpu();
    let target = Target { format: OFFSCREEN_FORMAT, width: 320, height: 180, samples: 1 };
    let chapter: InstancingChapter = common::chapter::create(gpu, target, &Default::default()).unwrap();
    // The default view's camera, with its far plane in the haze.
    let camera = Camera { far: FogSettings::HAZE.far_plane(), ..chapter.camera };
    let frustum = Frustum::from_view_projection(camera.view_projection());
    let groups = &chapter.plain.rock_field().groups;
    let all = visible_runs(groups, MAX_ROCKS, Some(&frustum));
    let (near, far) = near_and_far(groups, MAX_ROCKS, &frustum, camera.position, NEAR_GROUPS_METRES);
    assert_eq!(near.rocks + far.rocks, all.rocks, "every rock drawn once, near or far");
    // 60 vertices a rock; an octahedron, flat-shaded, has 8 × 3 = 24.
    let (before, after) = (60 * all.rocks, 60 * near.rocks + 24 * far.rocks);
    let saved = 100.0 * f64::from(before - after) / f64::from(before);
    eprintln!(
        "{} rocks: {} within {NEAR_GROUPS_METRES} m, {} beyond; {before} vertices become {after} ({saved:.0} % fewer), in {} + {} calls",
        all.rocks,
        near.rocks,
        far.rocks,
        near.runs.len(),
        far.runs.len()
    );
    // Within 300 m is (300 / 2088)² of the view's area, about 2 %: nearly
    // every rock is far, and 36 of its 60 vertices go.
    assert!(near.rocks * 20 < all.rocks);
    assert!((saved - COARSE_SAVES_PERCENT).abs() < 0.05, "{saved}");
    // The figures the lesson's solution gives.
    assert_eq!((all.rocks, near.rocks, before, after), (276_571, 6_279, 16_594_260, 6_863_748));
    assert_eq!((near.runs.len(), far.runs.len()), (14, 776));
}

/// The camera of the by-hand test (`culling_checks::BY_HAND`): at the
/// origin looking down −z, 60° high, a square picture 600 pixels high,
/// the far plane at 600 m, nothing clipped.
fn by_hand_picture() -> Picture {
    let camera = Camera {
        position: Vec3::ZERO,
        yaw: 0.0,
        pitch: 0.0,
        fov_y: 60f32.to_radians(),
        aspect: 1.0,
        near: 0.1,
        far: 600.0,
    };
    Picture { camera, height: 600, clip: KEEP_ALL }
}

/// The list each rock of `rocks` (its centre, and its radius) lands in,
/// culled by the chapter's compute pass from the by-hand camera with
/// `grading`: the level, or `None` where the pass drops it.
fn levels_of(rocks: &[([f32; 3], f32)], grading: Grading) -> Vec<Option<usize>> {
    let gpu = test_gpu();
    let device = &gpu.device;
    let culling = RockCulling::new(gpu, [60, 24, 12]).unwrap();
    // Each rock's own sphere is the unit sphere about where it stands, so
    // its radius in the world is its scale.
    let records: Vec<RockInstance> = (rocks.iter())
        .map(|&(position, radius)| RockInstance { position, yaw: 0.7, scale: [radius; 3], shade: 0.5 })
        .collect();
    let buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: Some("rocks placed by an exercise"),
        contents: bytemuck::cast_slice(&records),
        usage: wgpu::BufferUsages::STORAGE,
    });
    let group = culling.rocks_group(device, &buffer);
    let mut lists = culling.lists(device, records.len() as u32);
    let source = RockSource { group: &group, sphere: Vec4::new(0.0, 0.0, 0.0, 1.0), count: records.len() as u32 };
    culling.aim(&gpu.queue, &lists, &by_hand_picture(), &source, grading);
    let mut encoder = device.create_command_encoder(&Default::default());
    culling.cull(gpu, &mut encoder, &PassTimer::off(), &mut lists, &source);
    gpu.queue.submit([encoder.finish()]);
    let kept = lists.lists_now(gpu);
    (0..rocks.len() as u32).map(|index| kept.iter().position(|list| list.contains(&index))).collect()
}

// ANCHOR: right_edge
/// Exercise 1 of the compute lesson: how far to the right of straight
/// ahead the centre of a sphere of `radius`, `ahead` metres away, may lie
/// and the sphere still be kept, where half the field of view across is
/// `half_fov`. The side plane is at `ahead · tan(half_fov)`; a centre δ
/// past it is δ · cos(half_fov) from the plane, kept while that is at
/// most the radius.
fn rightmost_kept(ahead: f32, radius: f32, half_fov: f32) -> f32 {
    ahead * half_fov.tan() + radius / half_fov.cos()
}
// ANCHOR_END: right_edge

#[test]
fn compute_exercise_1_a_sphere_is_kept_to_1_155_m_past_the_side_plane() {
    let half_fov = 30f32.to_radians();
    assert!((100.0 * half_fov.tan() - 57.735).abs() < 1e-3, "the right plane, 100 m ahead");
    let bound = rightmost_kept(100.0, 1.0, half_fov);
    eprintln!("kept to x = {bound:.3} m");
    assert!((bound - 58.890).abs() < 1e-3, "{bound}");
    // The compute shader agrees, either side of the bound. Full detail: a
    // rock in view is kept, whatever its size.
    let levels = levels_of(&[([58.87, 0.0, -100.0], 1.0), ([58.91, 0.0, -100.0], 1.0)], Grading::FULL_DETAIL);
    assert_eq!(levels, [Some(0), None], "58.87 m is kept, 58.91 m dropped");
}

// ANCHOR: list_regions
/// Exercise 1 of the indirect lesson: where each level's list starts in a
/// picture's buffer of lists, and the bytes of all three, for `capacity`
/// rocks on a device whose storage offsets align to `alignment` bytes.
fn list_regions(capacity: u32, alignment: u32) -> ([u64; 3], u64) {
    let each = list_bytes(capacity, alignment);
    ([0, each, 2 * each], 3 * each)
}
// ANCHOR_END: list_regions

#[test]
fn indirect_exercise_1_three_lists_of_62_500_rocks_take_750_336_bytes_at_256() {
    // 62,500 × 4 = 250,000 bytes, 976.6 × 256: rounded up to 977 × 256.
    let (starts, total) = list_regions(62_500, 256);
    assert_eq!((starts, total), ([0, 250_112, 500_224], 750_336));
    assert_eq!(total - 3 * 62_500 * 4, 336, "112 bytes of padding a list");
    // On the test's own device, a picture's buffers are the three lists at
    // its alignment and a few hundred bytes more (the draws, the record,
    // the copies read back late).
    let device = &test_gpu().device;
    let culling = RockCulling::new(test_gpu(), [60, 24, 12]).unwrap();
    let alignment = device.limits().min_storage_buffer_offset_alignment;
    let lists = culling.lists(device, 62_500).gpu_bytes();
    let (_, ours) = list_regions(62_500, alignment);
    eprintln!("alignment {alignment}: a picture holds {lists} bytes, {ours} of them the lists");
    assert!(lists >= ours && lists - ours < 1024, "{lists} against {ours}");
}

// ANCHOR: dearer_full_rock
/// Exercise 1 of the size lesson: the plain's grading, the full rock from
/// 24 pixels across instead of 12.
const DEARER_FULL_ROCK: Grading = Grading { full: 24.0, ..Grading::LOD };
// ANCHOR_END: dearer_full_rock

#[test]
fn size_exercise_1_from_24_pixels_the_full_rock_ends_at_43_m() {
    // 600 / (2 tan 30°) = 519.6 pixels a radian; radius 1 at d is 1,039.2 / d.
    let per_radian = by_hand_picture().pixels_per_radian();
    let across = |d: f32| 2.0 / d * per_radian;
    assert!((2.0 * per_radian / 24.0 - 43.3).abs() < 0.05, "the full rock ends at 43.3 m");
    assert!((across(50.0) - 20.8).abs() < 0.05 && across(50.0) > DEARER_FULL_ROCK.coarse);
    // The compute pass, with the new grading and the old.
    let rocks = [([0.0, 0.0, -43.0], 1.0), ([0.0, 0.0, -44.0], 1.0), ([0.0, 0.0, -50.0], 1.0)];
    assert_eq!(levels_of(&rocks, DEARER_FULL_ROCK), [Some(0), Some(1), Some(1)]);
    assert_eq!(levels_of(&rocks, Grading::LOD), [Some(0), Some(0), Some(0)], "all full rocks before");
}

// ANCHOR: five_million
/// Exercise 1 of the advanced lesson: the grid of workgroups for `rocks`
/// rocks where a dispatch holds at most `max_per_dimension` along a side,
/// and how many invocations find no rock, by `cull_rocks`'s own index
/// (`id.y * groups.x * WORKGROUP_SIZE + id.x`).
fn idle_invocations(rocks: u32, max_per_dimension: u32) -> ((u32, u32), u64) {
    let (x, y) = dispatch_size(rocks, max_per_dimension);
    let row = x * WORKGROUP_SIZE;
    let indices = (0..y).flat_map(|id_y| (0..row).map(move |id_x| id_y * row + id_x));
    ((x, y), indices.filter(|&index| index >= rocks).count() as u64)
}
// ANCHOR_END: five_million

#[test]
fn limits_exercise_1_five_million_rocks_take_two_rows_mostly_idle() {
    // 5,000,000 / 64 = 78,125 workgroups: more than 65,535, so two rows.
    let ((x, y), idle) = idle_invocations(5_000_000, 65_535);
    assert_eq!((x, y), (65_535, 2));
    assert_eq!(u64::from(x * y) * 64, 8_388_480, "invocations run");
    assert_eq!(idle, 3_388_480);
    // A grid near square, 280 × 280 workgroups, would leave 17,600 idle.
    assert_eq!(280 * 280 * 64 - 5_000_000, 17_600);
}
