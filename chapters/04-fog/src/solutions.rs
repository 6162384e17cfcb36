//! Worked solutions to the exercises of chapter 04's lessons, compiled and
//! checked with the chapter's own tests: the lessons include them by
//! anchor, and each test asserts the figure it states.

use crate::{FogSettings, fog_shader};
use common::glam::Vec3;
use common::headless::{OFFSCREEN_FORMAT, Offscreen, read_texture};
use common::pipeline::uniform_entry;
use common::wgpu::util::DeviceExt as _;
use common::{PassTimer, ShaderFile, Target, image, shader, wgpu};
use terrain::culling::Frustum;
use terrain::heightfield::TerrainSettings;
use terrain::{KEEP_ALL, SKY, Sun, TerrainData, TerrainRenderer, start_camera};

/// One device for every test here: the terrain is made once on it and
/// shared (`Gpu::cached`).
fn test_gpu() -> &'static common::Gpu {
    static GPU: std::sync::OnceLock<common::Gpu> = std::sync::OnceLock::new();
    GPU.get_or_init(|| common::Gpu::headless(terrain::gpu_needs()).expect("an adapter (lavapipe will do)"))
}

// ANCHOR: fog_starts
/// Exercise 1: where the fog "starts", taken as the distance at which a
/// tenth of a surface's colour is gone: solve exp(−(d · density)^gradient)
/// = 0.9 for d, as `opaque_distance` solves it for 1/255.
fn fog_starts(fog: FogSettings) -> f32 {
    (-0.9f32.ln()).powf(1.0 / fog.gradient) / fog.density
}
// ANCHOR_END: fog_starts

/// Exercise 1: the terrain's triangles chapter 03's quadtree chooses from
/// the start camera at 1280 × 720, with the far plane at gradient 1's
/// opaque distance (held at 3 km) and at gradient 4's (measured: counted
/// from the quadtree, held exactly).
const TRIANGLES_AT_GRADIENT_1: usize = 284672;
const TRIANGLES_AT_GRADIENT_4: usize = 245760;

#[test]
fn exercise_1_gradient_4_is_clear_to_380_m_and_a_wall_by_1_km() {
    let gpu = test_gpu();
    let data = TerrainData::get(gpu, TerrainSettings::default());
    let [gentle, steep] = [1.0, 4.0].map(|gradient| FogSettings { gradient, ..FogSettings::HAZE });
    for fog in [gentle, steep, FogSettings::HAZE] {
        assert!((fog.visibility(fog_starts(fog)) - 0.9).abs() < 1e-5);
    }
    // The terrain's triangles each draws from the start camera at 1280 ×
    // 720, the far plane at the opaque distance (as the chapter sets it, at
    // most 3 km), as chapter 03's quadtree chooses them.
    let triangles = |fog: FogSettings| {
        let camera = common::Camera { far: fog.far_plane(), ..start_camera(&data.field, 16.0 / 9.0) };
        let frustum = Frustum::from_view_projection(camera.view_projection());
        let ranges = terrain::LodRanges::new(
            terrain::Detail::lod(720),
            camera.fov_y,
            data.field.settings.spacing,
            data.quadtree.node_reach(),
            data.quadtree.top_level(),
        );
        let mut patches = Vec::new();
        data.quadtree.select(&frustum, camera.position, &ranges, &mut patches);
        patches.len() * terrain::Patch::TRIANGLES as usize
    };
    let figures =
        [gentle, steep, FogSettings::HAZE].map(|fog| (fog_starts(fog), fog.opaque_distance(), triangles(fog)));
    eprintln!(
        "density 0.0015: (starts, opaque, triangles drawn) at gradient 1 {:?}, at gradient 4 {:?}, haze {:?}",
        figures[0], figures[1], figures[2]
    );
    // Gradient 1: a tenth gone at 70 m already, opaque only at 3.7 km.
    assert!((figures[0].0 - 70.2).abs() < 0.1 && (figures[0].1 - 3694.0).abs() < 1.0);
    // Gradient 4: clear to 380 m, then a wall: opaque at 1,023 m.
    assert!((figures[1].0 - 379.8).abs() < 0.1 && (figures[1].1 - 1023.0).abs() < 1.0);
    // The far plane comes in from 3 km (the limit) to 1,023 m, and the
    // terrain's triangles from 284,672 to 245,760: with levels of detail
    // the distant land was cheap already. (Measured: the counts come from
    // chapter 03's quadtree, and the test holds them exactly.)
    assert_eq!((figures[0].2, figures[1].2), (TRIANGLES_AT_GRADIENT_1, TRIANGLES_AT_GRADIENT_4));
    // At full detail every chunk in the frustum was drawn: the wall took
    // three quarters of them away, 1,219 becoming 316.
    let chunks = |fog: FogSettings| {
        let camera = common::Camera { far: fog.far_plane(), ..start_camera(&data.field, 16.0 / 9.0) };
        let frustum = Frustum::from_view_projection(camera.view_projection());
        data.chunk_bounds.iter().filter(|b| frustum.intersects(b)).count()
    };
    assert_eq!((chunks(gentle), chunks(steep)), (1219, 316));
    // The haze, gradient 1.5, between the two: 149 m, 2,088 m, 282,624 triangles.
    assert!((figures[2].0 - 148.7).abs() < 0.1 && (figures[2].1 - 2088.0).abs() < 1.0 && figures[2].2 == 282_624);
}

