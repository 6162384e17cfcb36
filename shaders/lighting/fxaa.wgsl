// Chapter 08: FXAA, fast approximate anti-aliasing (Timothy Lottes, NVIDIA,
// 2009), the last pass of the post chain. It sees only the finished
// picture: where a pixel differs enough from its neighbours it decides
// which way the edge runs, walks along it to find how long the step of the
// staircase is, and from where the pixel sits on that step works out how
// much of the neighbour across the edge to blend in.
#import common::fullscreen::{FullscreenOutput, fullscreen_triangle}

@group(0) @binding(0) var picture: texture_2d<f32>;
@group(0) @binding(1) var linear_sampler: sampler;

@vertex
fn vs_fullscreen(@builtin(vertex_index) index: u32) -> FullscreenOutput {
    return fullscreen_triangle(index, 0.0);
}

// ANCHOR: tuning
// A pixel is on an edge when the spread of lightness among it and its four
// neighbours is at least this share of the brightest of them...
const RELATIVE_THRESHOLD: f32 = 0.125;
// ...and at least this much: dark noise is not an edge.
const ABSOLUTE_THRESHOLD: f32 = 0.0312;
// How strongly a pixel unlike all its neighbours (a one-pixel dot, a thin
// line's end) is blended towards their average: 0 not at all, 1 fully.
const SUBPIXEL_BLEND: f32 = 0.75;
// The walk along an edge: steps at most, and how far step `i` goes, in
// pixels. Short steps first, where most staircases end; longer ones for
// edges near horizontal, whose steps are long.
const STEPS: i32 = 10;
fn step_length(i: i32) -> f32 {
    if i < 4 {
        return 1.0;
    }
    if i == 4 {
        return 1.5;
    }
    if i < 8 {
        return 2.0;
    }
    return select(8.0, 4.0, i == 8);
}
// ANCHOR_END: tuning

// Lightness as the eye judges it. The picture is stored in sRGB and read
// back linear; the square root of linear luminance is close to the sRGB
// curve, so equal steps of this look like equal steps of grey.
fn lightness(colour: vec3<f32>) -> f32 {
    return sqrt(dot(colour, vec3<f32>(0.2126, 0.7152, 0.0722)));
}

fn lightness_at(pixel: vec2<i32>) -> f32 {
    let last = vec2<i32>(textureDimensions(picture)) - 1;
    return lightness(textureLoad(picture, clamp(pixel, vec2<i32>(0), last), 0).rgb);
}

// The picture between pixels, bilinearly; one mip level, so it may be read
// in branches that neighbouring pixels do not take.
fn lightness_between(uv: vec2<f32>) -> f32 {
    return lightness(textureSampleLevel(picture, linear_sampler, uv, 0.0).rgb);
}

// ANCHOR: fs_fxaa
@fragment
fn fs_fxaa(in: FullscreenOutput) -> @location(0) vec4<f32> {
    let texel = 1.0 / vec2<f32>(textureDimensions(picture));
    let pixel = vec2<i32>(in.clip_position.xy);
    let own = textureLoad(picture, pixel, 0).rgb;

    // 1. Is this pixel on an edge? Compare it with its four neighbours.
    let centre = lightness(own);
    let up = lightness_at(pixel + vec2<i32>(0, -1));
    let down = lightness_at(pixel + vec2<i32>(0, 1));
    let left = lightness_at(pixel + vec2<i32>(-1, 0));
    let right = lightness_at(pixel + vec2<i32>(1, 0));
    let darkest = min(centre, min(min(up, down), min(left, right)));
    let brightest = max(centre, max(max(up, down), max(left, right)));
    let contrast = brightest - darkest;
    if contrast < max(ABSOLUTE_THRESHOLD, brightest * RELATIVE_THRESHOLD) {
        return vec4<f32>(own, 1.0);
    }

    // 2. Which way does it run? Lightness that changes from row to row is
    // a horizontal edge; from column to column, a vertical one. The
    // corners make the guess steadier on diagonals.
    let up_left = lightness_at(pixel + vec2<i32>(-1, -1));
    let up_right = lightness_at(pixel + vec2<i32>(1, -1));
    let down_left = lightness_at(pixel + vec2<i32>(-1, 1));
    let down_right = lightness_at(pixel + vec2<i32>(1, 1));
    let across_rows = 2.0 * abs(up + down - 2.0 * centre) + abs(up_left + down_left - 2.0 * left)
        + abs(up_right + down_right - 2.0 * right);
    let across_columns = 2.0 * abs(left + right - 2.0 * centre) + abs(up_left + up_right - 2.0 * up)
        + abs(down_left + down_right - 2.0 * down);
    let horizontal = across_rows >= across_columns;

    // 3. Which side is the other surface? The neighbour across the edge
    // that differs more. `across` is one pixel towards it, `along` one
    // pixel along the edge.
    let before = select(left, up, horizontal);
    let after = select(right, down, horizontal);
    let towards_before = abs(before - centre) >= abs(after - centre);
    let other = select(after, before, towards_before);
    let step = select(vec2<f32>(texel.x, 0.0), vec2<f32>(0.0, texel.y), horizontal);
    let across = select(step, -step, towards_before);
    let along = select(vec2<f32>(0.0, texel.y), vec2<f32>(texel.x, 0.0), horizontal);
    let gradient = abs(other - centre);
    let on_edge = 0.5 * (centre + other);

    // 4. Walk along the edge both ways, half a pixel across (where a
    // bilinear read is the mean of the two sides), until the mean leaves
    // the edge's: the ends of this step of the staircase.
    let start = in.uv + 0.5 * across;
    var back = start;
    var forth = start;
    var back_change = 0.0;
    var forth_change = 0.0;
    var back_done = false;
    var forth_done = false;
    for (var i = 0; i < STEPS; i++) {
        if !back_done {
            back -= step_length(i) * along;
            back_change = lightness_between(back) - on_edge;
            back_done = abs(back_change) >= 0.25 * gradient;
        }
        if !forth_done {
            forth += step_length(i) * along;
            forth_change = lightness_between(forth) - on_edge;
            forth_done = abs(forth_change) >= 0.25 * gradient;
        }
        if back_done && forth_done {
            break;
        }
    }

    // 5. How far is this pixel along its step? Distances in pixels.
    let to_back = dot(start - back, along) / dot(along, along);
    let to_forth = dot(forth - start, along) / dot(along, along);
    let nearer_change = select(forth_change, back_change, to_back < to_forth);
    // Near the end where the staircase turns towards this pixel's side, the
    // pixel is mostly the other surface: blend up to half of it. Near the
    // end that turns away, it is all this surface: blend nothing.
    let turns_towards = (centre < on_edge) != (nearer_change < 0.0);
    let edge_blend = select(0.0, 0.5 - min(to_back, to_forth) / (to_back + to_forth), turns_towards);

    // 6. A pixel unlike its whole neighbourhood (a dot, a line one pixel
    // wide) has no staircase to measure: blend it by how much it stands out.
    let neighbourhood = (2.0 * (up + down + left + right) + up_left + up_right + down_left + down_right) / 12.0;
    let stands_out = smoothstep(0.0, 1.0, clamp(abs(neighbourhood - centre) / contrast, 0.0, 1.0));
    let subpixel_blend = stands_out * stands_out * SUBPIXEL_BLEND;

    // 7. Read the picture that far across the edge: a bilinear read there
    // is the blend.
    let blend = max(edge_blend, subpixel_blend);
    return vec4<f32>(textureSampleLevel(picture, linear_sampler, in.uv + blend * across, 0.0).rgb, 1.0);
}
// ANCHOR_END: fs_fxaa
