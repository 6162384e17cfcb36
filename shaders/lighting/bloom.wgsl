// Chapter 08: bloom, a chain of downsamples and upsamples (Jimenez 2014).
// The first downsample also takes out the bright part of the picture.
#import common::fullscreen::{FullscreenOutput, fullscreen_triangle}

struct Params {
    threshold: f32,
    knee: f32,
    // 1 in the first pass: read the HDR picture and keep its bright part.
    prefilter: u32,
    padding: u32,
};
@group(0) @binding(0) var source: texture_2d<f32>;
@group(0) @binding(1) var linear_sampler: sampler;
@group(0) @binding(2) var<uniform> params: Params;

@vertex
fn vs_fullscreen(@builtin(vertex_index) index: u32) -> FullscreenOutput {
    return fullscreen_triangle(index, 0.0);
}

// ANCHOR: bright
// The part of a colour above the threshold, with a soft knee (bloom.rs
// has the same formula, tested).
fn bright_part(colour: vec3<f32>) -> vec3<f32> {
    let brightness = max(colour.r, max(colour.g, colour.b));
    var soft = clamp(brightness - params.threshold + params.knee, 0.0, 2.0 * params.knee);
    soft = soft * soft / (4.0 * params.knee + 1e-5);
    let weight = max(soft, brightness - params.threshold) / max(brightness, 1e-5);
    return colour * weight;
}
// ANCHOR_END: bright

fn tap(uv: vec2<f32>, texel: vec2<f32>, x: f32, y: f32) -> vec3<f32> {
    return textureSample(source, linear_sampler, uv + texel * vec2<f32>(x, y)).rgb;
}

// ANCHOR: downsample
@fragment
fn fs_downsample(in: FullscreenOutput) -> @location(0) vec4<f32> {
    if params.prefilter == 1u {
        // The four full-size texels under this half-size texel, each
        // bright-passed, averaged: the light they carry is kept exactly.
        let here = vec2<i32>(in.clip_position.xy) * 2;
        let last = vec2<i32>(textureDimensions(source)) - 1;
        var sum = vec3<f32>(0.0);
        for (var y = 0; y < 2; y++) {
            for (var x = 0; x < 2; x++) {
                sum += bright_part(textureLoad(source, min(here + vec2<i32>(x, y), last), 0).rgb);
            }
        }
        return vec4<f32>(sum * 0.25, 1.0);
    }
    // Thirteen bilinear taps: five overlapping 2 × 2 boxes, the middle one
    // weighted most. The weights sum to 1, so light is neither made nor lost.
    let texel = 1.0 / vec2<f32>(textureDimensions(source));
    let uv = in.uv;
    let centre = tap(uv, texel, 0.0, 0.0);
    let inner = tap(uv, texel, -1.0, -1.0) + tap(uv, texel, 1.0, -1.0) + tap(uv, texel, -1.0, 1.0) + tap(uv, texel, 1.0, 1.0);
    let corners = tap(uv, texel, -2.0, -2.0) + tap(uv, texel, 2.0, -2.0) + tap(uv, texel, -2.0, 2.0) + tap(uv, texel, 2.0, 2.0);
    let sides = tap(uv, texel, 0.0, -2.0) + tap(uv, texel, -2.0, 0.0) + tap(uv, texel, 2.0, 0.0) + tap(uv, texel, 0.0, 2.0);
    return vec4<f32>(centre * 0.125 + inner * 0.125 + corners * 0.03125 + sides * 0.0625, 1.0);
}
// ANCHOR_END: downsample

// ANCHOR: upsample
// A 3 × 3 tent (1 2 1 / 2 4 2 / 1 2 1, over 16) over the smaller level;
// the pipeline's blend mixes it into this level by the spread.
@fragment
fn fs_upsample(in: FullscreenOutput) -> @location(0) vec4<f32> {
    let texel = 1.0 / vec2<f32>(textureDimensions(source));
    let uv = in.uv;
    var sum = tap(uv, texel, 0.0, 0.0) * 4.0;
    sum += (tap(uv, texel, -1.0, 0.0) + tap(uv, texel, 1.0, 0.0) + tap(uv, texel, 0.0, -1.0) + tap(uv, texel, 0.0, 1.0)) * 2.0;
    sum += tap(uv, texel, -1.0, -1.0) + tap(uv, texel, 1.0, -1.0) + tap(uv, texel, -1.0, 1.0) + tap(uv, texel, 1.0, 1.0);
    return vec4<f32>(sum / 16.0, 1.0);
}
// ANCHOR_END: upsample
