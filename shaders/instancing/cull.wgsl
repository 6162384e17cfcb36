// Chapter 05: the course's first compute shader. One invocation per rock:
// is any of it in the picture, and how many pixels across is it? A rock
// that shows is appended to the list of its level of detail, and counted
// straight into that level's indirect draw, which the render pass then
// draws without the CPU ever learning how many there were.
#import instancing::rock::{Rock, Culling, bounding_sphere, pixels_across}

// ANCHOR: bindings
// `wgpu::util::DrawIndexedIndirectArgs`, as the GPU reads it for an
// indirect draw. The count of instances is an atomic: thousands of
// invocations add to it at once.
struct DrawArgs {
    index_count: u32,
    instance_count: atomic<u32>,
    first_index: u32,
    base_vertex: i32,
    first_instance: u32,
};

// Group 0: this picture's own (each picture of a frame has its own lists).
// `culling` is read-only storage, not a uniform, though it would fit one:
// the shader branches on it, and lavapipe keeps a new compiled copy of a
// shader that branches on a uniform every time it is bound (chapter 08).
@group(0) @binding(0) var<storage, read> culling: Culling;
@group(0) @binding(1) var<storage, read_write> lists: array<u32>;
@group(0) @binding(2) var<storage, read_write> draws: array<DrawArgs, 3>;
// Group 1: every rock, the same buffer the instanced draws read.
@group(1) @binding(0) var<storage, read> rocks: array<Rock>;
// ANCHOR_END: bindings

// ANCHOR: in_view
// Whether any of `sphere` is in the picture. In the camera's own space the
// frustum is symmetric: a side plane passes through the eye, tilted from
// straight ahead by half the field of view, and the sphere is out when its
// centre lies further than its radius beyond it.
fn in_view(sphere: vec4<f32>) -> bool {
    let p = (culling.view * vec4<f32>(sphere.xyz, 1.0)).xyz;
    let depth = -p.z;
    let r = sphere.w;
    if depth + r < culling.frustum.z || depth - r > culling.frustum.w {
        return false;
    }
    // Beyond the side planes: |x| − depth · tan is the distance along x
    // past the plane, and the plane's distance is that times its cosine;
    // compared with r, the cosine moves to the other side as √(1 + tan²).
    let tangents = culling.frustum.xy;
    let beyond = abs(p.xy) - depth * tangents;
    if any(beyond > r * sqrt(1.0 + tangents * tangents)) {
        return false;
    }
    // Wholly on the cut side of the picture's clip plane (chapter 07's water).
    let clip = culling.clip;
    return dot(clip.xyz, sphere.xyz) + clip.w >= -r * length(clip.xyz);
}
// ANCHOR_END: in_view

// ANCHOR: cull_rocks
const WORKGROUP_SIZE: u32 = 64u;

@compute @workgroup_size(64)
fn cull_rocks(@builtin(global_invocation_id) id: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>) {
    // The dispatch is a grid of workgroups, rows of at most the device's
    // limit per dimension: row id.y starts after id.y whole rows.
    let index = id.y * groups.x * WORKGROUP_SIZE + id.x;
    if index >= culling.counts.x {
        return;
    }
    let sphere = bounding_sphere(rocks[index], culling.sphere);
    if !in_view(sphere) {
        return;
    }
    let pixels = pixels_across(sphere, culling.eye);
    var level = 0u;
    if pixels < culling.sizes.z {
        return; // less than a pixel: nothing to see
    } else if pixels < culling.sizes.y {
        level = 2u;
    } else if pixels < culling.sizes.x {
        level = 1u;
    }
    // ANCHOR: append
    // atomicAdd returns the count before this invocation's 1: a slot of the
    // level's list no other invocation gets.
    let slot = atomicAdd(&draws[level].instance_count, 1u);
    lists[level * culling.counts.y + slot] = index;
    // ANCHOR_END: append
}
// ANCHOR_END: cull_rocks