/// Heights: the scale of the height fog, metres.
const FOG_HEIGHT: f32 = 100.0;

// ANCHOR: height_fog_cpu
/// Exercise 2, the simple version: the air at the surface's own height,
/// density · exp(−height / 100 m), all the way from the eye.
fn height_fog_simple(fog: FogSettings, distance: f32, height: f32) -> f32 {
    let density = fog.density * (-height / FOG_HEIGHT).exp();
    (-(distance * density).powf(fog.gradient)).exp()
}

/// Exercise 2, the exact version: the density integrated along the ray
/// from the eye (at `eye_height`) to the surface. Height changes linearly
/// along the ray, so the mean of exp(−h / H) over it is
/// (exp(−h₀ / H) − exp(−h₁ / H)) / ((h₁ − h₀) / H), or exp(−h₀ / H) for a
/// level ray.
fn height_fog_exact(fog: FogSettings, distance: f32, eye_height: f32, height: f32) -> f32 {
    let rise = (height - eye_height) / FOG_HEIGHT;
    let at_eye = (-eye_height / FOG_HEIGHT).exp();
    let mean = if rise.abs() < 1e-4 { at_eye } else { (at_eye - (-height / FOG_HEIGHT).exp()) / rise };
    (-(distance * fog.density * mean).powf(fog.gradient)).exp()
}
// ANCHOR_END: height_fog_cpu

/// The line of `fog.wgsl` the height fog replaces.
const VISIBILITY_CALL: &str = "return vec4<f32>(mix(fog.colour.rgb, surface, visibility(distance)), 1.0);";
/// Exercise 2: the height fog, the exact version, in `fs_main`.
const HEIGHT_FOG: &str = "
// ANCHOR: height_fog_wgsl
    // Exercise 2: the air thins with height, to 1/e every 100 m. The
    // density integrated from the eye to the surface is density · distance
    // times the mean of exp(−h / 100 m) along the ray (the simple version
    // takes exp(−h / 100 m) at the surface instead).
    let rise = (in.world_position.y - globals.eye.y) / 100.0;
    let at_eye = exp(-globals.eye.y / 100.0);
    let mean = select((at_eye - exp(-in.world_position.y / 100.0)) / rise, at_eye, abs(rise) < 1e-4);
    let thickness = distance * fog.density * mean;
    let seen = exp(-pow(thickness, fog.gradient));
    return vec4<f32>(mix(fog.colour.rgb, surface, seen), 1.0);
// ANCHOR_END: height_fog_wgsl
";

