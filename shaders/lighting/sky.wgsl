// Chapter 08: the sky over the city, a gradient from the horizon to the
// zenith with the sun in it, drawn at the far plane behind everything
// (chapter 06's trick). A piece of its own (`CitySky`), so that chapter 09
// draws the same sky over its textured city.
#import lighting::lights::frame
#import lighting::sky_light::sky_radiance
#import common::fullscreen::{FullscreenOutput, fullscreen_triangle, uv_to_ndc}

struct Sky {
    clip_to_world: mat4x4<f32>,
    horizon: vec4<f32>,
    zenith: vec4<f32>,
};
@group(1) @binding(0) var<uniform> sky: Sky;

@vertex
fn vs_fullscreen(@builtin(vertex_index) index: u32) -> FullscreenOutput {
    return fullscreen_triangle(index, 1.0);
}

@fragment
fn fs_sky(in: FullscreenOutput) -> @location(0) vec4<f32> {
    if frame.options.w == 1u {
        return vec4<f32>(0.0, 0.0, 0.0, 1.0);
    }
    let far = sky.clip_to_world * vec4<f32>(uv_to_ndc(in.uv), 1.0, 1.0);
    let direction = normalize(far.xyz / far.w);
    // Below the horizon, the horizon's colour: the city and its fields
    // stand in front of it.
    var colour = sky_radiance(direction, sky.horizon.rgb, sky.zenith.rgb, sky.horizon.rgb);
    let towards_sun = max(dot(direction, frame.sun_direction.xyz), 0.0);
    colour += frame.sun_colour.rgb * (8.0 * smoothstep(0.9995, 0.9998, towards_sun) + 0.15 * pow(towards_sun, 64.0));
    return vec4<f32>(colour, 1.0);
}
