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

@fragment
fn fs_layer(in: Varyings) -> @location(0) vec4<f32> {
    let texel = textureSample(picture, picture_sampler, in.uv);
    // Where the picture is sky, draw nothing: the sky behind shows, and so
    // do the layers behind this one, whatever order they are drawn in.
    if texel.a < 0.5 {
        discard;
    }
    let light = frame.ambient.rgb * 2.0 + frame.sun_colour.rgb * 0.3;
    var colour = mix(texel.rgb * light, layers.horizon.rgb, layers.haze[in.layer]);
    if layers.tint_by_depth.x == 1u {
        let tints = array<vec3<f32>, 3>(vec3<f32>(1.0, 0.25, 0.2), vec3<f32>(0.25, 1.0, 0.3), vec3<f32>(0.3, 0.45, 1.0));
        colour = tints[in.layer] * (0.3 + 0.7 * dot(texel.rgb, vec3<f32>(0.3, 0.6, 0.1)));
    }
    return vec4<f32>(colour, 1.0);
}
// ANCHOR_END: layers
