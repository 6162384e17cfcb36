//! Worked solutions to the exercises of chapter 09's lessons, in the
//! lessons' order, each test named after its lesson. Each makes the change
//! its exercise asks for and asserts the figure the lesson's solution
//! states, so that the solutions are built and checked with the chapter.

use std::collections::HashMap;
use std::path::Path;

use common::glam::{Mat4, Vec2, Vec3};
use common::headless::read_level_bytes;
use common::image::RgbaImage;
use common::texture::ColorSpace;
use common::{Camera, Chapter, Gpu, MeshData, ShaderFile, primitives, shader, wgpu};
use lighting::aerial_camera;
use lighting::city::{City, Material, Shape};
use lighting::lights::Light;
use textures::materials::{Uploader, upload};
use textures::mipmaps::{MipMaker, box_filter_srgb};
use textures::obj::smooth_normals;
use textures::scenes::{stage_lights, stage_placement, world_uvs};
use textures::tangents::{triangle_tangents, vertex_tangents};
use textures::{CameraPreset, TexturesChapter};

/// `file` with `edits` made to the text of `path` (the file itself or a
/// module it imports), composed with its imports and validated by naga.
/// Each edit's `before` must occur exactly once.
fn compiles_with(file: ShaderFile, path: &str, edits: &[(&str, &str)]) {
    file.compose_edited(path, edits).unwrap_or_else(|e| panic!("{e}"));
}

/// One of the project's pictures, by its path under `assets/`.
fn picture(path: &str) -> RgbaImage {
    let bytes = textures::builtin::read(Path::new(path)).unwrap();
    common::image::load_from_memory(&bytes).unwrap().to_rgba8()
}

/// A texel of a normal map as the direction it stores.
fn direction(texel: &common::image::Rgba<u8>) -> Vec3 {
    Vec3::new(texel[0] as f32, texel[1] as f32, texel[2] as f32) / 255.0 * 2.0 - 1.0
}

/// Metres one pixel spans at `distance` metres, across the view, with the
/// chapters' 60° field of view on 720 rows.
fn pixel_metres(distance: f32) -> f32 {
    distance * 2.0 * 30f32.to_radians().tan() / 720.0
}

// Lesson 1: texture coordinates and texel density.

// ANCHOR: round_tower
/// Texture coordinates, exercise 1: a round tower `diameter` metres across
/// (chapter 08's 24-sided cylinder, 30 m tall) clad in concrete, one repeat
/// per 4 m. Returns how many repeats go round it (the largest u on its
/// side, where the seam closes) and how wide one is (the length of the
/// side's top ring of vertices over that).
fn round_tower(diameter: f32) -> (f32, f32) {
    let cylinder = Shape::Cylinder.mesh();
    let model = Mat4::from_scale(Vec3::new(diameter, 30.0, diameter));
    let uvs = world_uvs(&cylinder, model, Shape::Cylinder, 4.0);
    let side: Vec<(Vec3, Vec2)> = cylinder
        .vertices
        .iter()
        .zip(&uvs)
        .filter(|(v, _)| v.normal[1] == 0.0)
        .map(|(v, uv)| (model.transform_point3(v.position.into()), *uv))
        .collect();
    let repeats = side.iter().map(|(_, uv)| uv.x).fold(0.0, f32::max);
    let mut top: Vec<(Vec3, Vec2)> = side.into_iter().filter(|(p, _)| p.y > 0.0).collect();
    top.sort_by(|a, b| a.1.x.total_cmp(&b.1.x));
    let round: f32 = top.windows(2).map(|pair| pair[0].0.distance(pair[1].0)).sum();
    (repeats, round / repeats)
}
// ANCHOR_END: round_tower

#[test]
fn coordinates_exercise_1_a_round_tower_takes_a_whole_number_of_repeats() {
    let (repeats_12, width_12) = round_tower(12.0);
    let (repeats_10, width_10) = round_tower(10.0);
    println!(
        "12 m across: {repeats_12} repeats of {width_12:.3} m; 10 m across: {repeats_10} repeats of {width_10:.3} m"
    );
    // Worked by hand: 24 chords of 2 r sin 7.5°, over 4 m, rounded.
    assert_eq!((repeats_12, repeats_10), (9.0, 8.0));
    assert!((width_12 - 4.18).abs() < 0.005 && (width_10 - 3.92).abs() < 0.005);
}

// Lesson 2: sampling, aliasing and mipmaps.

// ANCHOR: brick_repeat
/// Sampling, exercise 1: brick texels across one pixel of a wall `distance` metres
/// away, facing the camera, when one repeat of the 256-texel brick covers
/// `repeat` metres; and the mip level a trilinear sampler then reads.
fn brick_footprint(distance: f32, repeat: f32) -> (f32, f32) {
    let texels = 256.0 / repeat * pixel_metres(distance);
    (texels, texels.log2().max(0.0))
}

