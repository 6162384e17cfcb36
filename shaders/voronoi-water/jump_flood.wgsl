// Chapter 11: the same diagram by jump flooding (Rong & Tan 2006). The
// sites are dropped into their pixels; then, in log2(size) passes with a
// step that halves each time, every pixel looks at 9 pixels a step away
// and keeps the nearest site any of them knows about.
#import common::fullscreen::{FullscreenOutput, fullscreen_triangle}

// 0xffffffff: no site known yet.
const NONE: u32 = 4294967295u;

struct Step {
    // x: the step in pixels.
    step: vec4<u32>,
};
// Group 0 is the cones' (cones.wgsl): only its sites are used here.
@group(0) @binding(1) var<storage, read> sites: array<vec2<f32>>;
@group(1) @binding(0) var<uniform> pass_step: Step;
@group(1) @binding(1) var known: texture_2d<u32>;

// ANCHOR: seeds
// Pass zero: one point per site, at the pixel the site lies in.
struct SeedOutput {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) @interpolate(flat) site: u32,
};

@vertex
fn vs_seed(@builtin(vertex_index) site: u32) -> SeedOutput {
    let p = sites[site];
    return SeedOutput(vec4<f32>(p.x * 2.0 - 1.0, 1.0 - p.y * 2.0, 0.0, 1.0), site);
}

@fragment
fn fs_seed(in: SeedOutput) -> @location(0) u32 {
    return in.site;
}
// ANCHOR_END: seeds

@vertex
fn vs_fullscreen(@builtin(vertex_index) index: u32) -> FullscreenOutput {
    return fullscreen_triangle(index, 0.0);
}

// The squared distance from `p` to site `site` the short way round the
// tile (it wraps at its edges), in tile units.
fn torus_distance_squared(p: vec2<f32>, site: u32) -> f32 {
    let d = sites[site] - p;
    let wrapped = d - round(d);
    return dot(wrapped, wrapped);
}

// ANCHOR: step
@fragment
fn fs_step(in: FullscreenOutput) -> @location(0) u32 {
    let size = vec2<i32>(textureDimensions(known));
    let pixel = vec2<i32>(in.clip_position.xy);
    let centre = (vec2<f32>(pixel) + 0.5) / vec2<f32>(size);
    let step = i32(pass_step.step.x);
    var best = NONE;
    var best_distance = 1e9;
    for (var y = -1; y <= 1; y++) {
        for (var x = -1; x <= 1; x++) {
            // The tile wraps, so the neighbours do too.
            let there = ((pixel + vec2<i32>(x, y) * step) % size + size) % size;
            let site = textureLoad(known, there, 0).x;
            if site != NONE {
                let distance = torus_distance_squared(centre, site);
                if distance < best_distance || (distance == best_distance && site < best) {
                    best = site;
                    best_distance = distance;
                }
            }
        }
    }
    return best;
}
// ANCHOR_END: step
