//! Worked solutions to the exercises of book page 03, compiled and checked
//! with the chapter's other tests: the page includes them by anchor, and
//! each test asserts the figure its solution states.

use std::sync::{Arc, OnceLock};

use common::glam::Vec3;
use common::headless::{Offscreen, read_texture};
use common::wgpu::util::DeviceExt as _;
use common::{Gpu, PassTimer, ShaderFile, Target, image, shader, wgpu};
use terrain::chunks::{CHUNK_VERTICES, coarse_indices};
use terrain::culling::Frustum;
use terrain::heightfield::{CHUNK_QUADS, HeightField, TerrainSettings};
use terrain::noise::{Fbm, perlin3};
use terrain::{Detail, KEEP_ALL, SKY, Sun, TerrainData, TerrainMesh, TerrainRenderer, start_camera};

/// One device for these tests, so that the default terrain (4097² samples,
/// two seconds to make) is made once, whichever test asks first.
fn default_terrain() -> (&'static Gpu, Arc<TerrainData>) {
    static GPU: OnceLock<Gpu> = OnceLock::new();
    let gpu = GPU.get_or_init(|| Gpu::headless(terrain::gpu_needs()).expect("an adapter (lavapipe will do)"));
    (gpu, TerrainData::get(gpu, TerrainSettings::default()))
}

/// A field of 8 × 8 chunks (513² samples) without the cliff, with `fbm`.
fn patch(fbm: Fbm) -> TerrainSettings {
    TerrainSettings { chunks_per_side: 8, cliff_height: 0.0, fbm, ..Default::default() }
}

// ANCHOR: steepness
/// Exercise 1: the share of a field's samples steep enough for bare rock
/// (a slope over 35°, where `ground_colour` starts mixing it in), and the
/// mean slope in degrees.
fn steepness(field: &HeightField) -> (f32, f32) {
    let (mut rock, mut sum) = (0, 0.0);
    for z in 0..i64::from(field.size) {
        for x in 0..i64::from(field.size) {
            let slope = field.normal(x, z).y.acos().to_degrees();
            rock += usize::from(slope > 35.0);
            sum += slope;
        }
    }
    let samples = field.heights.len() as f32;
    (rock as f32 / samples, sum / samples)
}
// ANCHOR_END: steepness

#[test]
fn exercise_1_persistence_07_is_mountains_and_03_is_dunes() {
    let fbm = TerrainSettings::default().fbm;
    let measure = |persistence| steepness(&HeightField::generate(patch(Fbm { persistence, ..fbm })));
    let [(rough_rock, rough_slope), (default_rock, default_slope), (smooth_rock, smooth_slope)] =
        [0.7, 0.5, 0.3].map(measure);
    eprintln!(
        "persistence 0.7: {:.1} % rock, mean slope {rough_slope:.1}°; 0.5: {:.1} %, {default_slope:.1}°; \
         0.3: {:.2} %, {smooth_slope:.1}°",
        rough_rock * 100.0,
        default_rock * 100.0,
        smooth_rock * 100.0
    );
    // 0.7: rough ground, a sixth of it bare rock, slopes of 24° on average;
    // 0.3: smooth swells of 8°, no rock at all. (The default 0.5: 10°.)
    assert!((rough_rock - 0.174).abs() < 0.005 && (rough_slope - 24.4).abs() < 0.2);
    assert!(smooth_rock < 0.0005 && (smooth_slope - 7.7).abs() < 0.2);
    assert!(default_rock < 0.0005 && (default_slope - 10.4).abs() < 0.2);
}

// ANCHOR: ridged
/// Exercise 2: ridged noise. Each octave is 1 − |noise|: where the noise
/// crosses zero, |noise| has a crease, and 1 − |noise| a sharp crest.
/// Summed and normalised as `Fbm::sample` sums plain noise.
fn ridged(fbm: &Fbm, x: f64, y: f64, z: f64) -> f64 {
    let (mut sum, mut total, mut amplitude, mut frequency) = (0.0, 0.0, 1.0, 1.0);
    for _ in 0..fbm.octaves {
        sum += amplitude * (1.0 - perlin3(x * frequency, y * frequency, z).abs());
        total += amplitude;
        amplitude *= fbm.persistence;
        frequency *= fbm.lacunarity;
    }
    sum / total
}