/// How far `camera` is from the nearest brick building of chapter 08's
/// city, and from the middle one of them all (the boxes' nearest points).
fn brick_distances(camera: &Camera) -> (f32, f32) {
    let city = City::new();
    let mut distances: Vec<f32> = city
        .pieces
        .iter()
        .filter(|p| p.material == Material::Brick)
        .map(|p| {
            let corners = (0..8).map(|i| {
                let corner = Vec3::new((i & 1) as f32, ((i >> 1) & 1) as f32, ((i >> 2) & 1) as f32) - 0.5;
                p.model.transform_point3(corner)
            });
            let (low, high) = corners.fold((Vec3::MAX, Vec3::MIN), |(lo, hi), c| (lo.min(c), hi.max(c)));
            camera.position.clamp(low, high).distance(camera.position)
        })
        .collect();
    distances.sort_by(f32::total_cmp);
    (distances[0], distances[distances.len() / 2])
}

/// How much of the brick's pattern a mip level keeps: the standard
/// deviation of its texels' brightness (linear light), relative to level 0's.
fn brick_contrast(level: u32) -> f32 {
    let mut image = picture("textures/brick/albedo.png");
    let spread = |image: &RgbaImage| {
        let values: Vec<f32> = image.pixels().map(|p| (p[0] as f32 + p[1] as f32 + p[2] as f32) / 765.0).collect();
        let mean = values.iter().sum::<f32>() / values.len() as f32;
        (values.iter().map(|v| (v - mean).powi(2)).sum::<f32>() / values.len() as f32).sqrt()
    };
    let full = spread(&image);
    for _ in 0..level {
        image = box_filter_srgb(&image);
    }
    spread(&image) / full
}
// ANCHOR_END: brick_repeat

#[test]
fn sampling_exercise_1_bricks_every_3_m_are_huge_in_the_street_and_nearly_flat_from_the_air() {
    // In the street, a wall across the 12 m road; from the air, the aerial
    // camera's distance to the middle one of the city's brick buildings.
    let street = 10.0;
    let air = brick_distances(&aerial_camera(16.0 / 9.0)).1;
    let (street_1, street_3) = (brick_footprint(street, 1.0), brick_footprint(street, 3.0));
    let (air_1, air_3) = (brick_footprint(air, 1.0), brick_footprint(air, 3.0));
    let (contrast_1, contrast_3) = (brick_contrast(air_1.1.round() as u32), brick_contrast(air_3.1.round() as u32));
    println!(
        "a wall {street} m away: {:.2} texels a pixel (level {:.1}) at 1 m a repeat, {:.2} (level {:.1}) at 3 m; \
         the brick buildings from the air, {air:.0} m: level {:.1} and {:.1}, keeping {:.3} and {:.3} of the contrast",
        street_1.0, street_1.1, street_3.0, street_3.1, air_1.1, air_3.1, contrast_1, contrast_3
    );
    assert!((street_1.0 - 4.11).abs() < 0.01 && (street_3.0 - 1.37).abs() < 0.01);
    assert!((air - AIR_TO_BRICK).abs() < 1.0);
    assert!((contrast_1 - CONTRAST_KEPT_AT_1_M).abs() < 0.003 && (contrast_3 - CONTRAST_KEPT_AT_3_M).abs() < 0.003);
}

/// The share of the brick's pattern (its texels' standard deviation) that
/// the levels read from the air keep, at 1 m and 3 m a repeat.
const CONTRAST_KEPT_AT_1_M: f32 = 0.031;
const CONTRAST_KEPT_AT_3_M: f32 = 0.091;

/// Metres from the aerial camera to the middle one of the city's brick buildings.
const AIR_TO_BRICK: f32 = 321.0;
// ANCHOR: lod_clamp
/// Sampling, exercise 2: the trilinear sampler with its finest level clamped to 2.
fn clamped_to_level_2() -> wgpu::SamplerDescriptor<'static> {
    wgpu::SamplerDescriptor { lod_min_clamp: 2.0, ..textures::materials::SamplerMode::Mipmaps.descriptor(false) }
}

/// The mip level the GPU picks for the lab's floor along the middle column
/// of a 1280 × 720 picture, row by row: λ = log₂ of the larger of the
/// texture coordinates' changes to the next pixel across and down, in
/// texels (32 to the metre), with the floor's distance at that row.
fn lab_levels() -> Vec<(f32, f32)> {
    let camera = CameraPreset::Lab.place(16.0 / 9.0).1;
    let inverse = camera.view_projection().inverse();
    let floor = |x: f32, y: f32| {
        let ndc = Vec2::new(x / 1280.0 * 2.0 - 1.0, 1.0 - y / 720.0 * 2.0);
        let near = inverse.project_point3(ndc.extend(0.0));
        let d = inverse.project_point3(ndc.extend(1.0)) - near;
        (d.y < 0.0).then(|| near + d * (-near.y / d.y))
    };
    (0..720)
        .filter_map(|row| {
            let (x, y) = (640.5, row as f32 + 0.5);
            let (p, right, down) = (floor(x, y)?, floor(x + 1.0, y)?, floor(x, y + 1.0)?);
            let texels = |q: Vec3| (q - p).length() * 32.0;
            Some((p.distance(camera.position), texels(right).max(texels(down)).log2()))
        })
        .collect()
}
// ANCHOR_END: lod_clamp

