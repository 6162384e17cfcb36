// Lets a vertex shader write @builtin(clip_distances); only used under
// #ifdef CLIP_DISTANCES, which is defined when the device has the feature.
enable clip_distances;

// Chapter 05: very many rocks from one mesh.
// Every rock is the same 60 vertices; what makes each one itself is 32
// bytes of instance data: where it stands, which way it faces, how it is
// stretched, and how light its stone is (`Rock`, in rock.wgsl).
#import terrain::{globals, lit, clipped, plane_distance, chunk_colour}
#import fog::{fog, visibility}
#import instancing::rock::{Rock, Culling, turn, bounding_sphere, pixels_across, kept_size}

// ANCHOR: rock_output
struct RockOutput {
    @builtin(position) clip_position: vec4<f32>,
#ifdef CLIP_DISTANCES
    @builtin(clip_distances) clip_distances: array<f32, 1>,
#endif
    @location(0) world_position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) shade: f32,
    // The terrain chunk the rock stands in: its group.
    @location(3) @interpolate(flat) chunk: u32,
    // Its level of detail: 0 the full rock, 1 and 2 coarser.
    @location(4) @interpolate(flat) level: u32,
};
// ANCHOR_END: rock_output

// What the fragment shader reads (clip distances are for vertex shaders only).
struct RockInput {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) world_position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) shade: f32,
    @location(3) @interpolate(flat) chunk: u32,
    @location(4) @interpolate(flat) level: u32,
};

// ANCHOR: rock_vertex
// The model matrix, never built: scale, turn about y, move.
fn rock_vertex(rock: Rock, position: vec3<f32>, normal: vec3<f32>) -> RockOutput {
    let yaw = rock.position_yaw.w;
    let world = turn(position * rock.scale_shade.xyz, yaw) + rock.position_yaw.xyz;
    var out: RockOutput;
    out.clip_position = globals.view_proj * vec4<f32>(world, 1.0);
    out.world_position = world;
    // The inverse transpose of (turn · scale) is (turn · 1/scale): chapter 02's
    // normal matrix, worked out by hand.
    out.normal = turn(normal / rock.scale_shade.xyz, yaw);
    out.shade = rock.scale_shade.w;
    // Chunks are grid.y quads of scale.x metres a side, grid.x to a row.
    let cell = vec2<u32>(max(rock.position_yaw.xz, vec2<f32>(0.0)) / (f32(globals.grid.y) * globals.scale.x));
    out.chunk = min(cell.y, globals.grid.x - 1u) * globals.grid.x + min(cell.x, globals.grid.x - 1u);
    out.level = 0u;
#ifdef CLIP_DISTANCES
    out.clip_distances[0] = plane_distance(world);
#endif
    return out;
}
// ANCHOR_END: rock_vertex

// ANCHOR: vs_instanced
// One draw call for all rocks: locations 3 and 4 step once per instance,
// not once per vertex, so each instance reads its own Rock.
@vertex
fn vs_instanced(
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(3) position_yaw: vec4<f32>,
    @location(4) scale_shade: vec4<f32>,
) -> RockOutput {
    return rock_vertex(Rock(position_yaw, scale_shade), position, normal);
}
// ANCHOR_END: vs_instanced

// ANCHOR: vs_single
// The comparison: one draw call per rock, each reading its Rock from a
// uniform at a dynamic offset, as chapter 02 placed its primitives.
@group(2) @binding(0) var<uniform> single: Rock;

@vertex
fn vs_single(@location(0) position: vec3<f32>, @location(1) normal: vec3<f32>) -> RockOutput {
    return rock_vertex(single, position, normal);
}
// ANCHOR_END: vs_single

// ANCHOR: vs_culled
// The rocks the compute pass kept, one level's list per draw: instance i
// of the draw is the rock whose index is the list's i-th entry. Every
// indirect draw starts at instance 0 (WebGPU need not start one anywhere
// else), so each level's list has a binding of its own.
@group(2) @binding(1) var<storage, read> kept: array<u32>;
@group(2) @binding(2) var<storage, read> culling: Culling;
// x: which level this draw is, for the `lod-levels` view.
@group(2) @binding(3) var<uniform> level: vec4<u32>;
@group(3) @binding(0) var<storage, read> rocks: array<Rock>;

@vertex
fn vs_culled(
    @builtin(instance_index) instance: u32,
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
) -> RockOutput {
    let rock = rocks[kept[instance]];
    // Between two pixels across and one, the rock shrinks to nothing about
    // the centre of its sphere, so it leaves the picture without a pop.
    let pixels = pixels_across(bounding_sphere(rock, culling.sphere), culling.eye);
    let centre = culling.sphere.xyz;
    var out = rock_vertex(rock, centre + (position - centre) * kept_size(pixels, culling.sizes), normal);
    out.level = level.x;
    return out;
}
// ANCHOR_END: vs_culled

@fragment
fn fs_main(in: RockInput) -> @location(0) vec4<f32> {
    if clipped(in.world_position) {
        discard;
    }
    let basalt = vec3<f32>(0.16, 0.09, 0.06) * (0.6 + 0.9 * in.shade);
    let surface = lit(basalt, normalize(in.normal));
    let distance = length(in.world_position - globals.eye.xyz);
    return vec4<f32>(mix(fog.colour.rgb, surface, visibility(distance)), 1.0);
}

// The floor of the cost: the same vertices, no lighting, no fog.
@fragment
fn fs_flat(in: RockInput) -> @location(0) vec4<f32> {
    return vec4<f32>(0.2, 0.1, 0.07, 1.0);
}

// The `rock-chunks` view: each rock in its group's colour, lit but without
// fog: a colour per chunk from a hash of the chunk's index (`chunk_colour`,
// which terrain.wgsl lends), so neighbouring groups differ.
@fragment
fn fs_groups(in: RockInput) -> @location(0) vec4<f32> {
    if clipped(in.world_position) {
        discard;
    }
    return vec4<f32>(lit(chunk_colour(in.chunk), normalize(in.normal)), 1.0);
}

// The `lod-levels` view: each rock in its level's colour, lit but without
// fog, so the far ones show: red the full rock, yellow the octahedron,
// blue the tetrahedron.
@fragment
fn fs_levels(in: RockInput) -> @location(0) vec4<f32> {
    if clipped(in.world_position) {
        discard;
    }
    var colours = array<vec3<f32>, 3>(vec3<f32>(0.8, 0.12, 0.08), vec3<f32>(0.85, 0.7, 0.1), vec3<f32>(0.15, 0.35, 0.9));
    return vec4<f32>(lit(colours[min(in.level, 2u)], normalize(in.normal)), 1.0);
}
