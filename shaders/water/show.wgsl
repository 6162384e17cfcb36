// Chapter 07's `reflection` and `refraction` views: one of the water's
// pictures, stretched over the whole screen.
#import common::fullscreen::{FullscreenOutput, fullscreen_triangle}

@group(0) @binding(0) var picture: texture_2d<f32>;
@group(0) @binding(1) var picture_sampler: sampler;

@vertex
fn vs_fullscreen(@builtin(vertex_index) index: u32) -> FullscreenOutput {
    return fullscreen_triangle(index, 0.0);
}

@fragment
fn fs_show(in: FullscreenOutput) -> @location(0) vec4<f32> {
    return textureSample(picture, picture_sampler, in.uv);
}
