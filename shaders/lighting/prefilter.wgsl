// Chapter 08: the sky as a mirror sees it, blurred as much as a surface of
// each roughness blurs it (Karis 2013's first sum), on the GPU whenever
// the sky changes (prefiltered_sky.rs). One cube map, one mip level per
// roughness: level 0 is the sky itself, for a mirror; each level down is
// half the size and a step rougher, since a blurrier picture needs fewer
// texels. One invocation per texel of one level, all six faces at once.
#import lighting::sky_light::sky_radiance
#import lighting::brdf::{ggx_alpha, ggx_half_vector, hammersley}

struct SkyColours {
    horizon: vec4<f32>,
    zenith: vec4<f32>,
    ground: vec4<f32>,
};
// The roughness this level is blurred for, in x.
struct Level {
    roughness: vec4<f32>,
};
@group(0) @binding(0) var<uniform> colours: SkyColours;
@group(0) @binding(1) var<uniform> level: Level;
// The level's six faces, as layers.
@group(0) @binding(2) var faces: texture_storage_2d_array<rgba16float, write>;

// ANCHOR: direction
// The direction through texel centre `uv` (0..1 across, 0..1 down) of cube
// face `face`, in WebGPU's order +x, −x, +y, −y, +z, −z. Each face is seen
// from the cube's centre with its own right (s) and down (t) axes, the
// convention WebGPU takes from Vulkan and Direct3D: down the +x face
// runs −y, across it −z.
fn face_direction(face: u32, uv: vec2<f32>) -> vec3<f32> {
    let s = 2.0 * uv.x - 1.0;
    let t = 2.0 * uv.y - 1.0;
    switch face {
        case 0u: { return normalize(vec3<f32>(1.0, -t, -s)); }
        case 1u: { return normalize(vec3<f32>(-1.0, -t, s)); }
        case 2u: { return normalize(vec3<f32>(s, 1.0, t)); }
        case 3u: { return normalize(vec3<f32>(s, -1.0, -t)); }
        case 4u: { return normalize(vec3<f32>(s, -t, 1.0)); }
        default: { return normalize(vec3<f32>(-s, -t, -1.0)); }
    }
}
// ANCHOR_END: direction

// ANCHOR: prefilter
const SAMPLES: u32 = 512u;

@compute @workgroup_size(8, 8)
fn cs_prefilter(@builtin(global_invocation_id) id: vec3<u32>) {
    let size = textureDimensions(faces);
    if id.x >= size.x || id.y >= size.y {
        return;
    }
    let r = face_direction(id.z, (vec2<f32>(id.xy) + 0.5) / vec2<f32>(size));
    let horizon = colours.horizon.rgb;
    let zenith = colours.zenith.rgb;
    let ground = colours.ground.rgb;
    var light = sky_radiance(r, horizon, zenith, ground);
    if level.roughness.x > 0.0 {
        // Karis's assumption: the surface faces the reflected direction
        // and is seen from there (n = v = r), so the blur depends on r
        // alone. Half vectors drawn by GGX about n, each reflecting v to a
        // light direction l; the sky along l weighted by n·l.
        let alpha = ggx_alpha(level.roughness.x);
        let n = r;
        // Any two axes across n will do: GGX is the same all round.
        let across = select(vec3<f32>(0.0, 1.0, 0.0), vec3<f32>(1.0, 0.0, 0.0), abs(n.y) > 0.9);
        let x = normalize(cross(across, n));
        let y = cross(n, x);
        var sum = vec3<f32>(0.0);
        var weight = 0.0;
        for (var i = 0u; i < SAMPLES; i++) {
            let h_local = ggx_half_vector(hammersley(i, SAMPLES), alpha);
            let h = h_local.x * x + h_local.y * y + h_local.z * n;
            let l = 2.0 * dot(n, h) * h - n;
            let n_dot_l = dot(n, l);
            if n_dot_l > 0.0 {
                sum += sky_radiance(l, horizon, zenith, ground) * n_dot_l;
                weight += n_dot_l;
            }
        }
        light = sum / weight;
    }
    textureStore(faces, id.xy, id.z, vec4<f32>(light, 1.0));
}
// ANCHOR_END: prefilter
