// Chapter 02: the depth buffer made visible.
// A full-screen triangle reads the depth the scene pass left behind and
// turns it into grey: black near the camera, white far away.
#import common::fullscreen::{FullscreenOutput, fullscreen_triangle}

struct DepthView {
    near: f32,
    far: f32,
    // Distance shown as white in the linear view, in metres.
    range: f32,
    // 1: show the stored value itself, 0: convert it back to a distance.
    raw: u32,
};
// Read as a plain float texture rather than `texture_depth_2d`, through a
// nearest sampler rather than `textureLoad`: WebGPU allows both, and it is
// the way that also works on WebGL2, whose GLSL cannot fetch texels from a
// depth texture declared as one, and which reads 0 from a depth texture
// unless the sampler it goes through filters with "nearest".
@group(0) @binding(0) var depth_buffer: texture_2d<f32>;
@group(0) @binding(1) var<uniform> params: DepthView;
@group(0) @binding(2) var nearest: sampler;

// One triangle over the whole screen (shaders/common/fullscreen.wgsl).
@vertex
fn vs_fullscreen(@builtin(vertex_index) index: u32) -> FullscreenOutput {
    return fullscreen_triangle(index, 0.0);
}

// ANCHOR: linearize
@fragment
fn fs_depth(@builtin(position) pixel: vec4<f32>) -> @location(0) vec4<f32> {
    // `pixel.xy` is the pixel's centre: the nearest texel is its own.
    let uv = pixel.xy / vec2<f32>(textureDimensions(depth_buffer));
    let stored = textureSampleLevel(depth_buffer, nearest, uv, 0.0).r;
    var grey = stored;
    if params.raw == 0u {
        // Invert the projection: stored = far (d - near) / ((far - near) d).
        let distance = params.near * params.far / (params.far - stored * (params.far - params.near));
        grey = clamp(distance / params.range, 0.0, 1.0);
    }
    // The target sRGB-encodes what we write; decode first so the grey on
    // screen is proportional to the value.
    return vec4<f32>(vec3<f32>(pow(grey, 2.2)), 1.0);
}
// ANCHOR_END: linearize