/// A height field of ridged noise, sampled where `TerrainSettings::height_at`
/// samples fBm (same scale, slice and height; no cliff), and moved from
/// 0‥1 to −1‥1 like fBm, so the colours by height still fit.
fn ridged_field(settings: TerrainSettings) -> HeightField {
    let scale = f64::from(settings.spacing) / f64::from(settings.feature_size);
    let slice = f64::from(settings.seed) * 7.31 + 0.5;
    let size = settings.samples();
    let heights = (0..size * size)
        .map(|i| {
            let (x, z) = (f64::from(i % size) * scale, f64::from(i / size) * scale);
            (2.0 * ridged(&settings.fbm, x, z, slice) - 1.0) as f32 * settings.height
        })
        .collect();
    HeightField { settings, size, heights }
}
// ANCHOR_END: ridged

// ANCHOR: sharpest_crest
/// Exercise 2: how sharp the sharpest crest is. Along every row, the
/// slope up to a sample and the slope down from it, as angles: their
/// difference is how much the ground bends there, within one metre.
fn sharpest_crest(field: &HeightField) -> f32 {
    let spacing = field.settings.spacing;
    let mut sharpest = 0.0f32;
    for z in 0..i64::from(field.size) {
        for x in 1..i64::from(field.size) - 1 {
            let up = ((field.height(x, z) - field.height(x - 1, z)) / spacing).atan();
            let down = ((field.height(x + 1, z) - field.height(x, z)) / spacing).atan();
            sharpest = sharpest.max((up - down).to_degrees());
        }
    }
    sharpest
}
// ANCHOR_END: sharpest_crest

#[test]
fn exercise_2_ridged_noise_has_crests_sharper_than_fbm_ever_bends() {
    let settings = patch(TerrainSettings::default().fbm);
    let (smooth, ridges) = (sharpest_crest(&HeightField::generate(settings)), sharpest_crest(&ridged_field(settings)));
    eprintln!("the sharpest bend in one metre: fBm {smooth:.1}°, ridged {ridges:.1}°");
    // fBm's fade curve makes every octave smooth: the ground bends by 3.8°
    // at most across a metre. Ridged noise folds by 57° at its crests.
    assert!((smooth - 3.8).abs() < 0.1 && (ridges - 57.5).abs() < 0.5, "fBm {smooth}°, ridged {ridges}°");
}

/// The terrain's picture from the start camera at 1280 × 720, with
/// `shader`, into a target of `format`; `draw` records the chunks and
/// returns how many it drew.
fn render(
    shader: &ShaderFile,
    format: wgpu::TextureFormat,
    draw: impl FnOnce(&mut wgpu::RenderPass<'_>, &TerrainRenderer, &terrain::Viewpoint) -> usize,
) -> (image::RgbaImage, usize) {
    let (gpu, data) = default_terrain();
    let target = Target { format, width: 1280, height: 720 };
    let renderer = TerrainRenderer::new(gpu, data);
    let layout = gpu.device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
        label: None,
        bind_group_layouts: &[Some(&renderer.bind_group_layout)],
        immediate_size: 0,
    });
    let pipeline = TerrainRenderer::pipeline(gpu, shader, &layout, format).unwrap();
    let camera = start_camera(renderer.field(), target.aspect());
    let mut viewpoint = renderer.viewpoint(&gpu.device);
    renderer.aim(&gpu.queue, &mut viewpoint, &camera, Detail::lod(target.height), Sun::AFTERNOON, KEEP_ALL);
    renderer.write_chunk_flags(&gpu.queue, &Frustum::from_view_projection(camera.view_projection()));
    let (offscreen, depth) = (Offscreen::new(&gpu.device, target), common::texture::depth_view(&gpu.device, 1280, 720));
    let mut encoder = gpu.device.create_command_encoder(&Default::default());
    let drawn = {
        let mut pass =
            common::pipeline::scene_pass(&mut encoder, &PassTimer::off(), "exercise", &offscreen.view, SKY, &depth);
        pass.set_pipeline(&pipeline);
        renderer.bind(&mut pass, &viewpoint);
        draw(&mut pass, &renderer, &viewpoint)
    };
    gpu.queue.submit([encoder.finish()]);
    (read_texture(gpu, &offscreen.texture).unwrap(), drawn)
}

