// Chapter 10: the background, three pictures on planes standing further
// and further behind the level. Nothing here moves them: the camera's
// perspective makes a far plane slide past slower than a near one, which
// is all parallax is. Unlit, as the seed drew them, but tinted by the sky
// and hazed with distance, so they sit in the same light as the level.
#import lighting::lights::frame

// ANCHOR: layers
// 64 bytes, as LayersUniform in parallax.rs.
struct Layers {
    // rgb: the sky's colour at the horizon, which distance fades towards.
    horizon: vec4<f32>,
    // Per layer, near to far: how much haze (x), and (y) 1 to tint by depth.
    haze: vec4<f32>,
    tint_by_depth: vec4<u32>,
    padding: vec4<f32>,
};
@group(1) @binding(0) var picture: texture_2d<f32>;
@group(1) @binding(1) var picture_sampler: sampler;
@group(1) @binding(2) var<uniform> layers: Layers;

struct LayerVertex {
    @location(0) position: vec3<f32>,
    @location(1) uv: vec2<f32>,
    // 0 near, 1 middle, 2 far.
    @location(2) layer: u32,
};

struct Varyings {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) uv: vec2<f32>,
    @location(1) @interpolate(flat) layer: u32,
};

@vertex
fn vs_layer(vertex: LayerVertex) -> Varyings {
    return Varyings(frame.view_proj * vec4<f32>(vertex.position, 1.0), vertex.uv, vertex.layer);
}

// The layer's colour where its picture is `texel`: lit by the sky, hazed
// by distance, or tinted by depth for the `parallax` view.
fn layer_colour(texel: vec4<f32>, layer: u32) -> vec3<f32> {
    let light = frame.ambient.rgb * 2.0 + frame.sun_colour.rgb * 0.3;
    var colour = mix(texel.rgb * light, layers.horizon.rgb, layers.haze[layer]);
    if layers.tint_by_depth.x == 1u {
        let tints = array<vec3<f32>, 3>(vec3<f32>(1.0, 0.25, 0.2), vec3<f32>(0.25, 1.0, 0.3), vec3<f32>(0.3, 0.45, 1.0));
        colour = tints[layer] * (0.3 + 0.7 * dot(texel.rgb, vec3<f32>(0.3, 0.6, 0.1)));
    }
    return colour;
}

// With one sample a pixel: a cut-out. Where the picture is sky, draw
// nothing: the sky behind shows, and so do the layers behind this one,
// whatever order they are drawn in. Each pixel is all layer or all sky, so
// the outline is a staircase that multisampling cannot smooth: it is
// decided in the shader, not by a triangle's edge.
@fragment
fn fs_layer(in: Varyings) -> @location(0) vec4<f32> {
    let texel = textureSample(picture, picture_sampler, in.uv);
    if texel.a < 0.5 {
        discard;
    }
    return vec4<f32>(layer_colour(texel, in.layer), 1.0);
}

// ANCHOR: coverage
// With several samples a pixel: alpha to coverage. The pipeline turns the
// alpha written here into how many of the pixel's samples the fragment
// covers (a quarter of them at 0.25), so the outline is smoothed as a
// triangle's edge is. The picture's alpha blurs across a texel, several
// pixels wide up close; divided by how fast it changes from one pixel to
// the next (`fwidth`), it crosses from 0 to 1 within one pixel about the
// same 0.5 line the cut-out uses, so the outline stays as sharp.
@fragment
fn fs_layer_coverage(in: Varyings) -> @location(0) vec4<f32> {
    let texel = textureSample(picture, picture_sampler, in.uv);
    let coverage = clamp((texel.a - 0.5) / max(fwidth(texel.a), 1e-4) + 0.5, 0.0, 1.0);
    return vec4<f32>(layer_colour(texel, in.layer), coverage);
}
// ANCHOR_END: coverage
// ANCHOR_END: layers
