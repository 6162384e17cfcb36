//! The prefiltered sky (prefilter.wgsl), read back the way lights.wgsl
//! reads it, by the GPU's own cube look-up: its mirror level is the sky in
//! every direction (so the faces are where WebGPU looks for them), and each
//! rougher level is the sky blurred by GGX, against the same blur integrated
//! here on a grid of half vectors rather than importance-sampled.

use std::f32::consts::{FRAC_PI_4, PI};

use common::glam::{Quat, Vec3};
use common::{ShaderFile, wgpu};
use lighting::irradiance::SkyColours;
use lighting::lights::smoothstep;
use lighting::pbr;
use lighting::prefiltered_sky::PrefilteredSky;

use crate::pbr::{gpu, run_compute_with};

/// A sky whose three colours differ in every channel, so that a face or a
/// level looked up in the wrong place shows.
const SKY: SkyColours = SkyColours {
    horizon: Vec3::new(0.9, 0.6, 0.3),
    zenith: Vec3::new(0.1, 0.3, 0.8),
    ground: Vec3::new(0.05, 0.12, 0.02),
};

/// The sky's radiance towards `d`, as sky_light.wgsl's `sky_radiance`
/// defines it: the ground below the horizon, and from the horizon's
/// colour to the zenith's over the first 0.6 of height.
fn sky(d: Vec3) -> Vec3 {
    if d.y < 0.0 { SKY.ground } else { SKY.horizon.lerp(SKY.zenith, smoothstep(0.0, 0.6, d.y)) }
}

/// Each direction's look-up at its level (w), by the GPU's sampler.
const LOOK_UP: &str = r#"
@group(0) @binding(0) var<storage, read> input: array<vec4<f32>>;
@group(0) @binding(1) var<storage, read_write> results: array<vec4<f32>>;
@group(0) @binding(2) var sky_cube: texture_cube<f32>;
@group(0) @binding(3) var sky_sampler: sampler;
@compute @workgroup_size(64)
fn cs_look_up(@builtin(global_invocation_id) id: vec3<u32>) {
    if id.x >= arrayLength(&input) { return; }
    results[id.x] = textureSampleLevel(sky_cube, sky_sampler, input[id.x].xyz, input[id.x].w);
}
"#;

fn look_up(directions_and_levels: &[[f32; 4]]) -> Vec<Vec3> {
    let gpu = gpu();
    let mut prefiltered = PrefilteredSky::new(&gpu).unwrap();
    prefiltered.update(&gpu, SKY, &common::PassTimer::off());
    let file = ShaderFile { path: "tests/look_up.wgsl", embedded: LOOK_UP, imports: &[] };
    let more =
        [wgpu::BindingResource::TextureView(&prefiltered.view), wgpu::BindingResource::Sampler(&prefiltered.sampler)];
    run_compute_with(&gpu, file, "cs_look_up", directions_and_levels, directions_and_levels.len(), &more)
        .iter()
        .map(|c| Vec3::new(c[0], c[1], c[2]))
        .collect()
}

#[test]
fn the_mirror_level_is_the_sky_in_every_direction_the_gpu_looks_up() {
    let mut rng = common::rng::Rng::new(11);
    let directions: Vec<Vec3> = std::iter::repeat_with(|| {
        Vec3::new(rng.range(-1.0, 1.0), rng.range(-1.0, 1.0), rng.range(-1.0, 1.0)).normalize()
    })
    // Not within a texel of the horizon, where the sky steps to the ground
    // and a filtered look-up blends the two.
    .filter(|d| d.y.abs() > 0.05)
    .take(200)
    .collect();
    let input: Vec<[f32; 4]> = directions.iter().map(|d| d.extend(0.0).to_array()).collect();
    let found = look_up(&input);
    for (d, got) in directions.iter().zip(found) {
        let want = sky(*d);
        // A 64-texel face blends neighbours a degree or so apart (the
        // gradient moves by under 0.02 over that), in half floats.
        assert!((got - want).abs().max_element() < 0.02, "towards {d}: {got}, but the sky is {want}");
    }
}