/// `terrain.wgsl` with `edit` in place of `fs_main`'s default branch.
fn edited_terrain_shader(edit: &str) -> ShaderFile {
    let original = shader!("terrain/terrain.wgsl");
    assert!(original.embedded.contains(DEFAULT_BRANCH), "terrain.wgsl changed: update DEFAULT_BRANCH");
    let edited = original.embedded.replacen(DEFAULT_BRANCH, edit, 1);
    ShaderFile { embedded: Box::leak(edited.into_boxed_str()), ..original }
}

/// The default branch of `fs_main`: what the exercise replaces.
const DEFAULT_BRANCH: &str = "        default: {
            return vec4<f32>(shaded, 1.0);
        }";

/// Exercise 3: `fs_main`'s default branch, coloured as the `chunks` view
/// colours. (`render` must write the flags in every view for this:
/// `self.terrain.write_chunk_flags(&gpu.queue, &frustum)`.)
const CHUNK_COLOURS: &str = "
// ANCHOR: chunk_colours
        default: {
            var colour = vec3<f32>(0.06);
            if chunk_drawn[in.chunk] == 1u {
                colour = chunk_colour(in.chunk);
            }
            return vec4<f32>(lit(colour, n), 1.0);
        }
// ANCHOR_END: chunk_colours
";

/// To count the chunks, the test writes each chunk's number instead of its
/// colour, exactly (into a target without sRGB encoding): red the number's
/// low byte, green its high byte, blue 1 for a chunk that `chunk_drawn`
/// says was kept and 0.6 for one it says was culled.
const CHUNK_NUMBERS: &str = "        default: {
            let kept = select(0.6, 1.0, chunk_drawn[in.chunk] == 1u);
            return vec4<f32>(f32(in.chunk % 256u) / 255.0, f32(in.chunk / 256u) / 255.0, kept, 1.0);
        }";

/// The default view with every pixel of ground showing its chunk's number
/// (`CHUNK_NUMBERS`), drawn the chapter's way, and how many chunks were drawn.
fn chunk_numbers() -> &'static (image::RgbaImage, usize) {
    static PICTURE: OnceLock<(image::RgbaImage, usize)> = OnceLock::new();
    PICTURE.get_or_init(|| {
        render(&edited_terrain_shader(CHUNK_NUMBERS), wgpu::TextureFormat::Rgba8Unorm, |pass, terrain, viewpoint| {
            terrain.draw(pass, viewpoint)
        })
    })
}

/// The chunk a pixel of `CHUNK_NUMBERS` shows.
fn chunk_number(pixel: &image::Rgba<u8>) -> u32 {
    u32::from(pixel[0]) + 256 * u32::from(pixel[1])
}

/// The chunks a picture of `CHUNK_NUMBERS` shows, each once, and how many
/// of its pixels belong to a chunk marked as culled.
fn chunks_shown(picture: &image::RgbaImage) -> (std::collections::BTreeSet<u32>, usize) {
    let ground = picture.pixels().filter(|p| p[2] == 255 || p[2] == 153);
    let culled = picture.pixels().filter(|p| p[2] == 153).count();
    (ground.map(chunk_number).collect(), culled)
}

