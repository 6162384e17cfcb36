// Lets a vertex shader write @builtin(clip_distances); only used under
// #ifdef CLIP_DISTANCES, which is defined when the device has the feature.
enable clip_distances;

// Chapter 07: a lake. The surface is a grid moved by eight sine waves in
// the vertex shader; its colour comes from two pictures of the scene,
// one reflected in the water and one seen through it, mixed by Fresnel
// (fs_water), or in seed 003's style from a tiled water texture that
// pushes itself aside (fs_texture).
#import terrain::globals
#import fog::{fog, visibility}
#import water::waves::wave_sum

// ANCHOR: uniforms
struct Water {
    // x: the water's mean level (m), y: scene time (s), z: wave strength
    // (0 flat), w: 1 to mix by Fresnel, 0 for a fixed half-and-half.
    level_time: vec4<f32>,
    // x: DuDv distortion strength, y: metres per ripple-texture repeat,
    // z, w: the main camera's near and far planes.
    ripples: vec4<f32>,
    // Eight waves: xy direction, z amplitude (m), w wavelength (m)…
    waves: array<vec4<f32>, 8>,
    // …and their speeds (m/s), four to a vec4.
    speeds: array<vec4<f32>, 2>,
    // Seed 003's style: x how far the second read is pushed (tiles per
    // unit of colour), y metres of lake per tile of the texture.
    texture: vec4<f32>,
};
@group(2) @binding(0) var<uniform> water: Water;
@group(2) @binding(1) var reflection_texture: texture_2d<f32>;
@group(2) @binding(2) var refraction_texture: texture_2d<f32>;
// The refraction's depth buffer, read as plain floats through a nearest
// sampler: chapter 02's depth view says why.
@group(2) @binding(3) var refraction_depth: texture_2d<f32>;
@group(2) @binding(4) var dudv_map: texture_2d<f32>;
@group(2) @binding(5) var normal_map: texture_2d<f32>;
@group(2) @binding(6) var repeat_sampler: sampler;
@group(2) @binding(7) var clamp_sampler: sampler;
@group(2) @binding(8) var water_texture: texture_2d<f32>;
@group(2) @binding(9) var water_texture_sampler: sampler;
@group(2) @binding(10) var depth_nearest: sampler;
// ANCHOR_END: uniforms

struct WaterOutput {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) world_position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    // The clip position again, interpolated: the projective texture coordinates.
    @location(2) clip: vec4<f32>,
};

// ANCHOR: waves
// The waves' sum (waves.wgsl, the same sums as waves.rs on the CPU) lifts
// each vertex of the flat grid, and its slope gives the normal.
@vertex
fn vs_water(@location(0) position: vec3<f32>) -> WaterOutput {
    let p = position.xz;
    let sum = wave_sum(water.waves, water.speeds, p, water.level_time.y);
    let height = sum.x;
    let slope = sum.yz;
    let strength = water.level_time.z;
    let world = vec3<f32>(p.x, water.level_time.x + strength * height, p.y);
    var out: WaterOutput;
    out.clip_position = globals.view_proj * vec4<f32>(world, 1.0);
    out.world_position = world;
    out.normal = normalize(vec3<f32>(-strength * slope.x, 1.0, -strength * slope.y));
    out.clip = out.clip_position;
    return out;
}
// ANCHOR_END: waves

// Distance from the camera along its view, from a depth-buffer value.
fn linear_depth(depth: f32) -> f32 {
    let near = water.ripples.z;
    let far = water.ripples.w;
    return near * far / (far - depth * (far - near));
}

