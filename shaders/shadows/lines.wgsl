// Chapter 10: lines drawn over the finished picture: the collision boxes
// and the light's box. Already in display colours, so they are drawn after
// tone mapping, with no depth test: they show through everything.

struct Lines {
    view_proj: mat4x4<f32>,
};
@group(0) @binding(0) var<uniform> lines: Lines;

struct LineVertex {
    @location(0) position: vec3<f32>,
    @location(1) colour: vec4<f32>,
};

struct Varyings {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) colour: vec4<f32>,
};

@vertex
fn vs_line(vertex: LineVertex) -> Varyings {
    return Varyings(lines.view_proj * vec4<f32>(vertex.position, 1.0), vertex.colour);
}

@fragment
fn fs_line(in: Varyings) -> @location(0) vec4<f32> {
    return in.colour;
}
