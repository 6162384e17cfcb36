// Chapter 10: the shadow map itself, full screen: near the sun dark, far
// light, stretched over the depths the visible level spans so that its
// shapes stand out.
#import common::fullscreen::{FullscreenOutput, fullscreen_triangle}

struct Stretch {
    // x: the depth shown black, y: the depth shown white, z: the target's
    // width over its height.
    range: vec4<f32>,
};
// The depth map read as plain floats through a nearest sampler, as
// chapter 02's depth view does: OpenGL's GLSL cannot fetch the texels of a
// texture declared as depth.
@group(0) @binding(0) var shadow_map: texture_2d<f32>;
@group(0) @binding(1) var<uniform> stretch: Stretch;
@group(0) @binding(2) var nearest: sampler;

@vertex
fn vs_fullscreen(@builtin(vertex_index) index: u32) -> FullscreenOutput {
    return fullscreen_triangle(index, 0.0);
}

@fragment
fn fs_depth(in: FullscreenOutput) -> @location(0) vec4<f32> {
    let size = vec2<f32>(textureDimensions(shadow_map));
    // The map is square and the screen is wide: the whole map, full height,
    // with bars on either side.
    let uv = vec2<f32>(0.5 + (in.uv.x - 0.5) * stretch.range.z, in.uv.y);
    if uv.x < 0.0 || uv.x > 1.0 {
        return vec4<f32>(0.02, 0.03, 0.06, 1.0);
    }
    let texel = clamp(vec2<i32>(uv * size), vec2<i32>(0), vec2<i32>(size) - 1);
    let depth = textureSampleLevel(shadow_map, nearest, (vec2<f32>(texel) + 0.5) / size, 0.0).r;
    let shade = clamp((depth - stretch.range.x) / (stretch.range.y - stretch.range.x), 0.0, 1.0);
    return vec4<f32>(vec3<f32>(shade), 1.0);
}
