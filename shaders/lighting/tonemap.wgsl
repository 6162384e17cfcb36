// Chapter 08: from the HDR picture to the screen. Adds the bloom, scales by
// the exposure, and tone-maps with the ACES filmic curve as fitted by
// Narkowicz (2016). The target is sRGB: the GPU encodes the linear result,
// so no gamma curve is applied here.
#import common::fullscreen::{FullscreenOutput, fullscreen_triangle}

struct Composite {
    exposure: f32,
    bloom_strength: f32,
    // 0: the picture with bloom, tone-mapped; 1: the bloom alone;
    // 2: the picture as it is, untouched (the heat map).
    mode: u32,
    padding: u32,
};
@group(0) @binding(0) var hdr: texture_2d<f32>;
@group(0) @binding(1) var bloom: texture_2d<f32>;
@group(0) @binding(2) var linear_sampler: sampler;
@group(0) @binding(3) var<uniform> composite: Composite;

@vertex
fn vs_fullscreen(@builtin(vertex_index) index: u32) -> FullscreenOutput {
    return fullscreen_triangle(index, 0.0);
}

// ANCHOR: aces
// Krzysztof Narkowicz's fit of the ACES filmic tone curve: a toe that
// keeps shadows deep, a shoulder that rolls highlights off towards white.
// `aces_fit` in post.rs is the same curve, and a test holds them together.
fn aces(x: vec3<f32>) -> vec3<f32> {
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), vec3<f32>(0.0), vec3<f32>(1.0));
}
// ANCHOR_END: aces

// The bloom level is half the size: read it through a 3 × 3 tent for a
// smooth enlargement.
fn bloom_at(uv: vec2<f32>) -> vec3<f32> {
    let texel = 1.0 / vec2<f32>(textureDimensions(bloom));
    var sum = vec3<f32>(0.0);
    for (var y = -1; y <= 1; y++) {
        for (var x = -1; x <= 1; x++) {
            let weight = f32((2 - abs(x)) * (2 - abs(y)));
            sum += weight * textureSample(bloom, linear_sampler, uv + texel * vec2<f32>(f32(x), f32(y))).rgb;
        }
    }
    return sum / 16.0;
}

// ANCHOR: composite
@fragment
fn fs_composite(in: FullscreenOutput) -> @location(0) vec4<f32> {
    let scene = textureLoad(hdr, vec2<i32>(in.clip_position.xy), 0).rgb;
    let glow = bloom_at(in.uv) * composite.bloom_strength;
    switch composite.mode {
        case 1u: {
            return vec4<f32>(aces(glow * composite.exposure), 1.0);
        }
        case 2u: {
            return vec4<f32>(scene, 1.0);
        }
        default: {
            return vec4<f32>(aces((scene + glow) * composite.exposure), 1.0);
        }
    }
}
// ANCHOR_END: composite
