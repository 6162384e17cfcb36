// Chapter 11: from the diagram to the water's texture, as the seed did it:
// colour each cell, blur the colours (a box blur, horizontal then
// vertical, twice: close to a Gaussian), and find the edges of what is
// left (Sobel): the lines of foam. Every picture wraps at its edges, as
// the diagram does, so the texture repeats without seams.
#import common::fullscreen::{FullscreenOutput, fullscreen_triangle}

const NONE: u32 = 4294967295u;

struct Process {
    // x: 1 for the water's shades, 0 for a distinct hue per cell;
    // y: the blur's radius in texels (0: no blur); z: foam on (1) or off.
    options: vec4<u32>,
    // x, y: where foam starts and is full, in Sobel's gradient of the
    // blurred brightness.
    foam: vec4<f32>,
};
@group(0) @binding(0) var<uniform> process: Process;
// The diagram: a site's index per pixel.
@group(0) @binding(1) var ids: texture_2d<u32>;
// The picture the pass works on (the colours, a blur's half-way result…).
@group(1) @binding(0) var picture: texture_2d<f32>;

@vertex
fn vs_fullscreen(@builtin(vertex_index) index: u32) -> FullscreenOutput {
    return fullscreen_triangle(index, 0.0);
}

// A fixed hash of a site's index to three numbers in 0..1.
fn hash3(index: u32) -> vec3<f32> {
    var x = index * 747796405u + 2891336453u;
    var h = vec3<u32>(x, x * 277803737u, x * 2654435769u);
    h = (h ^ (h >> vec3<u32>(16u))) * 0x45d9f3bu;
    h = h ^ (h >> vec3<u32>(16u));
    return vec3<f32>(h & vec3<u32>(0xffffu)) / 65535.0;
}

// ANCHOR: colour
@fragment
fn fs_colour(in: FullscreenOutput) -> @location(0) vec4<f32> {
    let site = textureLoad(ids, vec2<i32>(in.clip_position.xy), 0).x;
    if site == NONE {
        // No cone reached this pixel: magenta, so a hole cannot hide.
        return vec4<f32>(1.0, 0.0, 1.0, 1.0);
    }
    let h = hash3(site);
    if process.options.x == 0u {
        return vec4<f32>(0.15 + 0.85 * h, 1.0);
    }
    // The sea's shades, in linear light (the picture is sRGB): deep blue
    // to teal, a little lighter or darker per cell.
    let shade = mix(vec3<f32>(0.008, 0.09, 0.36), vec3<f32>(0.02, 0.24, 0.46), h.x);
    return vec4<f32>(shade * (0.8 + 0.4 * h.y), 1.0);
}
// ANCHOR_END: colour

// ANCHOR: blur
// One direction of a box blur: the mean of 2r + 1 texels in a row (or a
// column), wrapping at the edges.
fn box_blur(pixel: vec2<i32>, direction: vec2<i32>) -> vec4<f32> {
    let size = vec2<i32>(textureDimensions(picture));
    let r = i32(process.options.y);
    var sum = vec4<f32>(0.0);
    for (var i = -r; i <= r; i++) {
        let there = ((pixel + direction * i) % size + size) % size;
        sum += textureLoad(picture, there, 0);
    }
    return sum / f32(2 * r + 1);
}

@fragment
fn fs_blur_across(in: FullscreenOutput) -> @location(0) vec4<f32> {
    return box_blur(vec2<i32>(in.clip_position.xy), vec2<i32>(1, 0));
}

@fragment
fn fs_blur_down(in: FullscreenOutput) -> @location(0) vec4<f32> {
    return box_blur(vec2<i32>(in.clip_position.xy), vec2<i32>(0, 1));
}
// ANCHOR_END: blur

// ANCHOR: edges
fn brightness(pixel: vec2<i32>) -> f32 {
    let size = vec2<i32>(textureDimensions(picture));
    let there = (pixel % size + size) % size;
    return dot(textureLoad(picture, there, 0).rgb, vec3<f32>(0.299, 0.587, 0.114));
}

