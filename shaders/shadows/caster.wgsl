// Chapter 10: the shadow pass. The scene's vertices, placed as the main
// pass places them, seen from the sun through its orthographic box; no
// fragment shader, because the depth is all this pass writes.
#import textures::surface::{Vertex, Instance, place}

// ANCHOR: caster
// The same matrix as `shadow.light_view_proj` in shadow.wgsl, in a group of
// its own: this pass draws into the shadow map, so it cannot also bind it.
@group(0) @binding(0) var<uniform> light_view_proj: mat4x4<f32>;

@vertex
fn vs_caster(vertex: Vertex, instance: Instance) -> @builtin(position) vec4<f32> {
    return light_view_proj * vec4<f32>(place(vertex, instance).world, 1.0);
}
// ANCHOR_END: caster
