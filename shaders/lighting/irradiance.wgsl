// Chapter 08: the sky's radiance projected on nine spherical harmonics, on
// the GPU, whenever the sky changes (scene_lights.rs). One workgroup: each
// of its 64 invocations integrates one ring of directions, a band of
// latitude, and the first adds the rings up.
#import lighting::sky_light::{PI, sky_radiance, sh_basis}

struct SkyColours {
    horizon: vec4<f32>,
    zenith: vec4<f32>,
    ground: vec4<f32>,
};
@group(0) @binding(0) var<uniform> colours: SkyColours;
@group(0) @binding(1) var<storage, read_write> sh: array<vec4<f32>, 9>;

// ANCHOR: project
const RINGS: u32 = 64u;
const SPOKES: u32 = 128u;
var<workgroup> rings: array<array<vec3<f32>, 9>, RINGS>;

@compute @workgroup_size(64)
fn cs_project(@builtin(local_invocation_index) ring: u32) {
    // ∫ L(ω) Y_k(ω) dω, with dω = sin θ dθ dφ, by the midpoint rule.
    let d_theta = PI / f32(RINGS);
    let d_phi = 2.0 * PI / f32(SPOKES);
    let theta = (f32(ring) + 0.5) * d_theta;
    var sum: array<vec3<f32>, 9>;
    for (var j = 0u; j < SPOKES; j++) {
        let phi = (f32(j) + 0.5) * d_phi;
        // θ from straight up (+y), the city's up.
        let d = vec3<f32>(sin(theta) * cos(phi), cos(theta), sin(theta) * sin(phi));
        let light = sky_radiance(d, colours.horizon.rgb, colours.zenith.rgb, colours.ground.rgb);
        let y = sh_basis(d);
        for (var k = 0u; k < 9u; k++) {
            sum[k] += light * y[k] * sin(theta) * d_theta * d_phi;
        }
    }
    rings[ring] = sum;
    workgroupBarrier();
    if ring == 0u {
        for (var k = 0u; k < 9u; k++) {
            var total = vec3<f32>(0.0);
            for (var r = 0u; r < RINGS; r++) {
                total += rings[r][k];
            }
            sh[k] = vec4<f32>(total, 0.0);
        }
    }
}
// ANCHOR_END: project