// Sobel's two 3×3 kernels estimate the brightness's gradient across and
// down; where it is steep, two cells meet.
fn sobel(p: vec2<i32>) -> f32 {
    let tl = brightness(p + vec2<i32>(-1, -1));
    let t = brightness(p + vec2<i32>(0, -1));
    let tr = brightness(p + vec2<i32>(1, -1));
    let l = brightness(p + vec2<i32>(-1, 0));
    let r = brightness(p + vec2<i32>(1, 0));
    let bl = brightness(p + vec2<i32>(-1, 1));
    let b = brightness(p + vec2<i32>(0, 1));
    let br = brightness(p + vec2<i32>(1, 1));
    let across = (tr + 2.0 * r + br) - (tl + 2.0 * l + bl);
    let down = (bl + 2.0 * b + br) - (tl + 2.0 * t + tr);
    return length(vec2<f32>(across, down));
}

// The edges alone: the gradient's size, as grey.
@fragment
fn fs_edges(in: FullscreenOutput) -> @location(0) vec4<f32> {
    let g = sobel(vec2<i32>(in.clip_position.xy));
    return vec4<f32>(vec3<f32>(smoothstep(process.foam.x, process.foam.y, g)), 1.0);
}

// The water's texture: the blurred cells, with foam where the edges are.
@fragment
fn fs_water(in: FullscreenOutput) -> @location(0) vec4<f32> {
    let pixel = vec2<i32>(in.clip_position.xy);
    let cells = textureLoad(picture, pixel, 0).rgb;
    var foam = 0.0;
    if process.options.z == 1u {
        foam = smoothstep(process.foam.x, process.foam.y, sobel(pixel));
    }
    return vec4<f32>(mix(cells, vec3<f32>(0.92, 0.97, 1.0), foam), 1.0);
}
// ANCHOR_END: edges

// ANCHOR: cells
// The id buffer as a picture, for checking the diagram: red = index % 256,
// green = index / 256. The target may be sRGB, which encodes what it is
// given; `srgb` = 1 hands it the value that encodes to the exact byte.
struct Show {
    // x: 1 if the target is sRGB; y: 1 to tile the picture at square
    // texels instead of stretching it over the target.
    options: vec4<u32>,
    // x: the target's width over its height; y: tiles down the target.
    shape: vec4<f32>,
};
@group(2) @binding(0) var<uniform> show: Show;
@group(2) @binding(1) var shown_sampler: sampler;

fn to_linear(byte: f32) -> f32 {
    let c = byte / 255.0;
    if c <= 0.04045 {
        return c / 12.92;
    }
    return pow((c + 0.055) / 1.055, 2.4);
}

fn encoded(bytes: vec3<f32>) -> vec4<f32> {
    if show.options.x == 1u {
        return vec4<f32>(to_linear(bytes.x), to_linear(bytes.y), to_linear(bytes.z), 1.0);
    }
    return vec4<f32>(bytes / 255.0, 1.0);
}

@fragment
fn fs_show_cells(in: FullscreenOutput) -> @location(0) vec4<f32> {
    let site = textureLoad(ids, vec2<i32>(in.clip_position.xy), 0).x;
    if site == NONE {
        return encoded(vec3<f32>(255.0, 0.0, 255.0));
    }
    return encoded(vec3<f32>(f32(site % 256u), f32(site / 256u), 0.0));
}
// ANCHOR_END: cells

// Any of the pictures, full screen: tiled at square texels so that the
// seams (or their absence) show, or stretched.
@fragment
fn fs_show(in: FullscreenOutput) -> @location(0) vec4<f32> {
    var uv = in.uv;
    if show.options.y == 1u {
        uv = vec2<f32>(in.uv.x * show.shape.x, in.uv.y) * show.shape.y;
    }
    return textureSample(picture, shown_sampler, uv);
}