/// What a surface of `roughness` facing `r` and seen from `r` reflects of
/// the sky, over its reflection weight: ∫ L(l) (n·l) D(h) (n·h) dω_h over
/// ∫ (n·l) D(h) (n·h) dω_h, n = v = r, l = 2 (n·h) h − n, by the midpoint
/// rule on a grid of half vectors within 45° of n (beyond it l is below
/// the surface).
fn blurred_sky(r: Vec3, roughness: f32) -> Vec3 {
    // GGX's width by Burley's rule, written out here rather than taken from
    // `pbr::ggx_alpha` (which pbr.rs's tests pin by hand): the prefilter
    // shader's own `ggx_alpha` must agree with it.
    let alpha = roughness * roughness;
    let turn = Quat::from_rotation_arc(Vec3::Z, r);
    let (rings, spokes) = (1024, 128);
    let (d_theta, d_phi) = (FRAC_PI_4 / rings as f32, 2.0 * PI / spokes as f32);
    let (mut light, mut weight) = (common::glam::DVec3::ZERO, 0.0f64);
    for i in 0..rings {
        let theta = (i as f32 + 0.5) * d_theta;
        let (sin_t, cos_t) = theta.sin_cos();
        let facets = pbr::ggx_distribution(cos_t, alpha) * cos_t * sin_t * d_theta * d_phi;
        for j in 0..spokes {
            let (sin_p, cos_p) = ((j as f32 + 0.5) * d_phi).sin_cos();
            let h = turn * Vec3::new(sin_t * cos_p, sin_t * sin_p, cos_t);
            let l = 2.0 * cos_t * h - r;
            let n_dot_l = l.dot(r);
            if n_dot_l > 0.0 {
                let w = f64::from(facets * n_dot_l);
                light += sky(l).as_dvec3() * w;
                weight += w;
            }
        }
    }
    (light / weight).as_vec3()
}

/// The direction through the centre of texel (x, y) of a `side`-texel face
/// of a cube, from WebGPU's face table (its order +x, −x, +y, −y, +z, −z;
/// s across and t down a face, as the spec's cube sampling defines them).
fn texel_direction(face: usize, x: u32, y: u32, side: u32) -> Vec3 {
    let s = 2.0 * (x as f32 + 0.5) / side as f32 - 1.0;
    let t = 2.0 * (y as f32 + 0.5) / side as f32 - 1.0;
    let d = match face {
        0 => Vec3::new(1.0, -t, -s),
        1 => Vec3::new(-1.0, -t, s),
        2 => Vec3::new(s, 1.0, t),
        3 => Vec3::new(s, -1.0, -t),
        4 => Vec3::new(s, -t, 1.0),
        _ => Vec3::new(-s, -t, -1.0),
    };
    d.normalize()
}

/// The roughness each level must be blurred for, by hand from how
/// lights.wgsl reads the cube (`level = roughness × (levels − 1)`): with
/// four levels, level k serves roughness k/3. Not `roughness_of`, the
/// function under test, which writes the roughness the shader blurs for.
const LEVEL_ROUGHNESS: [f32; 4] = [0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0];

#[test]
fn each_rougher_level_is_the_sky_blurred_by_ggx_as_the_integral_says() {
    assert_eq!(
        PrefilteredSky::LEVELS as usize,
        LEVEL_ROUGHNESS.len(),
        "the hand-worked roughnesses are for four levels"
    );
    // At texel centres, where a look-up at a whole level returns that
    // texel alone: on the +x face's upper and lower halves, straight up,
    // straight down, and towards +z just above the horizon.
    let mut cases = Vec::new();
    for level in 1..PrefilteredSky::LEVELS {
        let side = PrefilteredSky::SIZE >> level;
        let last = side - 1;
        for (face, x, y) in
            [(0, side / 3, side / 3), (0, side / 2, last), (2, side / 2, side / 2), (3, 0, 0), (4, 0, last / 2)]
        {
            cases.push((level, texel_direction(face, x, y, side)));
        }
    }
    let input: Vec<[f32; 4]> = cases.iter().map(|(level, d)| d.extend(*level as f32).to_array()).collect();
    let found = look_up(&input);
    let mut worst = 0.0f32;
    for ((level, r), got) in cases.iter().zip(found) {
        let roughness = LEVEL_ROUGHNESS[*level as usize];
        let want = blurred_sky(*r, roughness);
        let off = (got - want).abs().max_element();
        worst = worst.max(off);
        // 512 importance samples against the grid, in half floats: 0.008
        // at worst when this was written, at the horizon's step.
        assert!(off < 0.02, "level {level} (roughness {roughness:.2}) towards {r}: the GPU's {got}, integrated {want}");
    }
    eprintln!("prefiltered sky: worst difference from the integral {worst:.4}");
}
