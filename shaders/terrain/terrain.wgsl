// Lets a vertex shader write @builtin(clip_distances); only used under
// #ifdef CLIP_DISTANCES, which is defined when the device has the feature.
enable clip_distances;

// Chapter 03: a height-map terrain drawn as patches of one grid, each at
// the level of detail its distance asks for.
// A vertex carries nothing: its place in the grid comes from its index, the
// patch's place and level from the instance, its height from a texture.
// Later chapters `#import terrain::{...}` to draw the same ground.
#define_import_path terrain

struct Globals {
    view_proj: mat4x4<f32>,
    // The eye the patches were chosen for (and morph by).
    eye: vec4<f32>,
    // xyz: unit vector towards the sun; w: its strength, 1 by day, 0 at night.
    sun: vec4<f32>,
    // x: chunks per side, y: quads per chunk side, z: view (0 shaded,
    // 1 wireframe, 2 normals, 3 levels), w: samples per side.
    grid: vec4<u32>,
    // x: metres between samples, y: the terrain's height scale.
    scale: vec4<f32>,
    // A clip plane (n, d): fragments where n · p + d < 0 are thrown away.
    // (0, 0, 0, 1) keeps everything; chapter 07's water uses it.
    clip: vec4<f32>,
    // x: metres to the end of level 0's range (level L's ends 2^L times
    // further), y: the part of a range after which a level morphs,
    // z: the root's level, which never morphs.
    lod: vec4<f32>,
};
@group(0) @binding(0) var<uniform> globals: Globals;
// One 32-bit height per sample, read exactly (never filtered).
@group(0) @binding(1) var heights: texture_2d<f32>;
// Each sample's normal, x and z in two signed bytes, filtered between samples.
@group(0) @binding(2) var normals: texture_2d<f32>;
@group(0) @binding(3) var normal_sampler: sampler;

// Quads along one side of every patch.
const PATCH_QUADS: u32 = 32u;

struct VertexOutput {
    @builtin(position) clip_position: vec4<f32>,
#ifdef CLIP_DISTANCES
    // Where the GPU has the feature, it clips against the plane itself.
    @builtin(clip_distances) clip_distances: array<f32, 1>,
#endif
    @location(0) world_position: vec3<f32>,
    // The vertex's place in its level's grid: whole numbers on the lines
    // of the drawn cells, for the wireframe.
    @location(1) cell: vec2<f32>,
    // The patch's level, and how far its vertex has morphed into the next.
    @location(2) @interpolate(flat) level: u32,
    @location(3) morph: f32,
};

// What the fragment shader reads: the same locations, without the clip
// distances, which only a vertex shader may write.
struct FragmentInput {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) world_position: vec3<f32>,
    @location(1) cell: vec2<f32>,
    @location(2) @interpolate(flat) level: u32,
    @location(3) morph: f32,
};

// ANCHOR: vs_main
@vertex
fn vs_main(
    @builtin(vertex_index) vertex_index: u32,
    // Per instance: the patch's first sample (xy) and its level (z).
    @location(0) this_patch: vec3<u32>,
) -> VertexOutput {
    return terrain_vertex(vertex_index, this_patch);
}
// ANCHOR_END: vs_main

fn height_at(sample: vec2<u32>) -> f32 {
    return textureLoad(heights, min(sample, vec2<u32>(globals.grid.w - 1u)), 0).r;
}

// ANCHOR: morph_factor
// How far a vertex of `level`, `distance` metres from the eye, has turned
// into the next level: 0 until the morph starts, 1 at the range's end.
fn morph_factor(level: u32, distance: f32) -> f32 {
    if f32(level) >= globals.lod.z {
        return 0.0;
    }
    let end = globals.lod.x * f32(1u << level);
    let start = globals.lod.y * end;
    return clamp((distance - start) / (end - start), 0.0, 1.0);
}
// ANCHOR_END: morph_factor

// ANCHOR: terrain_vertex
fn terrain_vertex(vertex_index: u32, this_patch: vec3<u32>) -> VertexOutput {
    let side = PATCH_QUADS + 1u;
    let local = vec2<u32>(vertex_index % side, vertex_index / side);
    let level = this_patch.z;
    let step = 1u << level;
    var sample = vec2<f32>(this_patch.xy + local * step);
    let height = height_at(vec2<u32>(sample));
    let unmorphed = vec3<f32>(sample.x * globals.scale.x, height, sample.y * globals.scale.x);
    let k = morph_factor(level, distance(unmorphed, globals.eye.xyz));

    // ANCHOR: slide
    // A vertex at an odd place in the grid is one the next level does not
    // have. As it morphs it slides onto its even neighbour (one step back
    // along each odd axis), taking that neighbour's height with it; fully
    // morphed, it sits exactly on that vertex, the triangles it made fold
    // flat, and what is left is the next level's mesh, vertex for vertex:
    // nothing to pop when the level changes, no gap against a coarser
    // neighbour, not even a pixel.
    let odd = vec2<f32>(local % 2u);
    var y = height;
    if k > 0.0 && odd.x + odd.y > 0.0 {
        let neighbour = sample - odd * f32(step);
        sample -= odd * f32(step) * k;
        y = mix(height, height_at(vec2<u32>(neighbour)), k);
    }
    // ANCHOR_END: slide
    let world = vec3<f32>(sample.x * globals.scale.x, y, sample.y * globals.scale.x);

    var out: VertexOutput;
    out.clip_position = globals.view_proj * vec4<f32>(world, 1.0);
    out.world_position = world;
    out.cell = sample / f32(step);
    out.level = level;
    out.morph = k;
#ifdef CLIP_DISTANCES
    out.clip_distances[0] = plane_distance(world);
#endif
    return out;
}
// ANCHOR_END: terrain_vertex

