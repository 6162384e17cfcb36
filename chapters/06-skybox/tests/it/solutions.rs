//! Worked solutions to the exercises of chapter 06's lessons, compiled and
//! checked with the chapter's other tests: the pages include them by
//! anchor, and each test asserts the figure its solution states. A test's
//! name says which lesson's exercise it checks: `sky_box_…` for "A box at
//! infinity" (sky-box.md), `time_of_day_…` for "A sky that turns, a sun
//! that lights" (time-of-day.md).

use std::f32::consts::TAU;

use common::glam::{Mat4, Quat, Vec3};
use common::headless::{OFFSCREEN_FORMAT, Offscreen, read_texture};
use common::texture::{ColorSpace, cubemap_from_images, decode_faces};
use common::{Camera, Gpu, GpuNeeds, PassTimer, ShaderFile, Target, image, shader, wgpu};
use skybox::{DAY, NIGHT, Sky, SkyboxChapter, celestial_turn, day_blend, sun_at};
use terrain::noise::perlin3;

/// Exercise 1's day length in the overlay, seconds, and when its midnight
/// comes, seconds in: the page's figures.
const EXERCISE_DAY_SECONDS: f32 = 20.0;
const MIDNIGHT_SECONDS_IN: f32 = 12.0;

#[test]
fn time_of_day_exercise_1_at_midnight_the_sun_is_73_degrees_below_the_southern_horizon() {
    // A 20 s day, starting mid-morning (phase 0.4): midnight comes 12 s in.
    let gpu = crate::plain_gpu();
    let target = Target { format: OFFSCREEN_FORMAT, width: 64, height: 36, samples: 1 };
    let mut chapter: SkyboxChapter = common::chapter::create(gpu, target, &Default::default()).unwrap();
    chapter.day_seconds = EXERCISE_DAY_SECONDS;
    let midnight_phase = chapter.phase_at(MIDNIGHT_SECONDS_IN);
    assert!(midnight_phase.abs() < 1e-6 || (1.0 - midnight_phase).abs() < 1e-6, "{midnight_phase}");
    // And not before: half a second earlier it is still the day before.
    assert!(chapter.phase_at(MIDNIGHT_SECONDS_IN - 0.5) > 0.9);
    // The sun turns about the north–south axis, from a sunrise 16.7° south
    // of east. At midnight it is half a turn from noon: 73.3° below the
    // horizon, towards the south (+z), where noon has it 73.3° above.
    let midnight = sun_at(0.0).direction;
    let elevation = midnight.y.asin().to_degrees();
    eprintln!("the sun at midnight: {midnight}, {elevation:.1}° above the horizon");
    assert!(midnight.distance(Vec3::new(0.0, -0.958, 0.287)) < 1e-3);
    assert!((elevation + 73.3).abs() < 0.05);
    // It is the day's lowest point, and noon's sun mirrored in the horizon.
    assert!((0..100).all(|i| sun_at(i as f32 / 100.0).direction.y >= midnight.y - 1e-6));
    let noon = sun_at(0.5).direction;
    assert!(Vec3::new(noon.x, -noon.y, noon.z).distance(midnight) < 1e-5);
}

/// The sky alone (no plain), as `sky` draws it from `camera` at time of day `phase`.
fn render_sky(gpu: &Gpu, sky: &Sky, camera: &Camera, phase: f32, target: Target) -> image::RgbaImage {
    let viewpoint = sky.viewpoint(&gpu.device, 1);
    sky.aim(&gpu.queue, &viewpoint, camera, phase);
    let offscreen = Offscreen::new(&gpu.device, target);
    let depth = common::texture::depth_view(&gpu.device, target.width, target.height);
    let mut encoder = gpu.device.create_command_encoder(&Default::default());
    {
        let mut pass =
            common::pipeline::scene_pass(&mut encoder, &PassTimer::off(), "sky", &offscreen.view, terrain::SKY, &depth);
        sky.draw(&mut pass, &viewpoint);
    }
    gpu.queue.submit([encoder.finish()]);
    read_texture(gpu, &offscreen.texture).unwrap()
}

