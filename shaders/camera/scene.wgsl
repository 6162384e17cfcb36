// Chapter 02: model, view and projection.
// Each object's vertices go model → world (its own matrix), then
// world → clip (the camera's view-projection matrix).

// ANCHOR: uniforms
struct Camera {
    view_proj: mat4x4<f32>,
    // xyz: the eye position in world space.
    eye: vec4<f32>,
};
@group(0) @binding(0) var<uniform> camera: Camera;

struct Object {
    model: mat4x4<f32>,
    // The inverse transpose of `model`: keeps normals perpendicular to the
    // surface when the model is scaled unevenly.
    normal_matrix: mat4x4<f32>,
    // rgb: linear colour; a: strength of the ground's checker pattern.
    color: vec4<f32>,
};
@group(1) @binding(0) var<uniform> object: Object;
// ANCHOR_END: uniforms

struct VertexInput {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) uv: vec2<f32>,
};

struct VertexOutput {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) world_position: vec3<f32>,
    @location(1) normal: vec3<f32>,
};

// ANCHOR: vs_main
@vertex
fn vs_main(in: VertexInput) -> VertexOutput {
    let world = object.model * vec4<f32>(in.position, 1.0);
    var out: VertexOutput;
    out.clip_position = camera.view_proj * world;
    out.world_position = world.xyz;
    out.normal = (object.normal_matrix * vec4<f32>(in.normal, 0.0)).xyz;
    return out;
}
// ANCHOR_END: vs_main

// ANCHOR: fs_main
@fragment
fn fs_main(in: VertexOutput) -> @location(0) vec4<f32> {
    // Just enough light to read the shapes: a fixed sun, Lambert's cosine
    // and a constant ambient term. Chapter 08 does lighting properly.
    let sun = normalize(vec3<f32>(0.4, 0.8, 0.3));
    let n = normalize(in.normal);
    let light = 0.25 + 0.75 * max(dot(n, sun), 0.0);

    // One-metre checker squares on the ground, so motion is easy to see.
    let cell = vec2<i32>(floor(in.world_position.xz));
    let checker = f32((cell.x + cell.y) & 1);
    let color = object.color.rgb * (1.0 - 0.35 * object.color.a * checker);
    return vec4<f32>(color * light, 1.0);
}
// ANCHOR_END: fs_main

// The `normals` view: world-space normals as colours (x → red, y → green,
// z → blue). The target sRGB-encodes whatever we write, which is right for
// light but not for data, so the value is decoded first (≈ x^2.2) and the
// picture shows n * 0.5 + 0.5 exactly as a normal map would store it.
@fragment
fn fs_normals(in: VertexOutput) -> @location(0) vec4<f32> {
    let encoded = normalize(in.normal) * 0.5 + 0.5;
    return vec4<f32>(pow(encoded, vec3<f32>(2.2)), 1.0);
}
