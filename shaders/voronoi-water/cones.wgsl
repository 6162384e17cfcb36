// Chapter 11: a Voronoi diagram by drawing cones (Hoff et al. 1999). Each
// site is the apex of a cone seen from above by an orthographic camera;
// a pixel's depth is its distance from the site, so the depth test keeps,
// at every pixel, the nearest site. The pixel stores that site's index.

// ANCHOR: uniforms
struct Cones {
    // x: the cone's radius at its rim corners (tile units), y: 1 / the
    // depth at the rim, so that depth = distance × y stays in 0..1.
    radius: vec4<f32>,
    // x: segments around the cone, y: copies of each site (9: the tile and
    // its 8 neighbours; 1: the tile alone, which shows seams).
    counts: vec4<u32>,
};
@group(0) @binding(0) var<uniform> cones: Cones;
// Site positions in the tile, (0..1)².
@group(0) @binding(1) var<storage, read> sites: array<vec2<f32>>;
// ANCHOR_END: uniforms

struct ConeOutput {
    @builtin(position) clip_position: vec4<f32>,
    // Where this point of the cone is from its site, in tile units.
    @location(0) from_site: vec2<f32>,
    @location(1) @interpolate(flat) site: u32,
};

// ANCHOR: cone
// Instance i draws copy i % copies of site i / copies. Three vertices per
// segment: the apex, and two corners on the rim. The rim corners are at
// depth 1; the apex, at the site, at depth 0.
@vertex
fn vs_cone(@builtin(vertex_index) vertex: u32, @builtin(instance_index) instance: u32) -> ConeOutput {
    let copies = cones.counts.y;
    let site = instance / copies;
    let copy = instance % copies;
    // The 9 copies: offsets of −1, 0 and +1 tiles in x and y (copy 4, or
    // the only copy, is the tile itself).
    var tile = vec2<f32>(0.0);
    if copies == 9u {
        tile = vec2<f32>(f32(copy % 3u), f32(copy / 3u)) - 1.0;
    }
    let corner = vertex % 3u;
    let segment = vertex / 3u + corner - 1u;
    var from_site = vec2<f32>(0.0);
    var depth = 0.0;
    if corner != 0u {
        let angle = 6.2831853 * f32(segment) / f32(cones.counts.x);
        from_site = cones.radius.x * vec2<f32>(cos(angle), sin(angle));
        depth = 1.0;
    }
    // Tile (0, 0) at the top left, (1, 1) at the bottom right.
    let p = sites[site] + tile + from_site;
    var out: ConeOutput;
    out.clip_position = vec4<f32>(p.x * 2.0 - 1.0, 1.0 - p.y * 2.0, depth, 1.0);
    out.from_site = from_site;
    out.site = site;
    return out;
}
// ANCHOR_END: cone

// ANCHOR: fragment
// The depth the rasteriser interpolated: on a cone of few segments, the
// distance to a polygon, which makes the seed's wavy edges.
@fragment
fn fs_cone(in: ConeOutput) -> @location(0) u32 {
    return in.site;
}

struct ExactOutput {
    @location(0) site: u32,
    @builtin(frag_depth) depth: f32,
};

// The true distance, worked out per pixel: exact whatever the segment
// count (the `cells` view), at the price of the early depth test.
@fragment
fn fs_cone_exact(in: ConeOutput) -> ExactOutput {
    return ExactOutput(in.site, length(in.from_site) * cones.radius.y);
}
// ANCHOR_END: fragment
