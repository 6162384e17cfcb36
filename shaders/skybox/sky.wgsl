// Chapter 06: a sky from two cube maps, day and night, drawn behind
// everything in one full-screen triangle, with the sun drawn where the
// light comes from.
#import common::fullscreen::{FullscreenOutput, fullscreen_triangle, uv_to_ndc}

// ANCHOR: uniforms
struct Sky {
    // Clip space back to a world direction: the inverse of the camera's
    // projection times its view without the translation, so the sky never
    // comes closer however far the camera flies.
    clip_to_world: mat4x4<f32>,
    // World directions into each cube map: the day atmosphere drifts slowly
    // about the vertical, keeping its horizon level; the stars turn with
    // the sun about the celestial axis.
    world_to_day: mat4x4<f32>,
    world_to_stars: mat4x4<f32>,
    // xyz: towards the sun (the terrain's light), w: how much day shows.
    sun: vec4<f32>,
};
@group(0) @binding(0) var<uniform> sky: Sky;
@group(0) @binding(1) var day_sky: texture_cube<f32>;
@group(0) @binding(2) var night_sky: texture_cube<f32>;
@group(0) @binding(3) var sky_sampler: sampler;
// ANCHOR_END: uniforms

// ANCHOR: vs_sky
// A triangle that covers the screen, at depth 1: the far plane. With the
// depth test set to LessEqual and the depth buffer cleared to 1, the sky
// shows only where nothing nearer was drawn.
@vertex
fn vs_fullscreen(@builtin(vertex_index) index: u32) -> FullscreenOutput {
    return fullscreen_triangle(index, 1.0);
}
// ANCHOR_END: vs_sky

// ANCHOR: fs_sky
@fragment
fn fs_sky(in: FullscreenOutput) -> @location(0) vec4<f32> {
    // The pixel's point on the far plane, turned back into a world direction.
    let far = sky.clip_to_world * vec4<f32>(uv_to_ndc(in.uv), 1.0, 1.0);
    let direction = normalize(far.xyz / far.w);
    var day = textureSample(day_sky, sky_sampler, (sky.world_to_day * vec4<f32>(direction, 0.0)).xyz).rgb;
    let night = textureSample(night_sky, sky_sampler, (sky.world_to_stars * vec4<f32>(direction, 0.0)).xyz).rgb;

    // ANCHOR: sun_disc
    // The sun: a small white disc in a wide blue halo. Martian dust scatters
    // blue light forward, around the sun: blue sunsets, the opposite of Earth.
    let towards_sun = max(dot(direction, sky.sun.xyz), 0.0);
    day = mix(day, vec3<f32>(0.30, 0.42, 0.62), 0.75 * pow(towards_sun, 40.0));
    let disc = smoothstep(cos(radians(0.9)), cos(radians(0.6)), towards_sun);
    day = mix(day, vec3<f32>(1.0, 0.96, 0.88), disc);
    // ANCHOR_END: sun_disc
    return vec4<f32>(mix(night, day, sky.sun.w), 1.0);
}
// ANCHOR_END: fs_sky
