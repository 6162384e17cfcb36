// Lets a vertex shader write @builtin(clip_distances); only used under
// #ifdef CLIP_DISTANCES, which is defined when the device has the feature.
enable clip_distances;

// Chapter 04: exponential distance fog over chapter 03's terrain.
// The terrain module provides the vertices and the ground's colour; this
// file only decides how much of that colour survives the distance.
// Chapter 05's rocks `#import fog::{fog, visibility}` to stand in the same air.
#define_import_path fog
#import terrain::{globals, VertexOutput, FragmentInput, terrain_vertex, ground_normal, ground_colour, lit, clipped}

// ANCHOR: uniform
struct Fog {
    // Linear RGB: the sky's colour, which is also the clear colour.
    colour: vec4<f32>,
    // Per metre: how quickly the air thickens.
    density: f32,
    // The exponent: 1 is plain exponential fog, higher keeps the near
    // distance clearer and closes in faster further out.
    gradient: f32,
};
@group(1) @binding(0) var<uniform> fog: Fog;
// ANCHOR_END: uniform

@vertex
fn vs_main(@builtin(vertex_index) vertex_index: u32, @location(0) this_patch: vec3<u32>) -> VertexOutput {
    return terrain_vertex(vertex_index, this_patch);
}

// ANCHOR: fog
// How much of a surface `distance` metres away still shows through the air:
// 1 at the eye, falling towards 0.
fn visibility(distance: f32) -> f32 {
    return exp(-pow(distance * fog.density, fog.gradient));
}

@fragment
fn fs_main(in: FragmentInput) -> @location(0) vec4<f32> {
    if clipped(in.world_position) {
        discard;
    }
    let n = ground_normal(in.world_position.xz);
    let surface = lit(ground_colour(in.world_position.y, n), n);
    // Distance per fragment, not per vertex: see the chapter's text.
    let distance = length(in.world_position - globals.eye.xyz);
    return vec4<f32>(mix(fog.colour.rgb, surface, visibility(distance)), 1.0);
}
// ANCHOR_END: fog
