// Chapter 10: the lantern's shadow pass, run once for each face of its
// cube. The scene's vertices, placed as the main pass places them, seen
// through the face's 90° square; the fragment stores its distance from
// the light over the light's range, not the face's own depth, so that a
// lookup compares the same quantity whichever face the GPU reads.
#import textures::surface::{Vertex, Instance, place}

// ANCHOR: caster
// One face: world to its clip space (point_shadow.rs: `CubeFace::view_proj`),
// and the light, xyz where it is and w its range. Each face's copy sits at
// its own offset of one buffer, chosen per pass (a dynamic offset).
struct Face {
    view_proj: mat4x4<f32>,
    light: vec4<f32>,
};
@group(0) @binding(0) var<uniform> face: Face;

struct Cast {
    @builtin(position) clip: vec4<f32>,
    @location(0) world: vec3<f32>,
};

@vertex
fn vs_point_caster(vertex: Vertex, instance: Instance) -> Cast {
    let world = place(vertex, instance).world;
    return Cast(face.view_proj * vec4<f32>(world, 1.0), world);
}

// The depth test keeps the nearest surface along each texel's ray, which
// the distance finds as well as depth would: along one ray from the
// light, the two grow together.
@fragment
fn fs_point_caster(fragment: Cast) -> @builtin(frag_depth) f32 {
    return length(fragment.world - face.light.xyz) / face.light.w;
}
// ANCHOR_END: caster
