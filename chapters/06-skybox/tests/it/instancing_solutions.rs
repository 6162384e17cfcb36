//! Worked solutions to the exercises of book page 05 (instancing), compiled
//! and checked here, with chapter 06's tests (see `main.rs` for why): the
//! page includes them by anchor, and each test asserts the figure it states.

use std::ops::Range;

use common::glam::{Mat4, Quat, Vec3};
use common::headless::{OFFSCREEN_FORMAT, Offscreen, capture, read_texture};
use common::wgpu::util::DeviceExt as _;
use common::{Camera, Chapter, Gpu, MeshData, PassTimer, Target, Vertex, image, shader, wgpu};
use fog::{FogBinding, FogSettings};
use instancing::{
    InstancingChapter, MAX_ROCKS, RockGroup, RockInstance, RockRuns, plain_camera, rock_mesh, scatter, visible_runs,
};
use terrain::chunks::Aabb;
use terrain::culling::Frustum;
use terrain::heightfield::{HeightField, TerrainSettings};
use terrain::{KEEP_ALL, SKY, Sun, TerrainData, TerrainRenderer};

#[test]
fn exercise_1_one_call_per_rock_draws_the_same_picture() {
    let gpu = crate::plain_gpu();
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
fn exercise_2_a_tilted_rock_tilts_its_normal_by_the_same_rotation() {
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
fn exercise_3_four_rock_meshes_cost_three_more_calls() {
    let gpu = crate::plain_gpu();
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
/// Exercise 4: the runs the chapter draws, split by distance: the groups
/// whose box comes nearer than `near` metres to the eye keep the full rock,
/// the others are drawn with a coarse one. Each half is a list of runs of
/// its own, one instanced call each, as before.
fn near_and_far(groups: &[RockGroup], count: u32, frustum: &Frustum, eye: Vec3, near: f32) -> (RockRuns, RockRuns) {
    // The nearest point of a box to the eye is the eye clamped into it.
    let distance = |b: &Aabb| eye.clamp(b.min, b.max).distance(eye);
    let (close, far): (Vec<RockGroup>, Vec<RockGroup>) =
        groups.iter().cloned().partition(|group| distance(&group.bounds) < near);
    (visible_runs(&close, count, Some(frustum)), visible_runs(&far, count, Some(frustum)))
}
// ANCHOR_END: near_and_far

#[test]
fn exercise_4_far_rocks_with_a_coarse_mesh_save_three_fifths_of_the_vertices() {
    let gpu = crate::plain_gpu();
    let target = Target { format: OFFSCREEN_FORMAT, width: 320, height: 180, samples: 1 };
    let chapter: InstancingChapter = common::chapter::create(gpu, target, &Default::default()).unwrap();
    // The default view's camera, with its far plane in the haze.
    let camera = Camera { far: FogSettings::HAZE.far_plane(), ..chapter.camera };
    let frustum = Frustum::from_view_projection(camera.view_projection());
    let groups = &chapter.plain.rock_field().groups;
    let all = visible_runs(groups, MAX_ROCKS, Some(&frustum));
    let (near, far) = near_and_far(groups, MAX_ROCKS, &frustum, camera.position, 300.0);
    assert_eq!(near.rocks + far.rocks, all.rocks, "every rock drawn once, near or far");
    // 60 vertices a rock; an octahedron, flat-shaded, has 8 × 3 = 24.
    let (before, after) = (60 * all.rocks, 60 * near.rocks + 24 * far.rocks);
    let saved = 100.0 * f64::from(before - after) / f64::from(before);
    eprintln!(
        "{} rocks: {} within 300 m, {} beyond; {before} vertices become {after} ({saved:.0} % fewer), in {} + {} calls",
        all.rocks,
        near.rocks,
        far.rocks,
        near.runs.len(),
        far.runs.len()
    );
    // Within 300 m is (300 / 2088)² of the view's area, about 2 %: nearly
    // every rock is far, and 36 of its 60 vertices go.
    assert!(near.rocks * 20 < all.rocks);
    assert!((58.0..60.0).contains(&saved), "{saved}");
    // The figures page 05's solution gives.
    assert_eq!((all.rocks, near.rocks, before, after), (276_571, 6_279, 16_594_260, 6_863_748));
    assert_eq!((near.runs.len(), far.runs.len()), (14, 776));
}