/// A device that reads its shaders from a copy of `shaders/` where
/// `sky.wgsl` has `edit` in place of `original`, and the sky as it is and
/// as edited, both built on it.
fn skies(name: &str, original: &str, edit: &str) -> (Gpu, Sky, Sky) {
    let gpu = Gpu::headless(GpuNeeds::default()).expect("an adapter (lavapipe will do)");
    let as_it_is = Sky::new(&gpu, OFFSCREEN_FORMAT, &[1]).unwrap();
    let root = common::shader::scratch_copy(name).unwrap();
    let file = root.join("skybox/sky.wgsl");
    let text = std::fs::read_to_string(&file).unwrap();
    assert!(text.contains(original), "sky.wgsl changed: update the exercise's edit");
    std::fs::write(&file, text.replacen(original, edit, 1)).unwrap();
    gpu.read_shaders_from(Some(root.clone()));
    let edited = Sky::new(&gpu, OFFSCREEN_FORMAT, &[1]).unwrap();
    std::fs::remove_dir_all(root).unwrap();
    (gpu, as_it_is, edited)
}

/// The last line of `fs_sky`, which the time of day's exercises 2 and 3 extend.
const SKY_RETURN: &str = "    return vec4<f32>(mix(night, day, sky.sun.w), 1.0);";

/// Time of day, exercise 2: Phobos, in `fs_sky`. `world_to_stars` turns a
/// direction back by the sky's turn; applied twice to a fixed direction, it
/// carries that direction the other way round, twice a day.
const PHOBOS: &str = "
// ANCHOR: phobos_wgsl
    // Phobos circles Mars faster than Mars turns: it rises in the west
    // and sets in the east, about twice a day. Turned back by the sky's
    // turn twice, from the western horizon at sunrise:
    let phobos = (sky.world_to_stars * (sky.world_to_stars * vec4<f32>(-1.0, 0.0, 0.0, 0.0))).xyz;
    // A grey disc 0.8° across (the real one is 0.2°: a pixel).
    let on_phobos = smoothstep(cos(radians(0.45)), cos(radians(0.35)), dot(direction, phobos));
    let colour = mix(mix(night, day, sky.sun.w), vec3<f32>(0.36, 0.33, 0.31), on_phobos);
    return vec4<f32>(colour, 1.0);
// ANCHOR_END: phobos_wgsl
";

// ANCHOR: phobos_path
/// Time of day, exercise 2: where the shader draws Phobos at time of day
/// `phase`: the western horizon turned back by the sky's turn twice.
fn phobos_at(phase: f32) -> Vec3 {
    let back = celestial_turn(phase).inverse();
    back * (back * Vec3::NEG_X)
}
// ANCHOR_END: phobos_path

#[test]
fn time_of_day_exercise_2_phobos_rises_in_the_west_twice_a_day() {
    // It rises in the west: on the western horizon at sunrise, climbing.
    assert!(phobos_at(0.25).distance(Vec3::NEG_X) < 1e-5);
    assert!(phobos_at(0.26).y > 0.0 && phobos_at(0.24).y < 0.0);
    // It rises again half a day later (the real Phobos: every 11 h 6 min
    // of a 24 h 40 min day, 0.45 of it), and crosses to the east meanwhile.
    let rises: Vec<f32> = (0..1000)
        .map(|i| i as f32 / 1000.0)
        .filter(|&p| phobos_at(p).y <= 0.0 && phobos_at(p + 0.001).y > 0.0)
        .collect();
    eprintln!("Phobos rises at phases {rises:?}");
    assert_eq!(rises.len(), 2);
    assert!(rises.iter().all(|&p| phobos_at(p).x < -0.99), "in the west");
    assert!(phobos_at(0.49).x > 0.99, "set in the east");

    // The shader draws it there: aim at where `phobos_at` says, at
    // mid-morning, and the disc, the pixels the edit changes, is in the
    // middle of the picture, about 6 pixels across (0.8° in a 60° view
    // 450 pixels tall).
    let (gpu, as_it_is, with_phobos) = skies("sky-phobos", SKY_RETURN, PHOBOS);
    let target = Target { format: OFFSCREEN_FORMAT, width: 800, height: 450, samples: 1 };
    let camera = Camera::looking_at(Vec3::ZERO, phobos_at(0.4), target.aspect());
    let (before, after) =
        (render_sky(&gpu, &as_it_is, &camera, 0.4, target), render_sky(&gpu, &with_phobos, &camera, 0.4, target));
    let disc: Vec<(u32, u32)> = before
        .enumerate_pixels()
        .zip(after.pixels())
        .filter(|((_, _, a), b)| a != b)
        .map(|((x, y, _), _)| (x, y))
        .collect();
    let (xs, ys): (Vec<u32>, Vec<u32>) = disc.iter().copied().unzip();
    let width = xs.iter().max().unwrap() - xs.iter().min().unwrap() + 1;
    let centre = (xs.iter().sum::<u32>() as f32 / xs.len() as f32, ys.iter().sum::<u32>() as f32 / ys.len() as f32);
    eprintln!("Phobos: {} pixels, {width} across, centred on {centre:?}", disc.len());
    assert!((centre.0 - 400.0).abs() < 1.0 && (centre.1 - 225.0).abs() < 1.0, "{centre:?}");
    assert!((5..=8).contains(&width) && disc.len().abs_diff(32) <= 4, "{} pixels, {width} across", disc.len());
}

