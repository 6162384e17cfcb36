// Chapter 10: the lantern's cube shadow map, its six faces unfolded in a
// cross and drawn full screen: near the light dark, far light, nothing
// within its range white. Each pixel is read from the cube as a lookup
// reads it, along the direction its face and its place on the face give,
// so a face rendered the wrong way round would show as a seam.
#import common::fullscreen::{FullscreenOutput, fullscreen_triangle}

struct Unfolded {
    // Per face, in layer order (+x −x +y −y +z −z): its major axis, the
    // axis its columns run along (s), the axis its rows run down (t);
    // point_shadow.rs's table, written by `CubeView::draw`.
    axes: array<vec4<f32>, 18>,
    // x: the target's width over its height, y: a face's side in pixels.
    shape: vec4<f32>,
};
// Read as plain floats, as chapter 02's depth view reads its depth buffer:
// OpenGL's GLSL samples a texture declared as depth only to compare.
@group(0) @binding(0) var cube: texture_cube<f32>;
@group(0) @binding(1) var nearest: sampler;
@group(0) @binding(2) var<uniform> unfolded: Unfolded;

@vertex
fn vs_fullscreen(@builtin(vertex_index) index: u32) -> FullscreenOutput {
    return fullscreen_triangle(index, 0.0);
}

// The cross, four faces wide and three high: +y above +z, −y below it,
// and around the middle row −x, +z, +x, −z, so that each face meets its
// neighbours along the edges they share. −1 where there is no face.
fn face_at(cell: vec2<i32>) -> i32 {
    if cell.x < 0 || cell.x > 3 || cell.y < 0 || cell.y > 2 {
        return -1;
    }
    if cell.y == 1 {
        switch cell.x {
            case 0: { return 1; }
            case 1: { return 4; }
            case 2: { return 0; }
            default: { return 5; }
        }
    }
    if cell.x == 1 {
        return select(3, 2, cell.y == 0);
    }
    return -1;
}

@fragment
fn fs_unfolded(in: FullscreenOutput) -> @location(0) vec4<f32> {
    // The cross, centred, fills the target's height (bars either side)
    // or, in a target narrower than 4:3, its width.
    let wider = unfolded.shape.x * 3.0 / 4.0;
    let scale = vec2<f32>(max(wider, 1.0), max(1.0 / wider, 1.0));
    let grid = ((in.uv - 0.5) * scale + 0.5) * vec2<f32>(4.0, 3.0);
    let face = face_at(vec2<i32>(floor(grid)));
    if face < 0 {
        return vec4<f32>(0.02, 0.03, 0.06, 1.0);
    }
    let st = fract(grid);
    // A face's border, a pixel wide: where one face ends and the next begins.
    let border = min(min(st.x, 1.0 - st.x), min(st.y, 1.0 - st.y)) * unfolded.shape.y;
    if border < 1.0 {
        return vec4<f32>(0.9, 0.45, 0.1, 1.0);
    }
    let i = u32(face) * 3u;
    let direction = unfolded.axes[i].xyz + unfolded.axes[i + 1u].xyz * (st.x * 2.0 - 1.0)
        + unfolded.axes[i + 2u].xyz * (st.y * 2.0 - 1.0);
    let distance = textureSampleLevel(cube, nearest, direction, 0.0).r;
    return vec4<f32>(vec3<f32>(distance), 1.0);
}