#[test]
fn sampling_exercise_2_a_clamped_finest_level_blurs_everything_near() {
    assert_eq!(clamped_to_level_2().lod_min_clamp, 2.0);
    let levels = lab_levels();
    // The farthest row that still wants a level below 2, and the nearest row's level.
    let reach = levels.iter().filter(|(_, level)| *level < 2.0).map(|(distance, _)| *distance).fold(0.0, f32::max);
    let (nearest, level) = levels.iter().copied().min_by(|a, b| a.0.total_cmp(&b.0)).unwrap();
    let rows = levels.iter().filter(|(_, level)| *level < 2.0).count();
    println!(
        "rows wanting a level finer than 2: {rows} of 720, out to {reach:.1} m; the nearest floor, {nearest:.2} m away, \
         wants level {level:.2}: a level-2 texel there spans {:.0} pixels",
        2f32.powf(2.0 - level)
    );
    assert!((reach - LEVEL_2_REACH).abs() < 0.1 && (rows as f32 - LEVEL_2_ROWS).abs() < 3.0);
}

/// How far the lab's floor wants a finer level than 2, metres, and on how many rows of 720.
const LEVEL_2_REACH: f32 = 11.6;
const LEVEL_2_ROWS: f32 = 304.0;

// Lesson 3: sRGB, which numbers are light.

// ANCHOR: compute_mips
/// sRGB, exercise 1: a mip level by a compute shader, written to a storage
/// texture. Normal maps: average, normalise, store. Colour: the texels are
/// read through an sRGB view (decoded to light), averaged, encoded by the
/// shader, and stored through a plain `Rgba8Unorm` view of the same bytes,
/// since storage textures have no sRGB format.
const COMPUTE_MIPS: &str = "
@group(0) @binding(0) var above: texture_2d<f32>;
@group(0) @binding(1) var below: texture_storage_2d<rgba8unorm, write>;

fn mean_of_four(at: vec2<u32>) -> vec4<f32> {
    let corner = vec2<i32>(at) * 2;
    return (textureLoad(above, corner, 0) + textureLoad(above, corner + vec2<i32>(1, 0), 0)
        + textureLoad(above, corner + vec2<i32>(0, 1), 0) + textureLoad(above, corner + vec2<i32>(1, 1), 0)) / 4.0;
}

@compute @workgroup_size(8, 8)
fn cs_normals(@builtin(global_invocation_id) id: vec3<u32>) {
    if any(id.xy >= textureDimensions(below)) {
        return;
    }
    let average = mean_of_four(id.xy).xyz * 2.0 - 1.0;
    let n = normalize(select(vec3<f32>(0.0, 0.0, 1.0), average, length(average) > 1e-4));
    textureStore(below, id.xy, vec4<f32>(n * 0.5 + 0.5, 1.0));
}

fn encode(c: vec3<f32>) -> vec3<f32> {
    return select(1.055 * pow(c, vec3<f32>(1.0 / 2.4)) - 0.055, 12.92 * c, c <= vec3<f32>(0.0031308));
}

@compute @workgroup_size(8, 8)
fn cs_colour(@builtin(global_invocation_id) id: vec3<u32>) {
    if any(id.xy >= textureDimensions(below)) {
        return;
    }
    let mean = mean_of_four(id.xy);
    textureStore(below, id.xy, vec4<f32>(encode(mean.rgb), mean.a));
}
";

