// Chapter 11: islands, coloured by height from a gradient: sand at the
// waterline, grass, then rock towards the summit. Lit by the sun through
// chapter 08's frame, fogged into the sky like the sea.
#import lighting::lights::frame
#import voronoi_water::atmosphere::{fogged, island_colour}

struct IslandOutput {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) world: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) height: f32,
};

// ANCHOR: island
@vertex
fn vs_island(
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    // How high the vertex is, as a fraction of the island's summit.
    @location(2) height: f32,
    // Where this copy of the island stands.
    @location(3) offset: vec3<f32>,
) -> IslandOutput {
    let world = position + offset;
    return IslandOutput(frame.view_proj * vec4<f32>(world, 1.0), world, normal, height);
}

@fragment
fn fs_island(in: IslandOutput) -> @location(0) vec4<f32> {
    let n = normalize(in.normal);
    let albedo = island_colour(in.height);
    let sun = max(dot(n, frame.sun_direction.xyz), 0.0);
    let colour = albedo * (frame.ambient.rgb + frame.sun_colour.rgb * sun);
    return vec4<f32>(fogged(colour, in.world), 1.0);
}
// ANCHOR_END: island
