// Chapter 05: one rock, as the compute pass that culls the rocks and the
// vertex shader that draws them both see it: its record, the sphere around
// it, and how many pixels across it looks.
#define_import_path instancing::rock

// ANCHOR: rock
struct Rock {
    // xyz: where it stands (world), w: yaw in radians.
    position_yaw: vec4<f32>,
    // xyz: scale along its own axes, w: shade, 0 dark to 1 light.
    scale_shade: vec4<f32>,
};

fn turn(v: vec3<f32>, yaw: f32) -> vec3<f32> {
    let s = sin(yaw);
    let c = cos(yaw);
    return vec3<f32>(c * v.x + s * v.z, v.y, -s * v.x + c * v.z);
}
// ANCHOR_END: rock

// ANCHOR: culling
// What one picture asks of the rocks (`CullingInput` in rock_culling.rs).
struct Culling {
    // World → the camera's own space, where it looks down −z.
    view: mat4x4<f32>,
    // x, y: the tangents of half the field of view, across and up;
    // z, w: the near and far planes' distances.
    frustum: vec4<f32>,
    // The picture's clip plane (n, d): what lies where n · p + d < 0 is cut.
    clip: vec4<f32>,
    // xyz: the eye; w: pixels per radian at the picture's centre, its
    // height in pixels over 2 tan(fov_y / 2).
    eye: vec4<f32>,
    // The sphere around the rock in its own space: xyz centre, w radius.
    sphere: vec4<f32>,
    // Pixels across: x, the full rock from here; y, the octahedron; z, the
    // tetrahedron; below z a rock is not drawn; between z and w it shrinks.
    sizes: vec4<f32>,
    // x: rocks to test; y: u32s from one level's list to the next.
    counts: vec4<u32>,
};

// The sphere around `rock` in the world: xyz centre, w radius. Stretched
// unevenly, it still fits inside the sphere stretched by its largest scale.
fn bounding_sphere(rock: Rock, sphere: vec4<f32>) -> vec4<f32> {
    let scale = rock.scale_shade.xyz;
    let centre = turn(sphere.xyz * scale, rock.position_yaw.w) + rock.position_yaw.xyz;
    return vec4<f32>(centre, sphere.w * max(scale.x, max(scale.y, scale.z)));
}
// ANCHOR_END: culling

// ANCHOR: size
// How many pixels across a sphere looks from the eye: its angular size,
// 2r / d for a sphere far away, times the pixels per radian at the centre
// of the picture. By distance, not depth, so that turning the head never
// changes a rock's level.
fn pixels_across(sphere: vec4<f32>, eye: vec4<f32>) -> f32 {
    return 2.0 * sphere.w / max(distance(sphere.xyz, eye.xyz), 1e-4) * eye.w;
}

// How much of its size a rock keeps: 1 from `sizes.w` pixels up, shrinking
// to nothing at `sizes.z`, below which the culling drops it, so it fades
// out rather than popping.
fn kept_size(pixels: f32, sizes: vec4<f32>) -> f32 {
    if sizes.w <= sizes.z {
        return 1.0;
    }
    return clamp((pixels - sizes.z) / (sizes.w - sizes.z), 0.0, 1.0);
}
// ANCHOR_END: size