/// Level 1 of `image` by the compute shader's `entry` point, read back.
/// `srgb`: the source texture holds sRGB colour, read through an sRGB view.
fn level_1_by_compute(gpu: &Gpu, image: &RgbaImage, entry: &str, srgb: bool) -> Vec<u8> {
    let device = &gpu.device;
    let (width, height) = image.dimensions();
    let texture = |size: (u32, u32), usage| {
        device.create_texture(&wgpu::TextureDescriptor {
            label: Some("compute mips"),
            size: wgpu::Extent3d { width: size.0, height: size.1, depth_or_array_layers: 1 },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            // Plain bytes, with an sRGB view of them allowed: the one
            // format a storage texture and an sRGB texture can share.
            format: wgpu::TextureFormat::Rgba8Unorm,
            usage,
            view_formats: &[wgpu::TextureFormat::Rgba8UnormSrgb],
        })
    };
    let above = texture((width, height), wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST);
    let below = texture((width / 2, height / 2), wgpu::TextureUsages::STORAGE_BINDING | wgpu::TextureUsages::COPY_SRC);
    gpu.queue.write_texture(
        above.as_image_copy(),
        image.as_raw(),
        wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(4 * width), rows_per_image: None },
        above.size(),
    );
    let format = srgb.then_some(wgpu::TextureFormat::Rgba8UnormSrgb);
    let read = above.create_view(&wgpu::TextureViewDescriptor { format, ..Default::default() });
    let write = below.create_view(&Default::default());
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("compute mips"),
        source: wgpu::ShaderSource::Wgsl(COMPUTE_MIPS.into()),
    });
    let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: Some(entry),
        layout: None,
        module: &module,
        entry_point: Some(entry),
        compilation_options: Default::default(),
        cache: None,
    });
    let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some("compute mips"),
        layout: &pipeline.get_bind_group_layout(0),
        entries: &[
            wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::TextureView(&read) },
            wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::TextureView(&write) },
        ],
    });
    let mut encoder = device.create_command_encoder(&Default::default());
    {
        let mut pass = encoder.begin_compute_pass(&Default::default());
        pass.set_pipeline(&pipeline);
        pass.set_bind_group(0, &group, &[]);
        pass.dispatch_workgroups((width / 2).div_ceil(8), (height / 2).div_ceil(8), 1);
    }
    gpu.queue.submit([encoder.finish()]);
    read_level_bytes(gpu, &below, 0, 4).unwrap()
}
// ANCHOR_END: compute_mips

#[test]
fn srgb_exercise_1_compute_mips_match_the_render_passes_and_srgb_needs_a_plain_view() {
    let gpu = Gpu::headless(TexturesChapter::gpu_needs()).unwrap();
    // No sRGB format can be a storage texture, here or in WebGPU.
    let srgb = gpu.adapter.get_texture_format_features(wgpu::TextureFormat::Rgba8UnormSrgb);
    assert!(!srgb.allowed_usages.contains(wgpu::TextureUsages::STORAGE_BINDING));
    let mut mips = MipMaker::new(&gpu).unwrap();
    let mut up = Uploader::new(&gpu, &mut mips, &textures::builtin::read);
    let maps = [
        ("textures/brick/normal.png", ColorSpace::Linear, "cs_normals"),
        ("textures/brick/albedo.png", ColorSpace::Srgb, "cs_colour"),
    ];
    let uploaded: Vec<_> = maps.iter().map(|(path, space, _)| upload(&mut up, &picture(path), *space, path)).collect();
    up.finish();
    for ((path, space, entry), by_passes) in maps.iter().zip(&uploaded) {
        let by_passes = read_level_bytes(&gpu, &by_passes.texture, 1, 4).unwrap();
        let by_compute = level_1_by_compute(&gpu, &picture(path), entry, *space == ColorSpace::Srgb);
        let worst = by_passes.iter().zip(&by_compute).map(|(a, b)| a.abs_diff(*b)).max().unwrap();
        println!("{path}: level 1 by compute within {worst} of the render passes' ({} bytes)", by_compute.len());
        assert!(worst <= 2, "{path}: {worst}");
    }
    // And the CPU's box filter in linear light agrees with the sRGB one.
    let albedo = picture("textures/brick/albedo.png");
    let reference = box_filter_srgb(&albedo);
    let by_compute = level_1_by_compute(&gpu, &albedo, "cs_colour", true);
    assert!(reference.as_raw().iter().zip(&by_compute).all(|(a, b)| a.abs_diff(*b) <= 1));
}

// Lesson 4: models from OBJ and MTL.

// ANCHOR: smoothing
/// An edge, by the positions of its two ends (to a tenth of a millimetre).
type Edge = [[i64; 3]; 2];
/// A face along an edge: its own normal, and the normals it gives the edge's ends.
type FaceAlong = (Vec3, [Vec3; 2]);

/// Models, exercise 1: a mesh's edges between faces that are not in one plane,
/// and how many of them stay sharp once `smooth_normals` has given it
/// normals with `max_angle` degrees as the limit (an edge is sharp when
/// its two faces give its ends different normals).
fn sharp_edges(mesh: &MeshData, max_angle: f32) -> (usize, usize) {
    let (smooth, _) = smooth_normals(mesh, max_angle);
    let key = |i: u32| smooth.vertices[i as usize].position.map(|c| (c * 1e4).round() as i64);
    let mut edges: HashMap<Edge, Vec<FaceAlong>> = HashMap::new();
    for t in smooth.indices.chunks_exact(3) {
        let p = |k: usize| Vec3::from(smooth.vertices[t[k] as usize].position);
        let face = (p(1) - p(0)).cross(p(2) - p(0)).normalize();
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            let (ka, kb) = (key(a), key(b));
            let normals = |i: u32| Vec3::from(smooth.vertices[i as usize].normal);
            let (entry, ends) =
                if ka < kb { ([ka, kb], [normals(a), normals(b)]) } else { ([kb, ka], [normals(b), normals(a)]) };
            edges.entry(entry).or_default().push((face, ends));
        }
    }
    let creases: Vec<_> = edges.values().filter(|f| f.len() == 2 && f[0].0.dot(f[1].0) < 0.9999).collect();
    let sharp = creases.iter().filter(|f| f[0].1.iter().zip(&f[1].1).any(|(a, b)| a.distance(*b) > 1e-4)).count();
    (sharp, creases.len())
}
// ANCHOR_END: smoothing

