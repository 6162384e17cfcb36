// Chapter 10: reading a shadow map, as a module. `sunlit` answers, for a
// point on a surface, how much of the sun reaches it: 1 in full sun, 0 in
// shadow, between the two in a soft edge. The scene shader imports it and
// hands its answer to chapter 08's light loop (`light_surface_sunlit`).
#define_import_path shadows::shadow

// ANCHOR: bindings
// 112 bytes, as ShadowUniform in shadow_map.rs.
struct Shadow {
    // World space to the light's clip space: the orthographic box.
    light_view_proj: mat4x4<f32>,
    // x: the filter (0 none: all lit, 1 hard, 2 3×3 PCF, 3 Poisson, 4 PCSS),
    // y: the map's size in texels.
    options: vec4<u32>,
    // x: one texel's width in metres, y: the normal offset in texels,
    // z: the filter radius in texels (Poisson), w: PCSS's light width,
    // in metres of penumbra per metre between blocker and receiver.
    params: vec4<f32>,
    // x: the box's depth in metres (to turn depth differences into metres).
    extent: vec4<f32>,
};
@group(3) @binding(0) var shadow_map: texture_depth_2d;
// Compares without filtering (one texel's answer, 0 or 1) and with
// bilinear filtering (four texels' answers, weighted).
@group(3) @binding(1) var compare_nearest: sampler_comparison;
@group(3) @binding(2) var compare_linear: sampler_comparison;
// Storage, not uniform: `sunlit` switches on `options.x` (lights.wgsl's `frame` says why).
@group(3) @binding(3) var<storage, read> shadow: Shadow;
// The same map again, as plain floats through a nearest sampler, for PCSS's
// blocker search, which needs the stored depths themselves: OpenGL's GLSL
// cannot fetch the texels of a texture declared as depth.
@group(3) @binding(4) var shadow_depths: texture_2d<f32>;
@group(3) @binding(5) var depth_nearest: sampler;
// And once more for the blended comparisons: GLSL reads a texture through
// one sampler only.
@group(3) @binding(6) var shadow_map_blended: texture_depth_2d;
// ANCHOR_END: bindings

// ANCHOR: project
// Where a world point lands in the shadow map: texture coordinates (x
// right, y down) and its depth as the light sees it.
fn to_shadow_map(world: vec3<f32>) -> vec3<f32> {
    let clip = shadow.light_view_proj * vec4<f32>(world, 1.0);
    // Orthographic: w is 1, no division needed.
    return vec3<f32>(clip.x * 0.5 + 0.5, 0.5 - clip.y * 0.5, clip.z);
}
// ANCHOR_END: project

// ANCHOR: poisson
// Sixteen points spread over the unit disk, none closer to another than
// 0.43: a Poisson-disk set, random but never clumped. Made by dart
// throwing (random points, each kept only if it lands at least 0.42 from
// every point kept before); a test in tests/it/shadow_maps.rs checks the spacing.
const POISSON = array<vec2<f32>, 16>(
    vec2<f32>(0.3601, 0.3278), vec2<f32>(0.3830, -0.2752),
    vec2<f32>(-0.6418, -0.5223), vec2<f32>(0.3585, -0.8642),
    vec2<f32>(-0.1737, -0.5019), vec2<f32>(0.9096, -0.3169),
    vec2<f32>(-0.0412, -0.0842), vec2<f32>(-0.4291, 0.7227),
    vec2<f32>(-0.9274, -0.1001), vec2<f32>(0.4903, 0.7679),
    vec2<f32>(0.9485, 0.1567), vec2<f32>(-0.3953, 0.1683),
    vec2<f32>(-0.8404, 0.3301), vec2<f32>(0.0752, 0.9271),
    vec2<f32>(-0.2427, -0.9291), vec2<f32>(-0.0580, 0.4733),
);

// An angle per pixel from interleaved gradient noise (Jimenez 2014): it
// changes from pixel to pixel, so the sixteen taps turn a different way
// at each, and banding becomes fine noise. A function of the pixel
// alone, so pictures are the same every run.
fn pixel_angle(pixel: vec2<f32>) -> f32 {
    let noise = fract(52.9829189 * fract(dot(pixel, vec2<f32>(0.06711056, 0.00583715))));
    return noise * 6.2831853;
}

// The Poisson disk turned by `angle` and scaled to `radius` texels.
fn poisson_tap(i: u32, angle: f32, radius: f32) -> vec2<f32> {
    let c = cos(angle);
    let s = sin(angle);
    let p = POISSON[i];
    return vec2<f32>(c * p.x - s * p.y, s * p.x + c * p.y) * radius;
}
// ANCHOR_END: poisson

