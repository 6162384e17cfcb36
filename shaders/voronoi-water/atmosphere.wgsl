// Chapter 11: the sky's colours, as a module. The sky, the sun's disc and
// the islands take their colours from gradient pictures painted by
// `cargo xtask assets`, looked up by the sun's height (and, for the sky,
// by how high one looks; for the islands, by how high the ground is).
// The light the sun throws comes from a fourth gradient, read on the CPU.
#define_import_path voronoi_water::atmosphere

// ANCHOR: uniform
struct Atmosphere {
    inverse_view_proj: mat4x4<f32>,
    eye: vec4<f32>,
    // xyz: towards the sun; w: the sun's height as the gradients read it,
    // 0.5 + 0.5 sin(elevation): 0 straight below, 0.5 on the horizon.
    sun: vec4<f32>,
    // x: fog density per metre; y: the cosine of the sun disc's radius.
    fog: vec4<f32>,
};
@group(1) @binding(0) var<uniform> atmosphere: Atmosphere;
// Across: the sun's height; down: from the zenith to the horizon.
@group(1) @binding(1) var sky_gradient: texture_2d<f32>;
// Across: the sun's height (the moon's colour below 0.5).
@group(1) @binding(2) var sun_gradient: texture_2d<f32>;
// Across: height on an island, from the waterline to the summit.
@group(1) @binding(3) var island_gradient: texture_2d<f32>;
@group(1) @binding(4) var gradient_sampler: sampler;
// ANCHOR_END: uniform

// ANCHOR: lookups
// The sky's colour looking along `direction` (unit length).
fn sky_colour(direction: vec3<f32>) -> vec3<f32> {
    let up = clamp(direction.y, 0.0, 1.0);
    return textureSampleLevel(sky_gradient, gradient_sampler, vec2<f32>(atmosphere.sun.w, 1.0 - up), 0.0).rgb;
}

// The disc's colour: the sun's, or the moon's when the sun is down.
fn disc_colour() -> vec3<f32> {
    return textureSampleLevel(sun_gradient, gradient_sampler, vec2<f32>(atmosphere.sun.w, 0.5), 0.0).rgb;
}

// The ground's colour at `height`, 0 at the waterline and 1 at the summit.
fn island_colour(height: f32) -> vec3<f32> {
    return textureSampleLevel(island_gradient, gradient_sampler, vec2<f32>(clamp(height, 0.0, 1.0), 0.5), 0.0).rgb;
}
// ANCHOR_END: lookups

// ANCHOR: fog
// Far things fade into the sky's colour at the horizon: exponential fog
// (chapter 04's formula). At the sea's edge, about 398 m from the boat,
// exp(−0.004 × 398) ≈ 0.2 of the sea's colour is left (0.004 per metre is
// FOG_DENSITY in atmosphere.rs): the edge is softened, not hidden.
fn fogged(colour: vec3<f32>, world: vec3<f32>) -> vec3<f32> {
    let distance = length(world - atmosphere.eye.xyz);
    let clear = exp(-atmosphere.fog.x * distance);
    return mix(sky_colour(vec3<f32>(1.0, 0.0, 0.0)), colour, clear);
}
// ANCHOR_END: fog