#[test]
fn models_exercise_1_the_smoothing_angle_decides_which_edges_stay_sharp() {
    let shapes = [
        ("sphere", primitives::uv_sphere(16, 8)),
        ("cylinder", primitives::cylinder(16)),
        ("cube", primitives::cube()),
    ];
    let mut found = Vec::new();
    for (name, mesh) in &shapes {
        let counts: Vec<(usize, usize)> = [20.0, 60.0, 90.0].iter().map(|a| sharp_edges(mesh, *a)).collect();
        println!("{name}: sharp edges of creased ones at 20°, 60°, 90°: {counts:?}");
        found.push(counts.iter().map(|(sharp, _)| *sharp).collect::<Vec<_>>());
    }
    assert_eq!(found, SHARP_EDGES);
}

/// Sharp edges of the sphere, cylinder and cube at 20°, 60° and 90°.
const SHARP_EDGES: [[usize; 3]; 3] = [[176, 0, 0], [48, 32, 0], [12, 12, 0]];

// Lesson 5: bringing your own model.

// ANCHOR: centimetres
/// Bringing your own model, exercise 1: a box the size of a car, 450 cm
/// long, 150 cm high and 180 cm wide, as an OBJ in centimetres (no normals,
/// no texture coordinates, quads), or in metres when `unit` is 1: the scale
/// the stage gives it, and the length and height it stands on the stage.
fn car_sized_box(unit: f32) -> (f32, f32, f32) {
    let (length, height, width) = (4.5 / unit, 1.5 / unit, 1.8 / unit);
    let mut text = String::new();
    for i in 0..8 {
        let corner = |bit: usize, size: f32| if i >> bit & 1 == 1 { size } else { 0.0 };
        text += &format!("v {} {} {}\n", corner(0, length), corner(1, height), corner(2, width));
    }
    text += "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
    let read = |_: &Path| -> Result<Vec<u8>, common::files::ReadError> { Ok(text.as_bytes().to_vec()) };
    let loaded = textures::obj::load(Path::new("car-sized box.obj"), &read).unwrap();
    let (placement, scale) = stage_placement(loaded.model.bounds());
    let placed = |p: Vec3| placement.transform_point3(p);
    let on_stage = placed(Vec3::new(length, 0.0, 0.0)).distance(placed(Vec3::ZERO));
    let tall = placed(Vec3::new(0.0, height, 0.0)).y - placed(Vec3::ZERO).y;
    (scale, on_stage, tall)
}
// ANCHOR_END: centimetres

#[test]
fn your_model_exercise_1_a_model_in_centimetres_stands_as_tall_as_one_in_metres() {
    let (scale_cm, length_cm, height_cm) = car_sized_box(0.01);
    let (scale_m, length_m, height_m) = car_sized_box(1.0);
    println!(
        "in centimetres: scaled ×{scale_cm:.6}, {length_cm:.3} m long, {height_cm:.3} m high; \
         in metres: ×{scale_m:.4}, {length_m:.3} m long, {height_m:.3} m high"
    );
    // Worked by hand: the diagonal is √(450² + 150² + 180²) = 507.35 cm.
    assert!((scale_cm - 0.009855).abs() < 1e-6 && (scale_m - 0.9855).abs() < 1e-4);
    for (length, height) in [(length_cm, height_cm), (length_m, height_m)] {
        assert!((length - 4.435).abs() < 0.001 && (height - 1.478).abs() < 0.001);
    }
}

// Lesson 6: normal maps, tangent space and the TBN matrix.

// ANCHOR: wall_frame
/// Normal maps, exercise 1: a triangle of a wall facing +z, corners at
/// (0, 0, 0), (2, 0, 0) and (0, 1, 0) with texture coordinates (0, 1),
/// (±0.5, 1) and (0, 0.75), mirrored in u when `mirrored`: T and B of the
/// triangle, and the handedness w its corners get.
fn wall_frame(mirrored: bool) -> (Vec3, Vec3, f32) {
    let corners = [Vec3::ZERO, Vec3::new(2.0, 0.0, 0.0), Vec3::new(0.0, 1.0, 0.0)];
    let u = if mirrored { -0.5 } else { 0.5 };
    let uvs = [Vec2::new(0.0, 1.0), Vec2::new(u, 1.0), Vec2::new(0.0, 0.75)];
    let (t, b) = triangle_tangents(corners, uvs).unwrap();
    let w = vertex_tangents(&corners, &[Vec3::Z; 3], &uvs, &[0, 1, 2])[0].w;
    (t, b, w)
}
// ANCHOR_END: wall_frame