/// `fog.wgsl` with `edit` in place of `original`, as a shader file that
/// imports the terrain module like the chapter's.
fn edited_fog_shader(original: &str, edit: &str) -> ShaderFile {
    let file = fog_shader();
    assert!(file.embedded.contains(original), "fog.wgsl changed: update the exercise's edit");
    ShaderFile { embedded: Box::leak(file.embedded.replacen(original, edit, 1).into_boxed_str()), ..file }
}

// ANCHOR: fog_for_vertices
/// Exercise 3: the fog's uniform (`Fog` in fog.wgsl: colour, density,
/// gradient, padding) in a bind group the vertex stage can read too, as
/// per-vertex fog needs: `FogBinding::new` shows it to fragments only.
fn fog_group(device: &wgpu::Device, fog: FogSettings) -> (wgpu::BindGroupLayout, wgpu::BindGroup) {
    let values = [SKY.r as f32, SKY.g as f32, SKY.b as f32, 1.0, fog.density, fog.gradient, 0.0, 0.0];
    let buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: Some("fog"),
        contents: bytemuck::cast_slice(&values),
        usage: wgpu::BufferUsages::UNIFORM,
    });
    let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("fog"),
        entries: &[uniform_entry(0, wgpu::ShaderStages::VERTEX_FRAGMENT, size_of_val(&values))],
    });
    let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some("fog"),
        layout: &layout,
        entries: &[wgpu::BindGroupEntry { binding: 0, resource: buffer.as_entire_binding() }],
    });
    (layout, group)
}
// ANCHOR_END: fog_for_vertices

/// The terrain from the start camera in `fog`, at 320 × 180, drawn with `shader`.
fn render_fogged(shader: &ShaderFile, fog: FogSettings) -> image::RgbaImage {
    let gpu = test_gpu();
    let target = Target { format: OFFSCREEN_FORMAT, width: 320, height: 180, samples: 1 };
    let terrain = TerrainRenderer::new(gpu, TerrainData::get(gpu, TerrainSettings::default()));
    let (air_layout, air) = fog_group(&gpu.device, fog);
    let layout = gpu.device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
        label: None,
        bind_group_layouts: &[Some(&terrain.bind_group_layout), Some(&air_layout)],
        immediate_size: 0,
    });
    let pipeline = TerrainRenderer::pipeline(gpu, shader, &layout, (target.format, 1)).unwrap();
    let camera = common::Camera { far: fog.far_plane(), ..start_camera(terrain.field(), target.aspect()) };
    let mut viewpoint = terrain.viewpoint(&gpu.device);
    terrain.aim(gpu, &mut viewpoint, &camera, terrain::Detail::lod(target.height), Sun::AFTERNOON, KEEP_ALL);
    let offscreen = Offscreen::new(&gpu.device, target);
    let depth = common::texture::depth_view(&gpu.device, target.width, target.height);
    let mut encoder = gpu.device.create_command_encoder(&Default::default());
    {
        let mut pass =
            common::pipeline::scene_pass(&mut encoder, &PassTimer::off(), "fog", &offscreen.view, SKY, &depth);
        pass.set_pipeline(&pipeline);
        pass.set_bind_group(1, &air, &[]);
        terrain.draw(&mut pass, &viewpoint);
    }
    gpu.queue.submit([encoder.finish()]);
    read_texture(gpu, &offscreen.texture).unwrap()
}

/// Exercise 2, in the haze, 1 km away: what even fog leaves of any surface;
/// what simple height fog leaves of a valley floor at −100 m and a summit
/// at +100 m; what the exact height fog leaves of them from an eye 30 m up
/// (each worked out by the test's own integration, to within 0.001, the
/// valley's simple figure to within 0.000005).
const EVEN_FOG_KEEPS: f32 = 0.159;
const SIMPLE_VALLEY_KEEPS: f32 = 0.000266;
const SIMPLE_SUMMIT_KEEPS: f32 = 0.664;
const EXACT_VALLEY_KEEPS: f32 = 0.032;
const EXACT_SUMMIT_KEEPS: f32 = 0.489;
/// Exercise 2: the pixels of a 320 × 180 picture the height fog changes
/// (measured: a change detector, held to within 1,500).
const HEIGHT_FOG_CHANGED_PIXELS: usize = 27509;

