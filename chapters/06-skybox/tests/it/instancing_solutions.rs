//! Worked solutions to the exercises of book page 05 (instancing), compiled
//! and checked here, with chapter 06's tests (see `main.rs` for why): the
//! page includes them by anchor, and each test asserts the figure it states.

use std::ops::Range;
use std::sync::Arc;

use common::book_figures::{median_ms, solution, thousands};
use common::glam::{Mat4, Quat, Vec3};
use common::headless::{OFFSCREEN_FORMAT, Offscreen, capture, read_texture};
use common::wgpu::util::DeviceExt as _;
use common::{Camera, Chapter, Gpu, MeshData, PassTimer, ShaderFile, Target, Vertex, image, shader, wgpu};
use fog::{FogBinding, FogSettings};
use instancing::{
    InstancingChapter, MAX_ROCKS, RockGroup, RockInstance, RockRuns, plain_camera, rock_mesh, scatter, visible_runs,
};
use terrain::chunks::Aabb;
use terrain::culling::Frustum;
use terrain::heightfield::{HeightField, TerrainSettings};
use terrain::{KEEP_ALL, SKY, Sun, TerrainData, TerrainMesh, TerrainRenderer};

/// The median frame time, in ms, of `view` in chapter 05's bench table
/// (`book/src/bench/instancing.md`, written by `cargo xtask bench instancing`).
fn bench_median_ms(view: &str) -> f64 {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../book/src/bench/instancing.md");
    let table = std::fs::read_to_string(path).unwrap();
    median_ms(&table, view, "frame").unwrap_or_else(|| panic!("no frame row for {view} in {path}"))
}

