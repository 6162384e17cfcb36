// Lets a vertex shader write @builtin(clip_distances); only used under
// #ifdef CLIP_DISTANCES, which is defined when the device has the feature.
enable clip_distances;

// Chapter 03: a chunked height-map terrain.
// Vertices carry only a height and a packed normal; x and z come from the
// vertex's place in its chunk and the chunk's place in the world.
// Later chapters `#import terrain::{...}` to draw the same ground.
#define_import_path terrain

struct Globals {
    view_proj: mat4x4<f32>,
    eye: vec4<f32>,
    // xyz: unit vector towards the sun; w: its strength, 1 by day, 0 at night.
    sun: vec4<f32>,
    // x: chunks per side, y: quads per chunk side, z: view (0 shaded,
    // 1 wireframe, 2 normals, 3 chunks).
    grid: vec4<u32>,
    // x: metres between samples, y: the terrain's height scale.
    scale: vec4<f32>,
    // A clip plane (n, d): fragments where n · p + d < 0 are thrown away.
    // (0, 0, 0, 1) keeps everything; chapter 07's water uses it.
    clip: vec4<f32>,
};
@group(0) @binding(0) var<uniform> globals: Globals;
// One flag per chunk for the `chunks` view: 1 if culling kept it.
@group(0) @binding(1) var<storage, read> chunk_drawn: array<u32>;

struct VertexOutput {
    @builtin(position) clip_position: vec4<f32>,
#ifdef CLIP_DISTANCES
    // Where the GPU has the feature, it clips against the plane itself.
    @builtin(clip_distances) clip_distances: array<f32, 1>,
#endif
    @location(0) world_position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    // Grid coordinates in samples, for the wireframe.
    @location(2) grid: vec2<f32>,
    @location(3) @interpolate(flat) chunk: u32,
};

// What the fragment shader reads: the same locations, without the clip
// distances, which only a vertex shader may write.
struct FragmentInput {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) world_position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) grid: vec2<f32>,
    @location(3) @interpolate(flat) chunk: u32,
};

// ANCHOR: vs_main
@vertex
fn vs_main(
    @builtin(vertex_index) vertex_index: u32,
    // Each chunk is drawn as instance `chunk` of itself, so the index says which.
    @builtin(instance_index) chunk: u32,
    @location(0) height: f32,
    @location(1) normal: vec4<f32>,
) -> VertexOutput {
    return terrain_vertex(vertex_index, chunk, height, normal);
}

fn terrain_vertex(vertex_index: u32, chunk: u32, height: f32, normal: vec4<f32>) -> VertexOutput {
    let side = globals.grid.y + 1u;
    // vertex_index counts from the chunk's base vertex, in whole chunks.
    let local = vertex_index % (side * side);
    let chunk_xz = vec2<u32>(chunk % globals.grid.x, chunk / globals.grid.x);
    let grid = chunk_xz * globals.grid.y + vec2<u32>(local % side, local / side);
    let world = vec3<f32>(f32(grid.x) * globals.scale.x, height, f32(grid.y) * globals.scale.x);

    var out: VertexOutput;
    out.clip_position = globals.view_proj * vec4<f32>(world, 1.0);
    out.world_position = world;
    out.normal = normal.xyz;
    out.grid = vec2<f32>(grid);
    out.chunk = chunk;
#ifdef CLIP_DISTANCES
    out.clip_distances[0] = plane_distance(world);
#endif
    return out;
}
// ANCHOR_END: vs_main

// ANCHOR: colour
// Martian ground: dark dust in the valleys, ochre on the slopes, pale dust
// on the heights, bare rock wherever it is too steep for dust to stay.
fn ground_colour(height: f32, normal: vec3<f32>) -> vec3<f32> {
    let h = height / globals.scale.y; // about -1..1
    let slope = 1.0 - normal.y;       // 0 flat, 1 vertical
    let valley = vec3<f32>(0.20, 0.08, 0.04);
    let plain = vec3<f32>(0.50, 0.22, 0.09);
    let heights = vec3<f32>(0.68, 0.45, 0.30);
    let rock = vec3<f32>(0.30, 0.20, 0.15);
    var colour = mix(valley, plain, smoothstep(-0.6, 0.0, h));
    colour = mix(colour, heights, smoothstep(0.25, 0.75, h));
    return mix(colour, rock, smoothstep(0.18, 0.35, slope));
}
// ANCHOR_END: colour

// Lambert's cosine law for the sun, plus ambient light from the sky, both
// fading as the sun sets (some ambient stays: starlight).
fn lit(colour: vec3<f32>, normal: vec3<f32>) -> vec3<f32> {
    let strength = globals.sun.w;
    let ambient = 0.05 + 0.15 * strength;
    return colour * (ambient + 0.9 * strength * max(dot(normal, globals.sun.xyz), 0.0));
}

// Lines along the grid and the quads' diagonals, a pixel wide at any
// distance, fading out where cells get smaller than 8 pixels (denser lines
// would only paint the ground pale).
fn wire(grid: vec2<f32>) -> f32 {
    let width = fwidth(grid);
    let to_line = abs(fract(grid - 0.5) - 0.5) / width;
    let diagonal = grid.x + grid.y;
    let to_diagonal = abs(fract(diagonal - 0.5) - 0.5) / fwidth(diagonal);
    let nearest = min(min(to_line.x, to_line.y), to_diagonal);
    return (1.0 - clamp(nearest, 0.0, 1.0)) * (1.0 - smoothstep(0.125, 0.25, max(width.x, width.y)));
}

// A colour for each chunk, from a hash of its index.
fn chunk_colour(chunk: u32) -> vec3<f32> {
    var x = chunk * 747796405u + 2891336453u;
    x = ((x >> ((x >> 28u) + 4u)) ^ x) * 277803737u;
    x = (x >> 22u) ^ x;
    return 0.25 + 0.6 * vec3<f32>(f32(x & 255u), f32((x >> 8u) & 255u), f32((x >> 16u) & 255u)) / 255.0;
}

// ANCHOR: clip
// How far a point is on the kept side of the clip plane (negative: cut).
fn plane_distance(world_position: vec3<f32>) -> f32 {
    return dot(world_position, globals.clip.xyz) + globals.clip.w;
}

// True where the clip plane cuts this fragment away and the fragment shader
// must discard it. With clip distances the rasteriser has already done it.
fn clipped(world_position: vec3<f32>) -> bool {
#ifdef CLIP_DISTANCES
    return false;
#else
    return plane_distance(world_position) < 0.0;
#endif
}
// ANCHOR_END: clip

@fragment
fn fs_main(in: FragmentInput) -> @location(0) vec4<f32> {
    if clipped(in.world_position) {
        discard;
    }
    let n = normalize(in.normal);
    let shaded = lit(ground_colour(in.world_position.y, n), n);
    switch globals.grid.z {
        case 1u: {
            return vec4<f32>(mix(shaded * 0.5, vec3<f32>(1.0, 0.85, 0.55), wire(in.grid)), 1.0);
        }
        case 2u: {
            // Decoded so the picture shows n * 0.5 + 0.5 as stored in a normal map.
            return vec4<f32>(pow(n * 0.5 + 0.5, vec3<f32>(2.2)), 1.0);
        }
        case 3u: {
            var colour = vec3<f32>(0.06);
            if chunk_drawn[in.chunk] == 1u {
                colour = chunk_colour(in.chunk);
            }
            return vec4<f32>(lit(colour, n), 1.0);
        }
        default: {
            return vec4<f32>(shaded, 1.0);
        }
    }
}
