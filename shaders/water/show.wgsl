// Chapter 07's `reflection` and `refraction` views: one of the water's
// pictures, stretched over the whole screen.

@group(0) @binding(0) var picture: texture_2d<f32>;
@group(0) @binding(1) var picture_sampler: sampler;

struct ShowOutput {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) uv: vec2<f32>,
};

@vertex
fn vs_show(@builtin(vertex_index) index: u32) -> ShowOutput {
    let corner = vec2<f32>(f32((index << 1u) & 2u), f32(index & 2u));
    return ShowOutput(vec4<f32>(corner * 2.0 - 1.0, 0.0, 1.0), vec2<f32>(corner.x, 1.0 - corner.y));
}

@fragment
fn fs_show(in: ShowOutput) -> @location(0) vec4<f32> {
    return textureSample(picture, picture_sampler, in.uv);
}
