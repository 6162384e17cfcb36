// Chapter 09: one mip level from the level above it. The pass covers the
// smaller level; each of its pixels samples the level above at the pixel's
// centre, which there falls on the corner shared by four texels, and the
// linear filter returns their average: a 2 × 2 box filter, in linear light
// for sRGB textures (the sampler decodes, the target encodes).
#import common::fullscreen::{FullscreenOutput, fullscreen_triangle}

@group(0) @binding(0) var above: texture_2d<f32>;
@group(0) @binding(1) var bilinear: sampler;

@vertex
fn vs_fullscreen(@builtin(vertex_index) index: u32) -> FullscreenOutput {
    return fullscreen_triangle(index, 0.0);
}

// ANCHOR: colour
@fragment
fn fs_colour(in: FullscreenOutput) -> @location(0) vec4<f32> {
    return textureSampleLevel(above, bilinear, in.uv, 0.0);
}
// ANCHOR_END: colour

// ANCHOR: normal
// A normal map's level: average the directions, then make the average a
// unit vector again. Four normals that disagree average to a shorter one,
// and a short normal would darken the lighting where the surface is rough.
@fragment
fn fs_normal(in: FullscreenOutput) -> @location(0) vec4<f32> {
    let average = textureSampleLevel(above, bilinear, in.uv, 0.0).xyz * 2.0 - 1.0;
    let n = normalize(select(vec3<f32>(0.0, 0.0, 1.0), average, length(average) > 1e-4));
    return vec4<f32>(n * 0.5 + 0.5, 1.0);
}
// ANCHOR_END: normal