#[test]
fn exercise_1_one_call_per_rock_draws_the_same_picture_and_the_page_gives_its_cost() {
    let gpu = crate::plain_gpu();
    let target = Target { format: OFFSCREEN_FORMAT, width: 320, height: 180 };
    let mut chapter: InstancingChapter = common::chapter::create(gpu, target, &Default::default()).unwrap();
    let mut picture = |view: &str| {
        let view = common::chapter::view_index::<InstancingChapter>(view).unwrap();
        chapter.select_view(view);
        let picture = capture(gpu, &mut chapter, target, 0.0, view).unwrap();
        (picture, chapter.draw_calls.rocks)
    };
    // The two bench views: 10,000 rocks without the terrain, one call each
    // and all in one call.
    let ((one_by_one, calls), (instanced, one_call)) = (picture("naive-10k"), picture("rocks-10k"));
    assert_eq!((calls, one_call), (10_000, 1));
    assert_eq!(one_by_one, instanced, "the same rocks, byte for byte");

    // What the extra 9,999 calls cost, from the bench table (release
    // build, lavapipe, 1280 × 720), and what that means for the default
    // view's frame: the solution on page 05 must quote these figures, so
    // a bench run that moves them fails here until the page follows.
    let (naive, instanced, default) =
        (bench_median_ms("naive-10k"), bench_median_ms("rocks-10k"), bench_median_ms("default"));
    let per_call_us = (naive - instanced) * 1000.0 / 9_999.0;
    let to_halve = default * 1000.0 / per_call_us;
    // The slider's 20,000 calls (MAX_ONE_PER_DRAW), and a GPU's 5 ms frame.
    let slider_ms = 20_000.0 * per_call_us / 1000.0;
    let on_a_gpu = 5_000.0 / per_call_us;
    let quoted = [
        format!("{naive:.1} ms against {instanced:.1} ms"),
        format!("**{per_call_us:.1} µs**"),
        format!("frame is {default:.0} ms"),
        format!("**{}**", thousands((to_halve / 1000.0).round() * 1000.0)),
        format!("{slider_ms:.0} ms, {:.0} %", 100.0 * slider_ms / default),
        format!("about {} calls", thousands((on_a_gpu / 100.0).round() * 100.0)),
    ];
    let page =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../book/src/05-instancing.md")).unwrap();
    let solution = solution(&page, "What does one draw call cost").unwrap();
    for figure in &quoted {
        assert!(solution.contains(figure.as_str()), "page 05's solution should say `{figure}` (from the bench table)");
    }
    assert!(slider_ms < default, "the slider's calls do not halve the frame rate, as the page says");
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
        let target = Target { format: OFFSCREEN_FORMAT, width: 400, height: 225 };
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
            &gpu.queue,
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
    let target = Target { format: OFFSCREEN_FORMAT, width: 320, height: 180 };
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

/// Exercise 5: chapter 03's visible chunks in one instanced call. All the
/// instances of a call share one base vertex, so it can no longer say where
/// a chunk's vertices start: the shader reads them from a storage buffer
/// itself, at `chunk × 4225 + vertex_index` ("vertex pulling"), and a list
/// of the chunks the frustum keeps turns the instance into a chunk.
const ONE_CALL_TERRAIN: &str = "
// ANCHOR: one_call_terrain
enable clip_distances;
#import terrain::{VertexOutput, FragmentInput, globals, terrain_vertex, ground_colour, lit}

// A `TerrainVertex`: the height, then the normal's four signed bytes.
struct PackedVertex {
    height: f32,
    normal: u32,
};
@group(1) @binding(0) var<storage, read> vertices: array<PackedVertex>;
@group(1) @binding(1) var<storage, read> visible_chunks: array<u32>;

@vertex
fn vs_main(@builtin(vertex_index) vertex_index: u32, @builtin(instance_index) instance: u32) -> VertexOutput {
    let chunk = visible_chunks[instance];
    // What the base vertex did: skip the vertices of the chunks before it.
    let side = globals.grid.y + 1u;
    let vertex = vertices[chunk * side * side + vertex_index];
    return terrain_vertex(vertex_index, chunk, vertex.height, unpack4x8snorm(vertex.normal));
}

@fragment
fn fs_main(in: FragmentInput) -> @location(0) vec4<f32> {
    let n = normalize(in.normal);
    return vec4<f32>(lit(ground_colour(in.world_position.y, n), n), 1.0);
}
// ANCHOR_END: one_call_terrain
";

#[test]
fn exercise_5_every_visible_chunk_in_one_call_draws_the_same_terrain() {
    // A terrain of its own, 16 × 16 chunks, made here (not through the
    // device's cache, which keeps one terrain: the default one).
    let gpu = crate::plain_gpu();
    let settings = TerrainSettings { chunks_per_side: 16, ..Default::default() };
    let field = HeightField::generate(settings);
    let (vertices, bounds) = TerrainMesh::chunk_rows(&field, 0..16);
    let mesh = TerrainMesh::upload(&gpu.device, 16, &vertices, bounds);
    let terrain = TerrainRenderer::new(gpu, Arc::new(TerrainData { field, mesh, timings: (0.0, 0.0) }));
    let target = Target { format: OFFSCREEN_FORMAT, width: 320, height: 180 };
    let camera = terrain::start_camera(terrain.field(), target.aspect());
    let frustum = Frustum::from_view_projection(camera.view_projection());
    let visible: Vec<u32> = (0..terrain.chunk_bounds().len() as u32)
        .filter(|&c| frustum.intersects(&terrain.chunk_bounds()[c as usize]))
        .collect();

    // The storage buffers, their layout, and the pipeline.
    let device = &gpu.device;
    let storage = |contents: &[u8]| {
        device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: None,
            contents,
            usage: wgpu::BufferUsages::STORAGE,
        })
    };
    let (vertex_storage, visible_storage) =
        (storage(bytemuck::cast_slice(&vertices)), storage(bytemuck::cast_slice(&visible)));
    let group_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: None,
        entries: &[
            common::pipeline::storage_entry(0, wgpu::ShaderStages::VERTEX),
            common::pipeline::storage_entry(1, wgpu::ShaderStages::VERTEX),
        ],
    });
    let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout: &group_layout,
        entries: &[
            wgpu::BindGroupEntry { binding: 0, resource: vertex_storage.as_entire_binding() },
            wgpu::BindGroupEntry { binding: 1, resource: visible_storage.as_entire_binding() },
        ],
    });
    let pipeline_layout = |groups: &[Option<&wgpu::BindGroupLayout>]| {
        device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: None,
            bind_group_layouts: groups,
            immediate_size: 0,
        })
    };
    let one_call_layout = pipeline_layout(&[Some(&terrain.bind_group_layout), Some(&group_layout)]);
    let one_call_shader = ShaderFile {
        path: "terrain/one_call.wgsl",
        embedded: ONE_CALL_TERRAIN,
        imports: &[shader!("terrain/terrain.wgsl")],
    };
    let module = one_call_shader.module(gpu).unwrap();
    let one_call = common::pipeline::mesh_pipeline(
        device,
        &one_call_layout,
        &module,
        ("vs_main", "fs_main"),
        &[],
        target.format.into(),
    );
    let per_chunk_layout = pipeline_layout(&[Some(&terrain.bind_group_layout)]);
    let per_chunk =
        TerrainRenderer::pipeline(gpu, &shader!("terrain/terrain.wgsl"), &per_chunk_layout, target.format).unwrap();

    // The same picture both ways.
    let mut viewpoint = terrain.viewpoint(device);
    terrain.aim(&gpu.queue, &mut viewpoint, &camera, terrain::Detail::lod(target.height), Sun::AFTERNOON, KEEP_ALL);
    let render = |one_call_instead: bool| {
        let offscreen = Offscreen::new(device, target);
        let depth = common::texture::depth_view(device, target.width, target.height);
        let mut encoder = device.create_command_encoder(&Default::default());
        let calls = {
            let mut pass =
                common::pipeline::scene_pass(&mut encoder, &PassTimer::off(), "terrain", &offscreen.view, SKY, &depth);
            if one_call_instead {
                pass.set_pipeline(&one_call);
                terrain.bind(&mut pass, &viewpoint);
                pass.set_bind_group(1, &group, &[]);
                pass.set_index_buffer(terrain.mesh().index_buffer.slice(..), wgpu::IndexFormat::Uint16);
                pass.draw_indexed(0..terrain.mesh().index_count, 0, 0..visible.len() as u32);
                1
            } else {
                pass.set_pipeline(&per_chunk);
                terrain.draw(&mut pass, &viewpoint)
            }
        };
        gpu.queue.submit([encoder.finish()]);
        (read_texture(gpu, &offscreen.texture).unwrap(), calls)
    };
    let ((chunk_by_chunk, calls), (all_at_once, one)) = (render(false), render(true));
    eprintln!("{calls} chunks in {calls} calls, and in {one}");
    assert_eq!(calls, visible.len());
    assert_eq!(one, 1);
    // The same picture, but for a handful of pixels a step of one byte
    // apart: two shader programs, compiled differently, round differently.
    let steps: Vec<u8> = chunk_by_chunk
        .pixels()
        .zip(all_at_once.pixels())
        .map(|(a, b)| (0..3).map(|c| a[c].abs_diff(b[c])).max().unwrap())
        .filter(|&step| step > 0)
        .collect();
    eprintln!("{} of {} pixels differ, by at most {}", steps.len(), 320 * 180, steps.iter().max().unwrap_or(&0));
    assert!(steps.len() <= 10 && steps.iter().all(|&step| step == 1), "{steps:?}");
}

