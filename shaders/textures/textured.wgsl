// Chapter 09: textured, normal-mapped surfaces, lit by chapter 08's light
// loop. The albedo map gives the colour (decoded from sRGB by the texture
// format), the normal map bends the normal in the surface's own frame
// (tangent, bitangent, normal), and `light_surface` does the rest.
#import lighting::lights::{frame, Surface, light_surface}

// ANCHOR: bindings
// 64 bytes, as MaterialUniform in materials.rs.
struct Material {
    diffuse: vec3<f32>,
    specular: f32,
    emissive: vec3<f32>,
    shininess: f32,
    // x: has a normal map, y: has an albedo map (its alpha masks the
    // emissive light), z: glows only at night.
    flags: vec4<u32>,
};
@group(1) @binding(0) var albedo_map: texture_2d<f32>;
@group(1) @binding(1) var normal_map: texture_2d<f32>;
@group(1) @binding(2) var<uniform> material: Material;

// How this frame reads surfaces (lib.rs: ViewOptions).
struct ViewOptions {
    // 1: read the normal map's green as pointing down the image (DirectX).
    flip_green: u32,
    // For the tangent frame view's thirds.
    target_width: f32,
    padding: vec2<f32>,
};
@group(2) @binding(0) var surface_sampler: sampler;
@group(2) @binding(1) var<uniform> options: ViewOptions;
// ANCHOR_END: bindings

struct Vertex {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) uv: vec2<f32>,
    @location(3) tangent: vec4<f32>,
};

struct Instance {
    @location(4) model_0: vec4<f32>,
    @location(5) model_1: vec4<f32>,
    @location(6) model_2: vec4<f32>,
    @location(7) model_3: vec4<f32>,
    @location(8) normal_0: vec4<f32>,
    @location(9) normal_1: vec4<f32>,
    @location(10) normal_2: vec4<f32>,
    @location(11) glow: f32,
};

struct Varyings {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) world: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) uv: vec2<f32>,
    @location(3) tangent: vec4<f32>,
    @location(4) glow: f32,
};

// ANCHOR: vertex
@vertex
fn vs_main(vertex: Vertex, instance: Instance) -> Varyings {
    let model = mat4x4<f32>(instance.model_0, instance.model_1, instance.model_2, instance.model_3);
    let normal_matrix = mat3x3<f32>(instance.normal_0.xyz, instance.normal_1.xyz, instance.normal_2.xyz);
    let world = (model * vec4<f32>(vertex.position, 1.0)).xyz;
    // A tangent lies along the surface, like an edge: it moves with the
    // model matrix itself. The normal needs the inverse transpose (chapter 02).
    let tangent = (model * vec4<f32>(vertex.tangent.xyz, 0.0)).xyz;
    // A mirroring model matrix turns the frame inside out: flip handedness.
    let mirrored = determinant(mat3x3<f32>(model[0].xyz, model[1].xyz, model[2].xyz)) < 0.0;
    let handedness = select(vertex.tangent.w, -vertex.tangent.w, mirrored);
    var out: Varyings;
    out.clip_position = frame.view_proj * vec4<f32>(world, 1.0);
    out.world = world;
    out.normal = normal_matrix * vertex.normal;
    out.uv = vertex.uv;
    out.tangent = vec4<f32>(tangent, handedness);
    out.glow = instance.glow;
    return out;
}
// ANCHOR_END: vertex

// ANCHOR: tbn
// The surface's frame at this fragment. Interpolation has shortened the
// normal and tilted the tangent off it: normalise the normal, then take
// out of the tangent its part along the normal (Gram–Schmidt) and
// normalise that. The bitangent, "up the image", is w · (N × T).
struct Frame3 {
    t: vec3<f32>,
    b: vec3<f32>,
    n: vec3<f32>,
};

fn surface_frame(in: Varyings) -> Frame3 {
    let n = normalize(in.normal);
    let t = normalize(in.tangent.xyz - n * dot(n, in.tangent.xyz));
    let b = in.tangent.w * cross(n, t);
    return Frame3(t, b, n);
}

// A texel of a normal map, from 0..1 back to a direction in that frame.
fn mapped_normal(frame3: Frame3, texel: vec3<f32>) -> vec3<f32> {
    var m = texel * 2.0 - 1.0;
    if options.flip_green == 1u {
        m.y = -m.y;
    }
    return normalize(mat3x3<f32>(frame3.t, frame3.b, frame3.n) * m);
}
// ANCHOR_END: tbn

// ANCHOR: fragment
// The light a surface with normal n sends to the eye, and its own glow.
fn shade(in: Varyings, n: vec3<f32>, albedo_texel: vec4<f32>) -> vec4<f32> {
    let albedo = material.diffuse * albedo_texel.rgb;
    let lit = light_surface(in.world, n, Surface(albedo, material.specular, material.shininess));
    // An albedo map's alpha says where the material glows (lit windows).
    let mask = select(1.0, albedo_texel.a, material.flags.y == 1u);
    let night = select(1.0, frame.depth.w, material.flags.z == 1u);
    return vec4<f32>(lit + material.emissive * mask * night * in.glow, 1.0);
}

// With normal maps. The material decides whether it has one: a uniform,
// so every fragment of a draw takes the same branch, and sampling inside
// it is allowed (sampling needs its neighbours, for the mip level).
@fragment
fn fs_normal_mapped(in: Varyings) -> @location(0) vec4<f32> {
    let frame3 = surface_frame(in);
    var n = frame3.n;
    if material.flags.x == 1u {
        n = mapped_normal(frame3, textureSample(normal_map, surface_sampler, in.uv).xyz);
    }
    return shade(in, n, textureSample(albedo_map, surface_sampler, in.uv));
}

// Without: the interpolated normal, and no normal map read at all.
@fragment
fn fs_plain(in: Varyings) -> @location(0) vec4<f32> {
    return shade(in, normalize(in.normal), textureSample(albedo_map, surface_sampler, in.uv));
}
// ANCHOR_END: fragment

// The tangent frame as colours: the left third of the picture shows the
// tangent, the middle the bitangent, the right the normal.
@fragment
fn fs_frame(in: Varyings) -> @location(0) vec4<f32> {
    let frame3 = surface_frame(in);
    let third = u32(3.0 * in.clip_position.x / options.target_width);
    let v = select(select(frame3.n, frame3.b, third == 1u), frame3.t, third == 0u);
    return vec4<f32>(v * 0.5 + 0.5, 1.0);
}