#[test]
fn normal_maps_exercise_1_a_mirrored_texture_turns_the_tangent_and_its_handedness() {
    let (t, b, w) = wall_frame(false);
    let (t_mirrored, b_mirrored, w_mirrored) = wall_frame(true);
    println!("T {t}, B {b}, w {w}; mirrored: T {t_mirrored}, B {b_mirrored}, w {w_mirrored}");
    // Worked by hand from T = (Δv₂ e₁ − Δv₁ e₂) / d and B = (Δu₁ e₂ − Δu₂ e₁) / d.
    assert!(t.abs_diff_eq(Vec3::new(4.0, 0.0, 0.0), 1e-5) && b.abs_diff_eq(Vec3::new(0.0, -4.0, 0.0), 1e-5));
    assert!(t_mirrored.abs_diff_eq(Vec3::new(-4.0, 0.0, 0.0), 1e-5) && b_mirrored.abs_diff_eq(b, 1e-5));
    assert_eq!((w, w_mirrored), (1.0, -1.0));
    // Up the picture, w (N × T), is up the wall either way.
    for (t, w) in [(t, w), (t_mirrored, w_mirrored)] {
        assert!((Vec3::Z.cross(t.normalize()) * w).abs_diff_eq(Vec3::Y, 1e-6));
    }
}

// Lesson 7: flat, Gouraud and Phong, textured.

// ANCHOR: lamp_pool
/// Flat, Gouraud and Phong, exercise 1: how much of `lamp`'s light reaches
/// the floor at `point`, per unit of its colour: chapter 08's falloff times
/// cos θ, the floor's normal being +y. What lighting per fragment gives.
fn lamp_on_floor(lamp: &Light, point: Vec3) -> f32 {
    let cos = (lamp.position - point).normalize().y.max(0.0);
    lamp.reaching(point).x / lamp.colour.x * cos
}

/// What lighting per vertex gives at `point` on the stage's floor
/// (`common`'s plane of 8 × 8 quads, scaled to 40 m): the light at the
/// corners of the triangle under it, blended by its barycentric weights.
fn lamp_on_floor_per_vertex(lamp: &Light, point: Vec3) -> f32 {
    let floor = primitives::plane(8);
    let corner = |i: u32| Vec3::from(floor.vertices[i as usize].position) * Vec3::new(40.0, 1.0, 40.0);
    // Twice the signed area of (p, q, r) seen from above.
    let area = |p: Vec3, q: Vec3, r: Vec3| (q.x - p.x) * (r.z - p.z) - (r.x - p.x) * (q.z - p.z);
    floor
        .indices
        .chunks_exact(3)
        .find_map(|t| {
            let [a, b, c] = [corner(t[0]), corner(t[1]), corner(t[2])];
            let whole = area(a, b, c);
            let weights = [area(point, b, c), area(a, point, c), area(a, b, point)].map(|w| w / whole);
            weights.iter().all(|w| *w >= 0.0).then(|| {
                weights[0] * lamp_on_floor(lamp, a)
                    + weights[1] * lamp_on_floor(lamp, b)
                    + weights[2] * lamp_on_floor(lamp, c)
            })
        })
        .expect("the point is on the floor")
}
// ANCHOR_END: lamp_pool

#[test]
fn shading_exercise_1_per_vertex_the_lamps_pool_loses_half_its_peak() {
    let warm = stage_lights()[0];
    let under = Vec3::new(warm.position.x, 0.0, warm.position.z);
    let (per_fragment, per_vertex) = (lamp_on_floor(&warm, under), lamp_on_floor_per_vertex(&warm, under));
    let nearest_vertex = lamp_on_floor(&warm, Vec3::new(-5.0, 0.0, 0.0));
    println!(
        "under the lamp: {per_fragment:.4} per fragment, {per_vertex:.4} per vertex; \
         at the nearest vertex, (−5, 0, 0): {nearest_vertex:.4}"
    );
    // Worked by hand: 3 m straight down; the corners 3.39, 5.61 and 4.64 m
    // away, weighted 0.6, 0.1 and 0.3.
    assert!((per_fragment - 0.0996).abs() < 0.0001 && (per_vertex - 0.0522).abs() < 0.0001);
    assert!((nearest_vertex - 0.0703).abs() < 0.0001);
}

// Lesson 8 (advanced): green up, tangent space and face tangents.

// ANCHOR: green
/// Tangent frames, exercise 1: a normal map made the other way (DirectX's, green pointing
/// down the picture): the project's map with its green flipped, texel by texel.
fn flip_green(map: &RgbaImage) -> RgbaImage {
    let mut flipped = map.clone();
    flipped.pixels_mut().for_each(|p| p[1] = 255 - p[1]);
    flipped
}