/// Time of day, exercise 3: a glow along the night horizon, in `fs_sky`. It
/// is computed from `direction`, which is in the world's frame, not the
/// stars', so it stays level however the stars turn.
const NIGHT_GLOW: &str = "
// ANCHOR: glow_wgsl
    // Dust lit from below the horizon: brightest at it, gone 15° up.
    let glow = vec3<f32>(0.030, 0.016, 0.010) * (1.0 - smoothstep(0.0, 0.26, abs(direction.y)));
    return vec4<f32>(mix(night + glow, day, sky.sun.w), 1.0);
// ANCHOR_END: glow_wgsl
";

// ANCHOR: glow_fog
/// The glow at the horizon (direction.y = 0), linear RGB: `NIGHT_GLOW`'s.
const GLOW_AT_HORIZON: [f32; 3] = [0.030, 0.016, 0.010];

/// Time of day, exercise 3: the fog colour with the glow: the horizon the
/// fog fades to is brighter by the glow, as much as the night sky shows.
/// `render` passes it to `set_air` in place of `self.sky.fog_colour(self.phase)`.
fn fog_colour_with_glow(sky: &Sky, phase: f32) -> [f32; 3] {
    let (fog, night) = (sky.fog_colour(phase), 1.0 - day_blend(sun_at(phase)));
    [0, 1, 2].map(|c| fog[c] + GLOW_AT_HORIZON[c] * night)
}
// ANCHOR_END: glow_fog

/// The linear colour an sRGB-encoded pixel stands for.
fn linear(pixel: &image::Rgba<u8>) -> [f32; 3] {
    let decode = |byte: u8| {
        let c = f32::from(byte) / 255.0;
        if c <= 0.04045 { c / 12.92 } else { ((c + 0.055) / 1.055).powf(2.4) }
    };
    [decode(pixel[0]), decode(pixel[1]), decode(pixel[2])]
}

/// The mean linear colour of a picture's row `y`.
fn row_colour(picture: &image::RgbaImage, y: u32) -> [f32; 3] {
    let mut sum = [0.0; 3];
    for x in 0..picture.width() {
        let p = linear(picture.get_pixel(x, y));
        (0..3).for_each(|c| sum[c] += p[c] / picture.width() as f32);
    }
    sum
}

#[test]
fn time_of_day_exercise_3_the_night_horizon_glows_level_and_the_fog_glows_with_it() {
    let (gpu, as_it_is, glowing) = skies("sky-glow", SKY_RETURN, NIGHT_GLOW);
    let target = Target { format: OFFSCREEN_FORMAT, width: 320, height: 180, samples: 1 };
    // Looking level, west and east, at two times of the night: the horizon
    // is the picture's middle row, and row 30 looks 21° up.
    for (yaw, phase) in [(0.25 * TAU, 0.02), (0.75 * TAU, 0.9)] {
        let camera = Camera { yaw, pitch: 0.0, ..Camera::looking_at(Vec3::ZERO, Vec3::NEG_Z, target.aspect()) };
        let (plain, glowing_picture) =
            (render_sky(&gpu, &as_it_is, &camera, phase, target), render_sky(&gpu, &glowing, &camera, phase, target));
        let ([dark, dark_high], [glow, high]) =
            ([90, 30].map(|y| row_colour(&plain, y)), [90, 30].map(|y| row_colour(&glowing_picture, y)));
        let (fog_before, fog) = (as_it_is.fog_colour(phase), fog_colour_with_glow(&glowing, phase));
        eprintln!("night horizon {dark:?} → {glow:?}; the fog {fog_before:?} → {fog:?}");
        for c in 0..3 {
            // The horizon is brighter by the glow; 21° up, it is as it was.
            assert!((glow[c] - dark[c] - GLOW_AT_HORIZON[c]).abs() < 0.002, "channel {c}: {dark:?} → {glow:?}");
            assert!((high[c] - dark_high[c]).abs() < 0.0005, "channel {c}: {dark_high:?} → {high:?} 21° up");
            // The fog had the dark horizon's colour; it now has the glow's.
            assert!((fog_before[c] - dark[c]).abs() < 0.002 && (fog[c] - glow[c]).abs() < 0.002, "channel {c}");
        }
    }
}

