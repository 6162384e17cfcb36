// Chapter 10: reading a point light's cube shadow map, as a module.
// `point_lit` answers, for a point on a surface, how much of the light
// reaches it (1 lit, 0 in shadow, between at a soft edge);
// `shadowed_point_light` is chapter 08's point light at that point, scaled
// by that answer. The scene shader imports both.
#define_import_path shadows::point_shadow
#import lighting::lights::{frame, Surface, attenuation, reflected}

// ANCHOR: bindings
// 64 bytes, as PointShadowUniform in point_shadow.rs.
struct PointShadow {
    // xyz: where the light is; w: its range in metres (the cube stores
    // distance / range, 0 at the light and 1 at the range).
    light: vec4<f32>,
    // rgb: its colour, as chapter 08's `Light.colour`.
    colour: vec4<f32>,
    // x: the filter (0 none: the light passes through everything, 1 hard,
    // 2 3×3 PCF), y: a face's size in texels.
    options: vec4<u32>,
    // x: the normal offset, y: the depth bias, both in texels at the
    // point's distance; z: how far apart the PCF taps are, in texels.
    params: vec4<f32>,
};
// Bindings 1 to 5 of the scene's group 2 (binding 0 is the surface
// sampler): WebGPU promises a pipeline four groups, and the scene uses all four.
@group(2) @binding(1) var point_map: texture_depth_cube;
// One texel's answer, and four texels' answers blended, as the sun's.
@group(2) @binding(2) var point_compare_nearest: sampler_comparison;
@group(2) @binding(3) var point_compare_linear: sampler_comparison;
// Storage, not uniform: `point_lit` switches on `options.x` (lights.wgsl's `frame` says why).
@group(2) @binding(4) var<storage, read> point_shadow: PointShadow;
// The cube again, for the blended lookups: OpenGL's GLSL reads a texture
// through one sampler only.
@group(2) @binding(5) var point_map_blended: texture_depth_cube;
// ANCHOR_END: bindings

// ANCHOR: lookup
// Metres one texel of the cube covers at `distance` from the light, in
// the middle of a face: a face spans 90°, 2 × distance across.
fn cube_texel(distance: f32) -> f32 {
    return 2.0 * distance / f32(point_shadow.options.y);
}

// How much of the point light reaches `world`, a point on a surface with
// unit normal `n`.
fn point_lit(world: vec3<f32>, n: vec3<f32>) -> f32 {
    let mode = point_shadow.options.x;
    let range = point_shadow.light.w;
    let distance = length(world - point_shadow.light.xyz);
    // Beyond the range the light adds nothing, and the cube holds nothing.
    if mode == 0u || distance >= range {
        return 1.0;
    }
    let texel = cube_texel(distance);
    // The normal offset: look the point up a little off its surface, so
    // that the surface does not shadow itself (`PointBias` explains).
    let from_light = world + n * point_shadow.params.x * texel - point_shadow.light.xyz;
    // The depth bias: and take it to be a little nearer the light.
    let reference = (length(from_light) - point_shadow.params.y * texel) / range;
    // A direction, not a position: the GPU picks the face and the texel.
    if mode == 1u {
        return textureSampleCompareLevel(point_map, point_compare_nearest, from_light, reference);
    }
    // Percentage-closer filtering: nine directions around this one, a
    // texel apart (2 / size across the middle of a face, for a unit
    // direction), each compared with the same distance. Near a cube
    // edge some taps read the next face; the distance is the same there.
    let axis = normalize(from_light);
    let helper = select(vec3<f32>(0.0, 1.0, 0.0), vec3<f32>(1.0, 0.0, 0.0), abs(axis.y) > 0.9);
    let right = normalize(cross(helper, axis));
    let up = cross(axis, right);
    let step = point_shadow.params.z * 2.0 / f32(point_shadow.options.y);
    var sum = 0.0;
    for (var y = -1; y <= 1; y++) {
        for (var x = -1; x <= 1; x++) {
            let tap = axis + (right * f32(x) + up * f32(y)) * step;
            sum += textureSampleCompareLevel(point_map_blended, point_compare_linear, tap, reference);
        }
    }
    return sum / 9.0;
}
// ANCHOR_END: lookup

// ANCHOR: light
// The point light's share of what a surface at `world` reflects: chapter
// 08's falloff and reflection, with the light scaled by its shadow. The
// shadow is looked up with the surface's own normal `geometric`; `n` may
// be a normal map's.
fn shadowed_point_light(world: vec3<f32>, geometric: vec3<f32>, n: vec3<f32>, surface: Surface) -> vec3<f32> {
    let to_light = point_shadow.light.xyz - world;
    let distance = length(to_light);
    let l = to_light / max(distance, 1e-4);
    let v = normalize(frame.eye.xyz - world);
    let arriving = attenuation(distance, point_shadow.light.w) * point_lit(world, geometric);
    return reflected(surface, n, v, l, point_shadow.colour.rgb * arriving);
}
// ANCHOR_END: light