#[test]
fn exercise_3_no_chunk_on_screen_is_culled_and_only_82_of_the_1219_drawn_show() {
    // The edit itself is valid WGSL against the terrain module.
    let colours = edited_terrain_shader(CHUNK_COLOURS);
    common::shader::compose(colours.embedded, colours.path, &[]).unwrap();

    let (picture, drawn) = chunk_numbers();
    let (shown, culled_pixels) = chunks_shown(picture);
    eprintln!("{drawn} chunks drawn, {} of them show at least one pixel at 1280 × 720", shown.len());
    // A culled chunk is never drawn, so no pixel can show one.
    assert_eq!(culled_pixels, 0);
    // And of the 1,219 drawn, the cliff and the hills hide all but 82.
    assert_eq!(*drawn, 1219);
    assert!(shown.len().abs_diff(82) <= 2, "{} chunks shown", shown.len());
}

/// Chunks whose box is farther than this from the eye get the coarse list.
const LOD_DISTANCE: f32 = 500.0;

/// How far `eye` is from the nearest point of a chunk's box.
fn distance_to_box(eye: Vec3, bounds: &terrain::chunks::Aabb) -> f32 {
    eye.clamp(bounds.min, bounds.max).distance(eye)
}

// ANCHOR: lod
/// Exercise 4: the chunks `frustum` keeps, those within `LOD_DISTANCE` of
/// `eye` with the full index list, the rest with `coarse`, the list of
/// `coarse_indices(2)`: 32 × 32 quads over every second vertex. Returns
/// the triangles drawn.
fn draw_with_lod(
    pass: &mut wgpu::RenderPass<'_>,
    mesh: &TerrainMesh,
    coarse: &wgpu::Buffer,
    frustum: &Frustum,
    eye: Vec3,
) -> u32 {
    let coarse_count = (coarse.size() / 2) as u32;
    let kept = (0..mesh.bounds.len()).filter(|&c| frustum.intersects(&mesh.bounds[c]));
    let (near, far): (Vec<usize>, Vec<usize>) =
        kept.partition(|&c| distance_to_box(eye, &mesh.bounds[c]) <= LOD_DISTANCE);
    pass.set_vertex_buffer(0, mesh.vertex_buffer.slice(..));
    let mut triangles = 0;
    for (chunks, indices, count) in [(near, &mesh.index_buffer, mesh.index_count), (far, coarse, coarse_count)] {
        pass.set_index_buffer(indices.slice(..), wgpu::IndexFormat::Uint16);
        for chunk in chunks.into_iter().map(|c| c as u32) {
            pass.draw_indexed(0..count, (chunk * CHUNK_VERTICES) as i32, chunk..chunk + 1);
            triangles += count / 3;
        }
    }
    triangles
}
// ANCHOR_END: lod

// ANCHOR: cracks
/// Exercise 4: the gaps where a full chunk meets a coarse one. The coarse
/// chunk's edge runs straight from one even vertex to the next; the full
/// chunk's edge bends at the odd vertex between them. Returns the height
/// of every such crack along the borders between a full chunk and a coarse
/// one, both drawn.
fn cracks(field: &HeightField, mesh: &TerrainMesh, frustum: &Frustum, eye: Vec3) -> Vec<f32> {
    let n = mesh.chunks_per_side as i64;
    let drawn = |cx: i64, cz: i64| {
        (0..n).contains(&cx) && (0..n).contains(&cz) && frustum.intersects(&mesh.bounds[(cz * n + cx) as usize])
    };
    let coarse = |cx: i64, cz: i64| distance_to_box(eye, &mesh.bounds[(cz * n + cx) as usize]) > LOD_DISTANCE;
    let quads = i64::from(CHUNK_QUADS);
    let mut gaps = Vec::new();
    for cz in 0..n {
        for cx in 0..n {
            // The border with the chunk to the east (+x), then to the south (+z).
            for (dx, dz) in [(1, 0), (0, 1)] {
                let (ex, ez) = (cx + dx, cz + dz);
                if !drawn(cx, cz) || !drawn(ex, ez) || coarse(cx, cz) == coarse(ex, ez) {
                    continue;
                }
                // Grid point `k` along the shared edge.
                let point = |k: i64| if dx == 1 { (ex * quads, cz * quads + k) } else { (cx * quads + k, ez * quads) };
                for k in (1..quads).step_by(2) {
                    let [(x0, z0), (x1, z1), (x2, z2)] = [point(k - 1), point(k), point(k + 1)];
                    let straight = 0.5 * (field.height(x0, z0) + field.height(x2, z2));
                    gaps.push((field.height(x1, z1) - straight).abs());
                }
            }
        }
    }
    gaps
}
// ANCHOR_END: cracks