// ANCHOR: filters
// ANCHOR: hard
// One comparison: is the stored depth at `uv` at least `depth`?
fn hard(uv: vec2<f32>, depth: f32) -> f32 {
    return textureSampleCompareLevel(shadow_map, compare_nearest, uv, depth);
}
// ANCHOR_END: hard

// Percentage-closer filtering (Reeves et al. 1987): the answers of nine
// comparisons one texel apart, averaged. Each tap compares before it
// filters; averaging depths first would compare a depth nobody has.
fn pcf_3x3(uv: vec2<f32>, depth: f32, texel: f32) -> f32 {
    var sum = 0.0;
    for (var y = -1; y <= 1; y++) {
        for (var x = -1; x <= 1; x++) {
            let offset = vec2<f32>(f32(x), f32(y)) * texel;
            sum += textureSampleCompareLevel(shadow_map_blended, compare_linear, uv + offset, depth);
        }
    }
    return sum / 9.0;
}

// Sixteen comparisons on a Poisson disk of `radius` texels, turned per pixel.
fn poisson(uv: vec2<f32>, depth: f32, texel: f32, radius: f32, pixel: vec2<f32>) -> f32 {
    let angle = pixel_angle(pixel);
    var sum = 0.0;
    for (var i = 0u; i < 16u; i++) {
        let offset = poisson_tap(i, angle, radius) * texel;
        sum += textureSampleCompareLevel(shadow_map_blended, compare_linear, uv + offset, depth);
    }
    return sum / 16.0;
}
// ANCHOR_END: filters

// ANCHOR: pcss
// Percentage-closer soft shadows (Fernando 2005): a shadow's edge is as
// soft as the blocker is far from the receiver. Search for blockers (depths
// nearer the light than this point), average their depth, and widen the
// Poisson filter by the distance between the two.
fn pcss(uv: vec2<f32>, depth: f32, texel: f32, pixel: vec2<f32>) -> f32 {
    let size = i32(shadow.options.y);
    let angle = pixel_angle(pixel);
    let search = 12.0;
    var blockers = 0.0;
    var blocker_depth = 0.0;
    for (var i = 0u; i < 16u; i++) {
        let at = uv + poisson_tap(i, angle, search) * texel;
        let texel_at = clamp(vec2<i32>(at * f32(size)), vec2<i32>(0), vec2<i32>(size - 1));
        let stored = textureSampleLevel(shadow_depths, depth_nearest, (vec2<f32>(texel_at) + 0.5) / f32(size), 0.0).r;
        if stored < depth {
            blockers += 1.0;
            blocker_depth += stored;
        }
    }
    if blockers == 0.0 {
        return 1.0;
    }
    // Metres from the blockers to here, times the light's width per metre,
    // in texels: the penumbra's width.
    let metres = (depth - blocker_depth / blockers) * shadow.extent.x;
    let penumbra = metres * shadow.params.w / shadow.params.x;
    return poisson(uv, depth, texel, clamp(penumbra, 1.0, search), pixel);
}
// ANCHOR_END: pcss

// ANCHOR: sunlit
// How much sun reaches `world`, a point on a surface with unit normal `n`,
// drawn at `pixel`.
fn sunlit(world: vec3<f32>, n: vec3<f32>, pixel: vec2<f32>) -> f32 {
    let mode = shadow.options.x;
    if mode == 0u {
        return 1.0;
    }
    // The normal offset: look the point up a little off its surface, so
    // that a surface does not shadow itself (`Bias` in shadow_map.rs explains; the depth
    // bias in the shadow pass does the rest).
    let lifted = world + n * shadow.params.y * shadow.params.x;
    let p = to_shadow_map(lifted);
    // Outside the box the map knows nothing: call it sunlit.
    if any(p.xy < vec2<f32>(0.0)) || any(p.xy > vec2<f32>(1.0)) || p.z > 1.0 {
        return 1.0;
    }
    let texel = 1.0 / f32(shadow.options.y);
    switch mode {
        case 1u: { return hard(p.xy, p.z); }
        case 2u: { return pcf_3x3(p.xy, p.z, texel); }
        case 3u: { return poisson(p.xy, p.z, texel, shadow.params.z, pixel); }
        default: { return pcss(p.xy, p.z, texel, pixel); }
    }
}
// ANCHOR_END: sunlit