// ANCHOR: texel_size
/// The direction through the point (u, v) of cube face `face` (WebGPU's
/// order: +x, −x, +y, −y, +z, −z; u and v from −1 to 1, v down): where the
/// sky box's exercise 1 measures texels, and where the time of day's
/// exercise 4 paints its clouds.
fn cube_direction(face: usize, u: f32, v: f32) -> Vec3 {
    match face {
        0 => Vec3::new(1.0, -v, -u),
        1 => Vec3::new(-1.0, -v, u),
        2 => Vec3::new(u, 1.0, v),
        3 => Vec3::new(u, -1.0, -v),
        4 => Vec3::new(u, -v, 1.0),
        _ => Vec3::new(-u, -v, -1.0),
    }
    .normalize()
}

/// The angle between `a` and `b`, in degrees (through the sine and the
/// cosine together: `acos` alone loses small angles in `f32`).
fn degrees_between(a: Vec3, b: Vec3) -> f32 {
    a.cross(b).length().atan2(a.dot(b)).to_degrees()
}

/// Sky box, exercise 1: the angle between the centres of two texels
/// (column, row) of cube face `face`, `size` texels a side.
fn texel_degrees(face: usize, size: u32, a: (u32, u32), b: (u32, u32)) -> f32 {
    let centre = |(x, y): (u32, u32)| [x, y].map(|t| 2.0 * (t as f32 + 0.5) / size as f32 - 1.0);
    let ([ua, va], [ub, vb]) = (centre(a), centre(b));
    degrees_between(cube_direction(face, ua, va), cube_direction(face, ub, vb))
}

/// Sky box, exercise 1: the angle between the directions through two
/// neighbouring pixels in the middle of a picture `height` pixels tall seen
/// by `camera`, turned back into directions as the sky shader does: through
/// the inverse of its projection times its turn alone.
fn pixel_degrees(camera: &Camera, height: u32) -> f32 {
    let turn_only = Mat4::look_to_rh(Vec3::ZERO, camera.forward(), Vec3::Y);
    let clip_to_world = (camera.projection() * turn_only).inverse();
    let through_row = |row: f32| clip_to_world.project_point3(Vec3::new(0.0, 1.0 - 2.0 * row / height as f32, 1.0));
    let middle = height as f32 / 2.0;
    degrees_between(through_row(middle - 0.5), through_row(middle + 0.5))
}
// ANCHOR_END: texel_size

#[test]
fn sky_box_exercise_1_a_texel_covers_five_pixels_in_the_middle_of_a_face_and_two_in_a_corner() {
    let size = decode_faces(&DAY).unwrap()[0].width();
    assert_eq!(size, 256);
    // Worked by hand: 2 atan(1/256) in the middle of a face, √2/3 of it in
    // a corner; a pixel in the middle of the picture, 2 tan(30°)/720 radians.
    let middle_by_hand = 2.0 * (1.0f32 / 256.0).atan().to_degrees();
    let corner_by_hand = middle_by_hand * 2f32.sqrt() / 3.0;
    let pixel_by_hand = (2.0 * 30f32.to_radians().tan() / 720.0).to_degrees();
    // Measured: neighbouring texel centres along a row of the −z face, in
    // its middle and in its corner; and the chapter's camera, 1280 × 720.
    let middle = texel_degrees(5, size, (127, 128), (128, 128));
    let corner = texel_degrees(5, size, (254, 255), (255, 255));
    let target = Target { format: OFFSCREEN_FORMAT, width: 64, height: 36, samples: 1 };
    let chapter: SkyboxChapter = common::chapter::create(crate::plain_gpu(), target, &Default::default()).unwrap();
    let camera = Camera { aspect: 1280.0 / 720.0, ..chapter.camera };
    let pixel = pixel_degrees(&camera, 720);
    let (middle_pixels, corner_pixels) = (middle / pixel, corner / pixel);
    eprintln!(
        "a texel is {middle:.4}° in the middle of a face, {corner:.4}° in a corner; a pixel {pixel:.4}°: \
         {middle_pixels:.2} and {corner_pixels:.2} pixels"
    );
    assert!((middle - middle_by_hand).abs() < 1e-4 && (middle - 0.448).abs() < 0.001, "{middle}");
    assert!((corner - corner_by_hand).abs() < 0.002 && (corner - 0.21).abs() < 0.005, "{corner}");
    assert!((pixel - pixel_by_hand).abs() < 1e-4 && (pixel - 0.092).abs() < 0.001, "{pixel}");
    assert!((middle_pixels - 4.9).abs() < 0.05 && (corner_pixels - 2.3).abs() < 0.05);
}