#[test]
fn exercise_4_coarse_chunks_beyond_500_m_save_triangles_and_crack_at_the_ring() {
    let (gpu, data) = default_terrain();
    let camera = start_camera(&data.field, 16.0 / 9.0);
    let frustum = Frustum::from_view_projection(camera.view_projection());
    let coarse = gpu.device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: Some("every second vertex"),
        contents: bytemuck::cast_slice(&coarse_indices(2)),
        usage: wgpu::BufferUsages::INDEX,
    });
    let (with_lod, triangles) =
        render(&edited_terrain_shader(CHUNK_NUMBERS), wgpu::TextureFormat::Rgba8Unorm, |pass, terrain, _| {
            draw_with_lod(pass, terrain.mesh(), &coarse, &frustum, camera.position) as usize
        });
    let (full, drawn) = chunk_numbers();
    let before = *drawn as u32 * CHUNK_QUADS * CHUNK_QUADS * 2;
    eprintln!("triangles: {before} without, {triangles} with the coarse list beyond {LOD_DISTANCE} m");
    // 68 chunks within 500 m keep their 8,192 triangles; 1,151 beyond have
    // 2,048: 2.9 million triangles instead of 10.0, 71 % fewer.
    assert_eq!((before, triangles), (9_986_048, 68 * 8192 + 1151 * 2048));

    let gaps = cracks(&data.field, &data.mesh, &frustum, camera.position);
    let widest = gaps.iter().copied().fold(0.0, f32::max);
    let mean = gaps.iter().sum::<f32>() / gaps.len() as f32;
    // Pixels where the full picture shows ground and the other sky: holes.
    let sky = |p: &image::Rgba<u8>| p[2] != 255;
    let holes = full.pixels().zip(with_lod.pixels()).filter(|(a, b)| !sky(a) && sky(b)).count();
    let changed: Vec<_> = full.pixels().zip(with_lod.pixels()).filter(|(a, b)| a != b).collect();
    eprintln!(
        "{} odd vertices on full–coarse borders; gaps up to {widest:.2} m, {mean:.3} m on average; \
         {holes} pixels turn to sky, {} change",
        gaps.len(),
        changed.len()
    );
    // 17 borders of 32 odd vertices; the widest gap 16 cm, a fifth of the
    // 0.8 m a pixel spans 500 m away at 1280 × 720.
    assert_eq!(gaps.len(), 17 * 32);
    assert!((widest - 0.16).abs() < 0.01 && (mean - 0.009).abs() < 0.001, "{widest} {mean}");
    // The picture changes in a few dozen pixels, 6 of them now sky, and
    // all where the full picture shows a coarse chunk: the outlines of
    // the distant hills, lower in the coarse mesh. No crack shows.
    let coarse = |p: &image::Rgba<u8>| {
        distance_to_box(camera.position, &data.mesh.bounds[chunk_number(p) as usize]) > LOD_DISTANCE
    };
    assert!(changed.iter().all(|(a, _)| sky(a) || coarse(a)));
    assert!(changed.len().abs_diff(31) <= 10 && holes.abs_diff(6) <= 4, "{} changed, {holes} holes", changed.len());
}
