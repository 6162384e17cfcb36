// Chapter 01: the first triangle.
// Positions arrive already in clip space; each corner carries a colour that
// the rasteriser blends across the triangle before the fragment shader runs.

// ANCHOR: vertex
struct VertexInput {
    @location(0) position: vec2<f32>,
    @location(1) color: vec3<f32>,
};

struct VertexOutput {
    // Clip space: x and y from -1 to 1 across the target, z from 0 to 1.
    @builtin(position) clip_position: vec4<f32>,
    // Anything else the vertex shader outputs is interpolated per pixel.
    @location(0) color: vec3<f32>,
};

@vertex
fn vs_main(in: VertexInput) -> VertexOutput {
    var out: VertexOutput;
    out.clip_position = vec4<f32>(in.position, 0.0, 1.0);
    out.color = in.color;
    return out;
}
// ANCHOR_END: vertex

// ANCHOR: fragment
@fragment
fn fs_main(in: VertexOutput) -> @location(0) vec4<f32> {
    // `in.color` is already the blend of the three corners for this pixel.
    return vec4<f32>(in.color, 1.0);
}
// ANCHOR_END: fragment

// ANCHOR: flat
// The same triangle with interpolation switched off: every pixel takes the
// colour of the triangle's first ("provoking") vertex.
struct FlatOutput {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) @interpolate(flat) color: vec3<f32>,
};

@vertex
fn vs_flat(in: VertexInput) -> FlatOutput {
    return FlatOutput(vec4<f32>(in.position, 0.0, 1.0), in.color);
}

@fragment
fn fs_flat(in: FlatOutput) -> @location(0) vec4<f32> {
    return vec4<f32>(in.color, 1.0);
}
// ANCHOR_END: flat