/// Lambert's light on every texel of `map` (tangent space: x along the
/// picture, y up it, z out) from direction `light`, reading green as
/// `surface.wgsl` does, flipped if the overlay's checkbox is on.
fn lit(map: &RgbaImage, light: Vec3, checkbox: bool) -> Vec<f32> {
    map.pixels()
        .map(|t| {
            let mut n = direction(t);
            if checkbox {
                n.y = -n.y;
            }
            n.normalize().dot(light.normalize()).max(0.0)
        })
        .collect()
}
// ANCHOR_END: green

#[test]
fn tangent_frames_exercise_1_a_directx_map_is_lit_from_below_until_the_checkbox_flips_it() {
    let brick = picture("textures/brick/normal.png");
    let directx = flip_green(&brick);
    let from_above = Vec3::new(0.0, 1.0, 1.0);
    let from_below = Vec3::new(0.0, -1.0, 1.0);
    // Read as the project's maps are, the DirectX map is the brick lit from below…
    let wrong = lit(&directx, from_above, false);
    let differs = |a: &[f32], b: &[f32]| a.iter().zip(b).map(|(a, b)| (a - b).abs()).fold(0.0, f32::max);
    assert!(differs(&wrong, &lit(&brick, from_below, false)) < 1e-6);
    // …and with the checkbox, the brick lit from above (to the last bits of rounding).
    let right = lit(&brick, from_above, false);
    assert!(differs(&lit(&directx, from_above, true), &right) < 1e-6);
    // The bricks' upper edges (texels tilted up the picture) go dark.
    let tilts: Vec<f32> = brick.pixels().map(|t| direction(t).y).collect();
    let upper: Vec<usize> = (0..tilts.len()).filter(|&i| tilts[i] > 0.3).collect();
    let mean = |values: &[f32]| upper.iter().map(|&i| values[i]).sum::<f32>() / upper.len() as f32;
    println!("the upper edges' light: {:.2} read right, {:.2} read the wrong way up", mean(&right), mean(&wrong));
    assert!((mean(&right) - UPPER_EDGES_RIGHT).abs() < 0.02 && (mean(&wrong) - UPPER_EDGES_WRONG).abs() < 0.02);
}

/// The normal-maps lesson: the share of the brick's normal map that is flat,
/// within `FLAT_WITHIN` of (128, 128, 255) in every channel, per cent.
const FLAT_BRICK_PERCENT: f32 = 41.0;
const FLAT_WITHIN: u8 = 4;

#[test]
fn the_brick_normal_maps_flat_texels_are_the_share_the_lesson_says() {
    let brick = picture("textures/brick/normal.png");
    let flat = brick
        .pixels()
        .filter(|t| t[0].abs_diff(128) <= FLAT_WITHIN && t[1].abs_diff(128) <= FLAT_WITHIN && t[2] >= 255 - FLAT_WITHIN)
        .count();
    let percent = 100.0 * flat as f32 / (brick.width() * brick.height()) as f32;
    println!("{flat} flat texels: {percent:.2} %");
    assert!((percent - FLAT_BRICK_PERCENT).abs() < 0.5, "{percent} % of the brick's texels are flat");
    // And every one of them reads back as a direction within 3° of +z.
    for t in brick.pixels().filter(|t| t[0].abs_diff(128) <= FLAT_WITHIN && t[1].abs_diff(128) <= FLAT_WITHIN) {
        if t[2] >= 255 - FLAT_WITHIN {
            assert!(direction(t).normalize().z > 3f32.to_radians().cos(), "{t:?}");
        }
    }
}

/// Lambert's light on the brick's upper edges, from 45° above: read right, and the wrong way up.
const UPPER_EDGES_RIGHT: f32 = 0.95;
const UPPER_EDGES_WRONG: f32 = 0.0;

// ANCHOR: toksvig
/// Tangent frames, exercise 2: mipmap.wgsl keeps the length of the averaged normal in
/// alpha. It reads the four texels itself, and weights each direction by
/// the length stored with it, so that every level's length is that of the
/// average of all the base texels under it.
const KEEP_LENGTH: (&str, &str) = (
    "    let average = textureSampleLevel(above, bilinear, in.uv, 0.0).xyz * 2.0 - 1.0;
    let n = normalize(select(vec3<f32>(0.0, 0.0, 1.0), average, length(average) > 1e-4));
    return vec4<f32>(n * 0.5 + 0.5, 1.0);",
    "    let corner = vec2<i32>(in.clip_position.xy) * 2;
    var sum = vec3<f32>(0.0);
    for (var i = 0; i < 4; i++) {
        let texel = textureLoad(above, corner + vec2<i32>(i % 2, i / 2), 0);
        sum += normalize(texel.xyz * 2.0 - 1.0) * texel.a;
    }
    let average = sum / 4.0;
    let n = normalize(select(vec3<f32>(0.0, 0.0, 1.0), average, length(average) > 1e-4));
    return vec4<f32>(n * 0.5 + 0.5, length(average));",
);