// ANCHOR: cloud_faces
/// Time of day, exercise 4: a cube map of clouds. Like the skies, every
/// texel is a function of its direction alone (here five octaves of 3D noise
/// there), so the faces meet without seams. Red is the cover: 0 clear, 1 cloud.
fn cloud_faces(size: u32) -> [image::RgbaImage; 6] {
    let cover = |d: Vec3| {
        let (mut sum, mut amplitude, mut frequency) = (0.0, 1.0, 2.5);
        for _ in 0..5 {
            let p = d.as_dvec3() * frequency;
            sum += amplitude * perlin3(p.x, p.y, p.z);
            (amplitude, frequency) = (amplitude * 0.55, frequency * 2.1);
        }
        ((sum as f32 - 0.05) / 0.3).clamp(0.0, 1.0)
    };
    std::array::from_fn(|face| {
        image::RgbaImage::from_fn(size, size, |x, y| {
            let [u, v] = [x, y].map(|t| 2.0 * (t as f32 + 0.5) / size as f32 - 1.0);
            let c = (cover(cube_direction(face, u, v)) * 255.0).round() as u8;
            image::Rgba([c, c, c, 255])
        })
    })
}

/// How many times the clouds turn about the vertical in a day (the sun: once).
const CLOUD_TURNS_PER_DAY: f32 = 3.0;
// ANCHOR_END: cloud_faces

/// `sky.wgsl`'s day lookup, through the dust drift, and its uniform's end.
const DAY_LOOKUP: &str =
    "    var day = textureSample(day_sky, sky_sampler, (sky.world_to_day * vec4<f32>(direction, 0.0)).xyz).rgb;";
const UNIFORM_END: &str = "    sun: vec4<f32>,\n};";
const SAMPLER: &str = "@group(0) @binding(3) var sky_sampler: sampler;";
const SUN_DISC: &str = "    day = mix(day, vec3<f32>(1.0, 0.96, 0.88), disc);";
// ANCHOR: clouds_wgsl
/// Time of day, exercise 4, in `sky.wgsl`: the end of the uniform `Sky`,
/// with the clouds' turn…
const CLOUDS_UNIFORM: &str = "    sun: vec4<f32>,
    // World directions into the cloud map: turning about the vertical.
    world_to_clouds: mat4x4<f32>,
};";
/// …their cube map, a fifth binding…
const CLOUDS_BINDING: &str = "@group(0) @binding(3) var sky_sampler: sampler;
@group(0) @binding(4) var clouds: texture_cube<f32>;";
/// …the day sky, without the dust drift…
const STILL_DAY: &str = "    var day = textureSample(day_sky, sky_sampler, direction).rgb;";
/// …and the clouds over it, after the sun's disc, so they cover the sun too.
const CLOUDS_OVER_THE_SUN: &str = "    day = mix(day, vec3<f32>(1.0, 0.96, 0.88), disc);
    let cover = textureSample(clouds, sky_sampler, (sky.world_to_clouds * vec4<f32>(direction, 0.0)).xyz).r;
    day = mix(day, vec3<f32>(0.86, 0.74, 0.62), 0.85 * cover);";
// ANCHOR_END: clouds_wgsl

/// `Sky` in the edited sky.wgsl: chapter 06's uniform and the clouds' turn.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct CloudySkyUniform {
    clip_to_world: [[f32; 4]; 4],
    world_to_day: [[f32; 4]; 4],
    world_to_stars: [[f32; 4]; 4],
    sun: [f32; 4],
    world_to_clouds: [[f32; 4]; 4],
}

