// Shared by every full-screen pass (debug views, the sky, post-processing):
// one triangle that covers the whole target, so each pixel is shaded once.
#define_import_path common::fullscreen

struct FullscreenOutput {
    @builtin(position) clip_position: vec4<f32>,
    // Texture coordinates of the pixel: (0, 0) at the top left, (1, 1) at
    // the bottom right.
    @location(0) uv: vec2<f32>,
};

// ANCHOR: fullscreen
// Vertices 0, 1, 2 land at (-1, -1), (3, -1) and (-1, 3) in clip space: a
// triangle twice the screen's size whose inside holds the whole screen.
// `depth` is the clip-space z of every pixel (the sky draws at 1, the far plane).
fn fullscreen_triangle(index: u32, depth: f32) -> FullscreenOutput {
    let corner = vec2<f32>(f32((index << 1u) & 2u), f32(index & 2u));
    let clip = corner * 2.0 - 1.0;
    return FullscreenOutput(vec4<f32>(clip, depth, 1.0), vec2<f32>(corner.x, 1.0 - corner.y));
}
// ANCHOR_END: fullscreen

// Clip-space x and y of a pixel from its texture coordinates.
fn uv_to_ndc(uv: vec2<f32>) -> vec2<f32> {
    return vec2<f32>(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0);
}