#[test]
fn page_05_quotes_the_gpus_culling_from_the_bench_table_and_webgpus_limits() {
    let page =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../book/src/05-instancing.md")).unwrap();
    let section = page.split_once("## Culling rock by rock, on the GPU").unwrap().1;
    let section = section.split_once("## The views").unwrap().0;

    // The lavapipe table (release build, 1280 × 720): the frames, and the
    // frame outside the render pass, where the compute pass's work shows.
    let table =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../book/src/bench/instancing.md")).unwrap();
    let read = |view: &str, what: &str| median_ms(&table, view, what).unwrap_or_else(|| panic!("{view} {what}"));
    let (graded, by_chunk) = (read("default", "frame"), read("cpu-culling", "frame"));
    let outside = |view: &str| read(view, "frame") - read(view, "GPU: terrain and rocks pass");
    let culling_pass = read("default", "GPU: rock culling pass");
    for figure in [
        format!("frame is {graded:.0} ms against {by_chunk:.0} ms culling by chunk"),
        format!("compute pass at {culling_pass:.2} ms"),
        format!("{:.1} ms, against {:.1} ms culling by chunk", outside("default"), outside("cpu-culling")),
    ] {
        assert!(section.contains(&figure), "page 05 should say `{figure}` (from the bench table)");
    }
    assert!(graded < by_chunk, "culling on the GPU makes the frame shorter, as the page says");

    // WebGPU's least limits, as wgpu writes them, and what the rocks ask.
    let limits = wgpu::Limits::default();
    let rocks_bytes = u64::from(MAX_ROCKS) * std::mem::size_of::<RockInstance>() as u64;
    let workgroups = MAX_ROCKS.div_ceil(instancing::WORKGROUP_SIZE);
    for row in [
        format!(
            "| `maxComputeInvocationsPerWorkgroup` | {} | {} per workgroup |",
            limits.max_compute_invocations_per_workgroup,
            instancing::WORKGROUP_SIZE
        ),
        format!(
            "| `maxComputeWorkgroupsPerDimension` | {} | {} workgroups for a million rocks: one row |",
            thousands(limits.max_compute_workgroups_per_dimension.into()),
            thousands(workgroups.into())
        ),
        format!(
            "| `maxStorageBufferBindingSize` | {} bytes | the rocks: {} bytes |",
            thousands(limits.max_storage_buffer_binding_size as f64),
            thousands(rocks_bytes as f64)
        ),
        format!("| `maxStorageBuffersPerShaderStage` | {} |", limits.max_storage_buffers_per_shader_stage),
        format!("| `minStorageBufferOffsetAlignment` | {} bytes |", limits.min_storage_buffer_offset_alignment),
    ] {
        assert!(section.contains(&row), "page 05's table of limits should hold `{row}`");
    }
    let most = u64::from(limits.max_compute_workgroups_per_dimension) * u64::from(instancing::WORKGROUP_SIZE);
    assert!(section.contains(&format!(
        "{} workgroups, {} rocks\nat 64",
        thousands(limits.max_compute_workgroups_per_dimension.into()),
        thousands(most as f64)
    )));
    // A picture's lists on the largest map: three of 4 bytes a rock
    // (`map_memory`'s test checks a picture's buffers against the same sum).
    let lists_mb = instancing::LEVELS as u64 * u64::from(MAX_ROCKS) * 4 / 1_000_000;
    assert!(page.contains(&format!("bytes a rock and the counts: {lists_mb} MB a picture")));
    // The haze the camera sees through, as the page says.
    assert!(section.contains(&format!("the {} m the haze", thousands(FogSettings::HAZE.far_plane().into()))));
}