// ANCHOR: fs_water
@fragment
fn fs_water(in: WaterOutput) -> @location(0) vec4<f32> {
    // ANCHOR: projective
    // Projective texturing: where this fragment lands on screen is where to
    // read the refraction picture; the reflection picture was taken by a
    // camera below the water, upside down, so its v runs the other way.
    let ndc = in.clip.xy / in.clip.w;
    var refraction_uv = vec2<f32>(0.5 + 0.5 * ndc.x, 0.5 - 0.5 * ndc.y);
    var reflection_uv = vec2<f32>(0.5 + 0.5 * ndc.x, 0.5 + 0.5 * ndc.y);
    // ANCHOR_END: projective

    // How deep the water is here: the refraction's depth buffer holds the
    // lake bed, the fragment's own depth the surface.
    let size = vec2<f32>(textureDimensions(refraction_depth));
    let texel = vec2<f32>(vec2<i32>(refraction_uv * (size - 1.0)));
    let bed = textureSampleLevel(refraction_depth, depth_nearest, (texel + 0.5) / size, 0.0).r;
    let depth = linear_depth(bed) - linear_depth(in.clip_position.z);
    let shallow = clamp(depth / 1.5, 0.0, 1.0);

    // Ripples: the DuDv map, read twice, scrolling two ways, bends both
    // pictures, less so near the shore.
    let t = water.level_time.y;
    let tile = in.world_position.xz / water.ripples.y;
    let dudv = textureSample(dudv_map, repeat_sampler, tile + vec2<f32>(0.02 * t, 0.0)).rg * 2.0 - 1.0
        + textureSample(dudv_map, repeat_sampler, tile * 0.7 + vec2<f32>(-0.013 * t, 0.017 * t)).rg * 2.0 - 1.0;
    let distortion = dudv * water.ripples.x * shallow;
    refraction_uv = clamp(refraction_uv + distortion, vec2<f32>(0.001), vec2<f32>(0.999));
    reflection_uv = clamp(reflection_uv + distortion, vec2<f32>(0.001), vec2<f32>(0.999));
    var refraction = textureSample(refraction_texture, clamp_sampler, refraction_uv).rgb;
    let reflection = textureSample(reflection_texture, clamp_sampler, reflection_uv).rgb;
    // Deeper water is murkier.
    refraction = mix(refraction, vec3<f32>(0.04, 0.09, 0.10), clamp(depth / 12.0, 0.0, 0.75));

    // Small ripples from the normal map (red x, green z, blue up), on top
    // of the waves' own normal.
    let ripple = textureSample(normal_map, repeat_sampler, tile * 2.0 + distortion * 4.0).rgb * 2.0 - 1.0;
    let n = normalize(in.normal + vec3<f32>(ripple.x, 0.0, ripple.y) * 0.35);
    let to_eye = normalize(globals.eye.xyz - in.world_position);

    // Fresnel (Schlick's approximation): water reflects 2 % looking
    // straight down and nearly everything at a grazing angle.
    var fresnel = 0.5;
    if water.level_time.w > 0.5 {
        fresnel = 0.02 + 0.98 * pow(1.0 - max(dot(to_eye, n), 0.0), 5.0);
    }
    var colour = mix(refraction, reflection, fresnel);

    // The sun's highlight, fading with the sun itself at dusk.
    let mirrored = reflect(-globals.sun.xyz, n);
    let highlight = pow(max(dot(mirrored, to_eye), 0.0), 160.0) * globals.sun.w;
    colour += vec3<f32>(1.0, 0.95, 0.85) * highlight * shallow;

    // Fog like everything else, and soft edges where the water is shallow.
    let distance = length(globals.eye.xyz - in.world_position);
    colour = mix(fog.colour.rgb, colour, visibility(distance));
    return vec4<f32>(colour, shallow);
}
// ANCHOR_END: fs_water

// ANCHOR: fs_texture
// Seed 003's water: no pictures of the scene, only a tiled water texture,
// read twice. The first read, where the fragment is, is not shown: its
// green and blue say how far to push the second read, which scrolls with
// time. The push stays where it is on the lake while the texture drifts
// through it, so the pattern swirls and stretches instead of sliding
// along stiffly as one picture. (The texture is sRGB, so the push reads
// its colours in linear light: darker than its bytes, a smaller push.)
const TEXTURE_DRIFT: vec2<f32> = vec2<f32>(-0.006, 0.024); // tiles per second
// The second read's frequency, in times the first's: its tile is two thirds
// of the first's, so the two line up again every 2 tiles of the first.
const SECOND_READ_FREQUENCY: f32 = 1.5;

@fragment
fn fs_texture(in: WaterOutput) -> @location(0) vec4<f32> {
    let uv = in.world_position.xz / water.texture.y;
    let push = textureSample(water_texture, water_texture_sampler, uv).gb;
    var moved = uv + TEXTURE_DRIFT * water.level_time.y;
    moved += vec2<f32>(-push.x, push.y) * water.texture.x;
    let albedo = textureSample(water_texture, water_texture_sampler, moved * SECOND_READ_FREQUENCY).rgb;

    // Seed 003 showed the texture as it was. Lit by the sun through the
    // waves' normal, with a highlight like the pictures' style's, the
    // waves show in it too.
    let n = normalize(in.normal);
    let to_eye = normalize(globals.eye.xyz - in.world_position);
    let sunlight = globals.sun.w * max(dot(n, globals.sun.xyz), 0.0);
    var lit = albedo * (0.35 + 0.65 * sunlight);
    let glint = reflect(-globals.sun.xyz, n);
    lit += vec3<f32>(1.0, 0.95, 0.85) * pow(max(dot(glint, to_eye), 0.0), 160.0) * globals.sun.w;

    let distance = length(globals.eye.xyz - in.world_position);
    return vec4<f32>(mix(fog.colour.rgb, lit, visibility(distance)), 1.0);
}
// ANCHOR_END: fs_texture