/// …and textured.wgsl lowers the shininess by Toksvig's factor,
/// |N̄| / (|N̄| + s (1 − |N̄|)): the shorter the average, the wider the highlight.
const TOKSVIG: [(&str, &str); 4] = [
    (
        "    var n = frame3.n;\n    if material.flags.x == 1u {",
        "    var n = frame3.n;\n    var shininess = material.shininess;\n    if material.flags.x == 1u {",
    ),
    (
        "fn shade(in: Varyings, n: vec3<f32>, albedo_texel: vec4<f32>) -> vec4<f32> {",
        "fn shade(in: Varyings, n: vec3<f32>, albedo_texel: vec4<f32>) -> vec4<f32> {
    return shade_with(in, n, albedo_texel, material.shininess);
}

fn toksvig(average_length: f32, shininess: f32) -> f32 {
    return average_length / (average_length + shininess * (1.0 - average_length)) * shininess;
}

fn shade_with(in: Varyings, n: vec3<f32>, albedo_texel: vec4<f32>, shininess: f32) -> vec4<f32> {",
    ),
    (
        "Surface(albedo, material.specular, material.shininess, physical.x, physical.y)",
        "Surface(albedo, material.specular, shininess, physical.x, physical.y)",
    ),
    (
        "        let texel = textureSample(normal_map, surface_sampler, in.uv).xyz;
        n = mapped_normal(frame3, texel, options.flip_green == 1u);
    }
    return shade(in, n, textureSample(albedo_map, surface_sampler, in.uv));",
        "        let texel = textureSample(normal_map, surface_sampler, in.uv);
        n = mapped_normal(frame3, texel.xyz, options.flip_green == 1u);
        shininess = toksvig(texel.a, shininess);
    }
    return shade_with(in, n, textureSample(albedo_map, surface_sampler, in.uv), shininess);",
    ),
];

/// The mean length of the averaged normal at each mip level of a normal
/// map, each level's texels the average of the base texels under them.
fn averaged_lengths(path: &str) -> Vec<f32> {
    let image = picture(path);
    let mut level: Vec<Vec3> = image.pixels().map(|t| direction(t).normalize()).collect();
    let mut size = image.width() as usize;
    let mut lengths = Vec::new();
    while size >= 1 {
        lengths.push(level.iter().map(|v| v.length()).sum::<f32>() / level.len() as f32);
        if size == 1 {
            break;
        }
        let half = size / 2;
        level = (0..half * half)
            .map(|i| {
                let (x, y) = (i % half * 2, i / half * 2);
                (level[y * size + x]
                    + level[y * size + x + 1]
                    + level[(y + 1) * size + x]
                    + level[(y + 1) * size + x + 1])
                    / 4.0
            })
            .collect();
        size = half;
    }
    lengths
}

fn toksvig_shininess(length: f32, shininess: f32) -> f32 {
    length / (length + shininess * (1.0 - length)) * shininess
}
// ANCHOR_END: toksvig

#[test]
fn tangent_frames_exercise_2_toksvig_widens_the_metal_highlight_from_afar() {
    compiles_with(
        shader!("textures/mipmap.wgsl", imports: ["common/fullscreen.wgsl"]),
        "textures/mipmap.wgsl",
        &[KEEP_LENGTH],
    );
    compiles_with(
        shader!("textures/textured.wgsl", imports: ["lighting/brdf.wgsl", "lighting/sky_light.wgsl", "lighting/lights.wgsl", "textures/surface.wgsl"]),
        "textures/textured.wgsl",
        &TOKSVIG,
    );
    let lengths = averaged_lengths("textures/metal/normal.png");
    let expected = [1.000, 0.989, 0.978, 0.957, 0.949, 0.946, 0.944, 0.943, 0.943];
    assert!(lengths.iter().zip(expected).all(|(l, e)| (l - e).abs() < 0.001), "{lengths:?}");
    let shininess: Vec<f32> = lengths.iter().map(|l| toksvig_shininess(*l, 64.0)).collect();
    println!("metal normal map, mean |N̄| by level: {lengths:.3?}; Toksvig's shininess from 64: {shininess:.1?}");
    // The torus: 1.6 m across, the metal twice round it (256 texels per
    // 2.5 m of its outer side): from the whole-stage camera, 11 m away, and
    // from 40 m, the level a pixel reads.
    let level = |distance: f32| (256.0 / 2.5 * pixel_metres(distance)).log2().max(0.0);
    println!("the torus reads level {:.1} from 11 m and {:.1} from 40 m", level(11.0), level(40.0));
    let at = |distance: f32| shininess[level(distance).round() as usize];
    assert!((at(11.0) - 37.9).abs() < 0.1 && (at(40.0) - TOKSVIG_AT_40_M).abs() < 0.1, "{}", at(40.0));
}

/// Toksvig's shininess for the metal (64) at the level the torus reads from 40 m.
const TOKSVIG_AT_40_M: f32 = 16.6;
