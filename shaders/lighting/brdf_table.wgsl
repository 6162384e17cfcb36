// Chapter 08: the split-sum table (Karis 2013), computed on the GPU once,
// when the chapter starts. A surface under a sky of even light L reflects
// L × ∫ f cos over the hemisphere. Schlick's F is f0 + (1 − f0)(1 − v·h)⁵,
// so the integral splits into f0 × A + B, where A and B depend only on the
// view's angle and the roughness: one texel each, x = n·v, y = roughness.
// The integral is estimated by importance sampling: half vectors drawn
// where GGX puts its facets, so that few samples are wasted on directions
// that reflect nothing.
#import lighting::brdf::{ggx_alpha, ggx_half_vector, hammersley, smith_visibility}

@group(0) @binding(0) var table: texture_storage_2d<rgba16float, write>;

// ANCHOR: integrate
const SAMPLES: u32 = 1024u;

@compute @workgroup_size(8, 8)
fn cs_brdf_table(@builtin(global_invocation_id) id: vec3<u32>) {
    let size = textureDimensions(table);
    if id.x >= size.x || id.y >= size.y {
        return;
    }
    let n_dot_v = (f32(id.x) + 0.5) / f32(size.x);
    let alpha = ggx_alpha((f32(id.y) + 0.5) / f32(size.y));
    let v = vec3<f32>(sqrt(1.0 - n_dot_v * n_dot_v), 0.0, n_dot_v);
    var a = 0.0;
    var b = 0.0;
    for (var i = 0u; i < SAMPLES; i++) {
        let h = ggx_half_vector(hammersley(i, SAMPLES), alpha);
        let v_dot_h = dot(v, h);
        let l = 2.0 * v_dot_h * h - v;
        if l.z > 0.0 && v_dot_h > 0.0 {
            // f cos / pdf, without F: the pdf of l is D n·h / (4 v·h), and
            // f cos is D V F n·l, so D cancels.
            let weight = smith_visibility(n_dot_v, l.z, alpha) * 4.0 * l.z * v_dot_h / h.z;
            let grazing = pow(1.0 - v_dot_h, 5.0);
            a += (1.0 - grazing) * weight;
            b += grazing * weight;
        }
    }
    textureStore(table, id.xy, vec4<f32>(a, b, 0.0, 1.0) / vec4<f32>(f32(SAMPLES), f32(SAMPLES), 1.0, 1.0));
}
// ANCHOR_END: integrate