/// A bind group entry for a cube map's view.
fn cube_view(binding: u32, texture: &common::texture::Texture) -> wgpu::BindGroupEntry<'_> {
    wgpu::BindGroupEntry { binding, resource: wgpu::BindingResource::TextureView(&texture.view) }
}

/// Chapter 06's sky with clouds, as the solution changes `Sky`: a fifth
/// binding for the cloud map, and the clouds' turn in the uniform.
struct CloudySky {
    pipeline: wgpu::RenderPipeline,
    group: wgpu::BindGroup,
    uniform: wgpu::Buffer,
}

impl CloudySky {
    fn new(gpu: &Gpu, format: wgpu::TextureFormat, cloud_faces: &[image::RgbaImage; 6]) -> Self {
        let device = &gpu.device;
        let cube = |faces: &[image::RgbaImage; 6], space| cubemap_from_images(device, &gpu.queue, faces, space, "sky");
        let day = cube(&decode_faces(&DAY).unwrap(), ColorSpace::Srgb);
        let night = cube(&decode_faces(&NIGHT).unwrap(), ColorSpace::Srgb);
        let clouds = cube(cloud_faces, ColorSpace::Linear);
        let cube_entry = |binding| wgpu::BindGroupLayoutEntry {
            binding,
            visibility: wgpu::ShaderStages::FRAGMENT,
            ty: wgpu::BindingType::Texture {
                sample_type: wgpu::TextureSampleType::Float { filterable: true },
                view_dimension: wgpu::TextureViewDimension::Cube,
                multisampled: false,
            },
            count: None,
        };
        let size = size_of::<CloudySkyUniform>();
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("cloudy sky"),
            entries: &[
                common::pipeline::uniform_entry(0, wgpu::ShaderStages::FRAGMENT, size),
                cube_entry(1),
                cube_entry(2),
                common::pipeline::sampler_entry(3),
                cube_entry(4),
            ],
        });
        let uniform = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("cloudy sky"),
            size: size as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("cloudy sky"),
            layout: &layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: uniform.as_entire_binding() },
                cube_view(1, &day),
                cube_view(2, &night),
                wgpu::BindGroupEntry { binding: 3, resource: wgpu::BindingResource::Sampler(&day.sampler) },
                cube_view(4, &clouds),
            ],
        });
        let mut text = shader!("skybox/sky.wgsl", imports: ["common/fullscreen.wgsl"]).embedded.to_string();
        let edits = [
            (UNIFORM_END, CLOUDS_UNIFORM),
            (SAMPLER, CLOUDS_BINDING),
            (DAY_LOOKUP, STILL_DAY),
            (SUN_DISC, CLOUDS_OVER_THE_SUN),
        ];
        for (from, to) in edits {
            assert!(text.contains(from), "sky.wgsl changed: update the exercise's edit");
            text = text.replacen(from, to, 1);
        }
        let file = ShaderFile {
            embedded: Box::leak(text.into_boxed_str()),
            ..shader!("skybox/sky.wgsl", imports: ["common/fullscreen.wgsl"])
        };
        let module = file.module(gpu).unwrap();
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("cloudy sky"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let pipeline = common::fullscreen::pipeline(
            device,
            "cloudy sky",
            &pipeline_layout,
            &module,
            "fs_sky",
            format.into(),
            None,
        );
        Self { pipeline, group, uniform }
    }

    // ANCHOR: clouds_aim
    /// Time of day, exercise 4: `Sky::aim` with the clouds: the day sky no
    /// longer drifts (`world_to_day` is the identity), and the clouds turn
    /// `CLOUD_TURNS_PER_DAY` times a day about the vertical.
    fn aim(&self, queue: &wgpu::Queue, camera: &Camera, phase: f32) {
        let turn_only = Mat4::look_to_rh(Vec3::ZERO, camera.forward(), Vec3::Y);
        let sun = sun_at(phase);
        let clouds = Quat::from_rotation_y(TAU * CLOUD_TURNS_PER_DAY * phase);
        let uniform = CloudySkyUniform {
            clip_to_world: (camera.projection() * turn_only).inverse().to_cols_array_2d(),
            world_to_day: Mat4::IDENTITY.to_cols_array_2d(),
            world_to_stars: Mat4::from_quat(celestial_turn(phase).inverse()).to_cols_array_2d(),
            sun: sun.direction.normalize().extend(day_blend(sun)).into(),
            world_to_clouds: Mat4::from_quat(clouds.inverse()).to_cols_array_2d(),
        };
        queue.write_buffer(&self.uniform, 0, bytemuck::bytes_of(&uniform));
    }
    // ANCHOR_END: clouds_aim

    fn render(&self, gpu: &Gpu, camera: &Camera, phase: f32, target: Target) -> image::RgbaImage {
        self.aim(&gpu.queue, camera, phase);
        let offscreen = Offscreen::new(&gpu.device, target);
        let mut encoder = gpu.device.create_command_encoder(&Default::default());
        {
            let mut pass = common::fullscreen::pass(&mut encoder, &PassTimer::off(), "sky", &offscreen.view, None);
            pass.set_pipeline(&self.pipeline);
            pass.set_bind_group(0, &self.group, &[]);
            pass.draw(0..3, 0..1);
        }
        gpu.queue.submit([encoder.finish()]);
        read_texture(gpu, &offscreen.texture).unwrap()
    }
}