// ANCHOR: normal
// The ground's normal under a point, from the normal map: filtered between
// the four samples around it, so it is the same at every level of detail.
fn ground_normal(world_xz: vec2<f32>) -> vec3<f32> {
    let uv = (world_xz / globals.scale.x + 0.5) / f32(globals.grid.w);
    let xz = textureSampleLevel(normals, normal_sampler, uv, 0.0).rg;
    return normalize(vec3<f32>(xz.x, sqrt(max(1.0 - dot(xz, xz), 0.0)), xz.y));
}
// ANCHOR_END: normal

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

// ANCHOR: lit
// Lambert's cosine law for the sun, plus ambient light from the sky, both
// fading as the sun sets (some ambient stays: starlight).
fn lit(colour: vec3<f32>, normal: vec3<f32>) -> vec3<f32> {
    let strength = globals.sun.w;
    let ambient = 0.05 + 0.15 * strength;
    return colour * (ambient + 0.9 * strength * max(dot(normal, globals.sun.xyz), 0.0));
}
// ANCHOR_END: lit

// Lines along the drawn cells and their diagonals, a pixel wide at any
// distance, fading out as cells shrink from 1 / WIRE_FADE_START = 2.5 pixels
// across to 1 / WIRE_FADE_END = 1.4 (denser lines would only paint the
// ground pale). `fwidth(cell)` is cells a pixel, the inverse of a cell's
// width in pixels.
const WIRE_FADE_START: f32 = 0.4;
const WIRE_FADE_END: f32 = 0.7;
fn wire(cell: vec2<f32>) -> f32 {
    let width = fwidth(cell);
    let to_line = abs(fract(cell - 0.5) - 0.5) / width;
    let diagonal = cell.x + cell.y;
    let to_diagonal = abs(fract(diagonal - 0.5) - 0.5) / fwidth(diagonal);
    let nearest = min(min(to_line.x, to_line.y), to_diagonal);
    return (1.0 - clamp(nearest, 0.0, 1.0)) * (1.0 - smoothstep(WIRE_FADE_START, WIRE_FADE_END, max(width.x, width.y)));
}

// A colour for each chunk, from a hash of its index.
fn chunk_colour(chunk: u32) -> vec3<f32> {
    var x = chunk * 747796405u + 2891336453u;
    x = ((x >> ((x >> 28u) + 4u)) ^ x) * 277803737u;
    x = (x >> 22u) ^ x;
    return 0.25 + 0.6 * vec3<f32>(f32(x & 255u), f32((x >> 8u) & 255u), f32((x >> 16u) & 255u)) / 255.0;
}

// ANCHOR: level_colour
// A colour per level of detail, turning into the next level's as the
// vertices morph: the `lod-levels` and `quadtree` views.
fn level_colour(level: u32, morph: f32) -> vec3<f32> {
    let palette = array<vec3<f32>, 8>(
        vec3<f32>(0.90, 0.25, 0.20), vec3<f32>(0.95, 0.65, 0.15), vec3<f32>(0.85, 0.85, 0.25),
        vec3<f32>(0.35, 0.75, 0.30), vec3<f32>(0.25, 0.65, 0.80), vec3<f32>(0.35, 0.40, 0.85),
        vec3<f32>(0.65, 0.35, 0.80), vec3<f32>(0.80, 0.80, 0.80),
    );
    let l = min(level, 6u);
    return mix(palette[l], palette[l + 1u], morph);
}
// ANCHOR_END: level_colour

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
    let n = ground_normal(in.world_position.xz);
    let shaded = lit(ground_colour(in.world_position.y, n), n);
    switch globals.grid.z {
        case 1u: {
            return vec4<f32>(mix(shaded * 0.5, vec3<f32>(1.0, 0.85, 0.55), wire(in.cell)), 1.0);
        }
        case 2u: {
            // Decoded so the picture shows n * 0.5 + 0.5 as stored in a normal map.
            return vec4<f32>(pow(n * 0.5 + 0.5, vec3<f32>(2.2)), 1.0);
        }
        case 3u: {
            return vec4<f32>(lit(level_colour(in.level, in.morph), n), 1.0);
        }
        default: {
            return vec4<f32>(shaded, 1.0);
        }
    }
}