#[test]
fn exercise_2_height_fog_fills_the_valleys_and_leaves_the_peaks() {
    // In the haze, 1 km away: a valley floor at −100 m and a summit at
    // +100 m, against the same ground in the chapter's even fog.
    let haze = FogSettings::HAZE;
    let (valley, summit, even) =
        (height_fog_simple(haze, 1000.0, -100.0), height_fog_simple(haze, 1000.0, 100.0), haze.visibility(1000.0));
    eprintln!("1 km away, simple height fog: valley {valley:.4}, summit {summit:.3}; even fog {even:.3}");
    assert!((valley - SIMPLE_VALLEY_KEEPS).abs() < 0.000005, "{valley}");
    assert!((summit - SIMPLE_SUMMIT_KEEPS).abs() < 0.001 && (even - EVEN_FOG_KEEPS).abs() < 0.001);
    // Along the ray, from an eye at 30 m: the valley 1 km away keeps more
    // (the ray crosses thinner air on its way down), the summit less (the
    // ray starts in thicker air).
    let (valley_exact, summit_exact) =
        (height_fog_exact(haze, 1000.0, 30.0, -100.0), height_fog_exact(haze, 1000.0, 30.0, 100.0));
    eprintln!("exact, eye at 30 m: valley {valley_exact:.3}, summit {summit_exact:.3}");
    assert!((valley_exact - EXACT_VALLEY_KEEPS).abs() < 0.001 && (summit_exact - EXACT_SUMMIT_KEEPS).abs() < 0.001);
    assert!((height_fog_exact(haze, 500.0, 20.0, 20.0) - height_fog_simple(haze, 500.0, 20.0)).abs() < 1e-6);

    // The WGSL edit builds, runs, and changes the picture.
    let even_picture = render_fogged(&fog_shader(), haze);
    let height_picture = render_fogged(&edited_fog_shader(VISIBILITY_CALL, HEIGHT_FOG), haze);
    let changed = even_picture.pixels().zip(height_picture.pixels()).filter(|(a, b)| a != b).count();
    eprintln!("height fog changes {changed} of {} pixels", 320 * 180);
    // Nearly half the picture: nearly all the ground.
    assert!(changed.abs_diff(HEIGHT_FOG_CHANGED_PIXELS) < 1_500, "{changed}");
}

/// Exercise 3: fog computed per vertex. The vertex shader works out the
/// visibility and the rasteriser interpolates it, as the Mars project did.
const PER_VERTEX_FOG: &str = "
// ANCHOR: per_vertex_fog
enable clip_distances;
#import terrain::{globals, terrain_vertex, ground_normal, ground_colour, lit}
#import fog::{fog, visibility}

struct FoggedVertex {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) world_position: vec3<f32>,
    // Computed at the vertex, blended across the triangle.
    @location(1) seen: f32,
};

@vertex
fn vs_main(@builtin(vertex_index) vertex_index: u32, @location(0) this_patch: vec3<u32>) -> FoggedVertex {
    let v = terrain_vertex(vertex_index, this_patch);
    let distance = length(v.world_position - globals.eye.xyz);
    return FoggedVertex(v.clip_position, v.world_position, visibility(distance));
}

@fragment
fn fs_main(in: FoggedVertex) -> @location(0) vec4<f32> {
    let n = ground_normal(in.world_position.xz);
    let surface = lit(ground_colour(in.world_position.y, n), n);
    return vec4<f32>(mix(fog.colour.rgb, surface, in.seen), 1.0);
}
// ANCHOR_END: per_vertex_fog
";

/// The per-vertex shader as a file importing the terrain and fog modules.
fn per_vertex_shader() -> ShaderFile {
    ShaderFile {
        path: "fog/per_vertex.wgsl",
        embedded: PER_VERTEX_FOG,
        imports: &[shader!("terrain/terrain.wgsl"), shader!("fog/fog.wgsl", imports: ["terrain/terrain.wgsl"])],
    }
}

