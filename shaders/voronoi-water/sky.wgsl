// Chapter 11: the sky, from a gradient looked up by the sun's height and
// the direction of each pixel, with the sun (or the moon) as a disc that
// is bright enough to bloom.
#import common::fullscreen::{FullscreenOutput, fullscreen_triangle, uv_to_ndc}
#import voronoi_water::atmosphere::{atmosphere, sky_colour, disc_colour}

@vertex
fn vs_fullscreen(@builtin(vertex_index) index: u32) -> FullscreenOutput {
    return fullscreen_triangle(index, 1.0);
}

// ANCHOR: sky
@fragment
fn fs_sky(in: FullscreenOutput) -> @location(0) vec4<f32> {
    let far = atmosphere.inverse_view_proj * vec4<f32>(uv_to_ndc(in.uv), 1.0, 1.0);
    let direction = normalize(far.xyz / far.w - atmosphere.eye.xyz);
    var colour = sky_colour(direction);
    // The sun by day; by night the moon, opposite it.
    var towards = atmosphere.sun.xyz;
    if atmosphere.sun.w < 0.5 {
        towards = -towards;
    }
    let c = dot(direction, towards);
    let disc = smoothstep(atmosphere.fog.y - 0.00002, atmosphere.fog.y + 0.00002, c);
    // A halo around the disc, then the disc itself, far brighter than the
    // sky: what bloom spreads.
    let halo = pow(max(c, 0.0), 600.0) * 0.6;
    colour += disc_colour() * (halo + disc * 12.0) * step(0.0, direction.y + 0.01);
    return vec4<f32>(colour, 1.0);
}
// ANCHOR_END: sky
