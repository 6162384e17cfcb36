// Chapter 09: textured, normal-mapped surfaces, lit by chapter 08's light
// loop. The albedo map gives the colour (decoded from sRGB by the texture
// format), the normal map bends the normal in the surface's own frame
// (tangent, bitangent, normal), and `light_surface` does the rest.
#import lighting::lights::{frame, Surface, light_surface}
#import textures::surface::{Vertex, Instance, Varyings, vary, material, albedo_map, normal_map, Frame3, surface_frame, mapped_normal}

// ANCHOR: bindings
// How this frame reads surfaces (lib.rs: ViewOptions).
struct ViewOptions {
    // 1: read the normal map's green as pointing down the image (DirectX).
    flip_green: u32,
    // For the tangent frame view's thirds.
    target_width: f32,
    padding: vec2<f32>,
};
@group(2) @binding(0) var surface_sampler: sampler;
@group(2) @binding(1) var<storage, read> options: ViewOptions;
// ANCHOR_END: bindings

@vertex
fn vs_main(vertex: Vertex, instance: Instance) -> Varyings {
    return vary(vertex, instance, frame.view_proj);
}

// The surface's frame at this fragment, from the interpolated normal and
// tangent (surface.wgsl).
fn fragment_frame(in: Varyings) -> Frame3 {
    return surface_frame(in.normal, in.tangent);
}


// ANCHOR: fragment
// The light a surface with normal n sends to the eye, and its own glow.
fn shade(in: Varyings, n: vec3<f32>, albedo_texel: vec4<f32>) -> vec4<f32> {
    var albedo = material.diffuse * albedo_texel.rgb;
    // Vertex colours (OBJ's `v x y z r g b`) tint it, where the model has them.
    if material.flags.w == 1u {
        albedo *= in.colour;
    }
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
    let frame3 = fragment_frame(in);
    var n = frame3.n;
    if material.flags.x == 1u {
        let texel = textureSample(normal_map, surface_sampler, in.uv).xyz;
        n = mapped_normal(frame3, texel, options.flip_green == 1u);
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
    let frame3 = fragment_frame(in);
    let third = u32(3.0 * in.clip_position.x / options.target_width);
    let v = select(select(frame3.n, frame3.b, third == 1u), frame3.t, third == 0u);
    return vec4<f32>(v * 0.5 + 0.5, 1.0);
}