// ANCHOR: ground_quad
/// Exercise 3: chapter 02's 60 m ground quad, per vertex. The rasteriser
/// blends the corners' visibilities by the point's barycentric weights,
/// which in a triangle are linear in the world position. Returns the
/// visibility it gives at `point` and the true one there, seen from `eye`.
fn quad_visibility(fog: FogSettings, eye: Vec3, point: Vec3) -> (f32, f32) {
    // Chapter 02's ground: `primitives::plane(1)` scaled by 60, two
    // triangles (b, c, d) and (a, c, b) on either side of the diagonal x + z = 0.
    let [a, b, c, d] = [(-30.0, -30.0), (30.0, -30.0), (-30.0, 30.0), (30.0, 30.0)].map(|(x, z)| Vec3::new(x, 0.0, z));
    let [p, q, r] = if point.x + point.z > 0.0 { [b, c, d] } else { [a, c, b] };
    let area = |u: Vec3, v: Vec3, w: Vec3| (v - u).cross(w - u).y;
    let weights = [area(point, q, r), area(p, point, r), area(p, q, point)].map(|w| w / area(p, q, r));
    let per_vertex: f32 =
        [p, q, r].iter().zip(weights).map(|(corner, w)| w * fog.visibility(corner.distance(eye))).sum();
    (per_vertex, fog.visibility(point.distance(eye)))
}
// ANCHOR_END: ground_quad

/// Exercise 3: chapter 02's ground under its camera, 4 m below the eye, in
/// fog scaled to that scene: what it should keep, and what per-vertex fog
/// leaves it (the blend of the quad's corners), to within 0.001.
const TRUE_UNDER_THE_EYE: f32 = 0.994;
const PER_VERTEX_UNDER_THE_EYE: f32 = 0.519;

#[test]
fn exercise_3_per_vertex_fog_matches_on_terrain_and_fails_on_a_big_quad() {
    // On the terrain, cells of 1 to 8 m within the storm's 588 m: the dust
    // storm per vertex and per fragment, from the start camera.
    let storm = FogSettings::DUST_STORM;
    let (per_fragment, per_vertex) = (render_fogged(&fog_shader(), storm), render_fogged(&per_vertex_shader(), storm));
    let differences: Vec<u8> = per_fragment
        .pixels()
        .zip(per_vertex.pixels())
        .map(|(a, b)| (0..3).map(|c| a[c].abs_diff(b[c])).max().unwrap())
        .collect();
    let (most, differing) = (*differences.iter().max().unwrap(), differences.iter().filter(|&&d| d > 0).count());
    eprintln!(
        "terrain in the dust storm, per vertex against per fragment: {differing} pixels differ, by at most {most}"
    );
    // Measured (a change detector, as the page says): 139 pixels, one step.
    assert!(most <= 1 && differing.abs_diff(139) <= 30, "{differing} pixels, by up to {most}");

    // Chapter 02's ground, 60 m across in two triangles, seen from its
    // camera at (−3, 4, 9) in fog scaled to that scene (density 0.02,
    // gradient 2: opaque at 118 m). Right under the eye the ground is 4 m
    // away and should be clear; per vertex it takes the corners' fog.
    let small_scene_fog = FogSettings { density: 0.02, gradient: 2.0 };
    let eye = Vec3::new(-3.0, 4.0, 9.0);
    let (blended, true_visibility) = quad_visibility(small_scene_fog, eye, Vec3::new(-3.0, 0.0, 9.0));
    eprintln!("under chapter 02's camera: per vertex {blended:.3}, per fragment {true_visibility:.3}");
    assert!(
        (blended - PER_VERTEX_UNDER_THE_EYE).abs() < 0.001 && (true_visibility - TRUE_UNDER_THE_EYE).abs() < 0.001,
        "{blended} {true_visibility}"
    );
}