/// Exercise 4's figures: the cloud map's mean cover, and the share of the
/// test's view where clouds show (a difference over 8 levels), fractions.
const CLOUD_COVER: f32 = 0.28;
const CLOUDS_SHOWN: f32 = 0.39;

#[test]
fn time_of_day_exercise_4_clouds_turn_three_times_a_day_over_a_still_sky() {
    let faces = cloud_faces(64);
    let texels = faces.iter().flat_map(|f| f.pixels());
    let cover = texels.map(|p| f32::from(p[0]) / 255.0).sum::<f32>() / (6 * 64 * 64) as f32;
    eprintln!("cloud cover {:.0} %", cover * 100.0);
    assert!((cover - CLOUD_COVER).abs() < 0.01, "{cover}");

    // The clouds alone: the picture with them, against the same sky with
    // a cloud map that is clear everywhere.
    let gpu = Gpu::headless(GpuNeeds::default()).expect("an adapter (lavapipe will do)");
    let clear = std::array::from_fn(|_| image::RgbaImage::from_pixel(64, 64, image::Rgba([0, 0, 0, 255])));
    let (cloudy, cloudless) =
        (CloudySky::new(&gpu, OFFSCREEN_FORMAT, &faces), CloudySky::new(&gpu, OFFSCREEN_FORMAT, &clear));
    let target = Target { format: OFFSCREEN_FORMAT, width: 200, height: 112, samples: 1 };
    let clouds_seen = |camera: &Camera, phase: f32| -> Vec<i16> {
        let (a, b) = (cloudy.render(&gpu, camera, phase, target), cloudless.render(&gpu, camera, phase, target));
        a.pixels().zip(b.pixels()).map(|(p, q)| i16::from(p[1]) - i16::from(q[1])).collect()
    };
    let mean_difference =
        |a: &[i16], b: &[i16]| a.iter().zip(b).map(|(x, y)| f32::from((x - y).abs())).sum::<f32>() / a.len() as f32;
    // Looking north, 20° up, at mid-morning; then a Martian hour later
    // (1/24 of a day), looking the same way, and looking 45° further round
    // with the clouds (three turns a day are 45° an hour; the sun's 15°).
    let morning =
        Camera { yaw: 0.0, pitch: 20f32.to_radians(), ..Camera::looking_at(Vec3::ZERO, Vec3::NEG_Z, target.aspect()) };
    let hour = 1.0 / 24.0;
    let followed = Camera { yaw: morning.yaw + TAU * CLOUD_TURNS_PER_DAY * hour, ..morning };
    let (now, later_same_way, later_followed) =
        (clouds_seen(&morning, 0.38), clouds_seen(&morning, 0.38 + hour), clouds_seen(&followed, 0.38 + hour));
    let (moved, followed_difference) = (mean_difference(&now, &later_same_way), mean_difference(&now, &later_followed));
    let shown = now.iter().filter(|&&d| d.abs() > 8).count() as f32 / now.len() as f32;
    eprintln!(
        "clouds cover {:.0} % of the view; an hour later they differ by {moved:.1} on average, \
         by {followed_difference:.1} when the camera turns with them",
        shown * 100.0
    );
    assert!((shown - CLOUDS_SHOWN).abs() < 0.03, "{shown}");
    assert!((moved - 23.7).abs() < 3.0 && followed_difference < 1.0, "{followed_difference} against {moved}");
}
