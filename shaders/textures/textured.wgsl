// Chapter 09: textured, normal-mapped surfaces, lit by chapter 08's light
// loop. The albedo map gives the colour (decoded from sRGB by the texture
// format), the normal map bends the normal in the surface's own frame
// (tangent, bitangent, normal), and `light_surface` does the rest. Lit per
// fragment (Phong shading), per vertex (Gouraud) or per face (flat), as
// chapter 08's city is; the textures are read per fragment in all three.
#import lighting::lights::{frame, Surface, light_surface, phong_surface}
#import textures::surface::{Vertex, Instance, Varyings, vary, material, albedo_map, normal_map, physical_at, Frame3, surface_frame, mapped_normal}

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
// The surface's colour at a fragment: the material's, times the albedo
// map's texel there.
fn albedo_at(colour: vec3<f32>, albedo_texel: vec4<f32>) -> vec3<f32> {
    var albedo = material.diffuse * albedo_texel.rgb;
    // Vertex colours (OBJ's `v x y z r g b`) tint it, where the model has them.
    if material.flags.w == 1u {
        albedo *= colour;
    }
    return albedo;
}

// The light the surface gives off of its own at a fragment: an albedo
// map's alpha says where the material glows (lit windows).
fn glow_at(glow: f32, albedo_texel: vec4<f32>) -> vec3<f32> {
    let mask = select(1.0, albedo_texel.a, material.flags.y == 1u);
    let night = select(1.0, frame.depth.w, material.flags.z == 1u);
    return material.emissive * mask * night * glow;
}

// The light a surface with normal n sends to the eye, and its own glow.
fn shade(in: Varyings, n: vec3<f32>, albedo_texel: vec4<f32>) -> vec4<f32> {
    let albedo = albedo_at(in.colour, albedo_texel);
    let physical = physical_at(in.uv, surface_sampler);
    let lit = light_surface(in.world, n, Surface(albedo, material.specular, material.shininess, physical.x, physical.y));
    return vec4<f32>(lit + glow_at(in.glow, albedo_texel), 1.0);
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

// ANCHOR: gouraud
// Gouraud shading: each vertex is lit, and the light is interpolated. The
// texture is still read per fragment, so the vertex hands on the light,
// not a colour: what arrives per unit of albedo (the sky's and the
// diffuse light) and the highlights, which do not depend on the albedo.
// The fragment multiplies the first by its texel and adds the second.
// There is no normal at a texel to bend here: normal maps are left out.
struct LitVaryings {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) uv: vec2<f32>,
    @location(1) glow: f32,
    @location(2) colour: vec3<f32>,
    @location(3) received: vec3<f32>,
    @location(4) highlights: vec3<f32>,
};

@vertex
fn vs_gouraud(vertex: Vertex, instance: Instance) -> LitVaryings {
    let v = vary(vertex, instance, frame.view_proj);
    let n = normalize(v.normal);
    // light_surface adds albedo × (sky + diffuse) and specular × highlights:
    // with albedo 1 and no specular it returns the first light, with albedo
    // 0 the second. Two loops, and chapter 08's lights.wgsl as it is.
    let received = light_surface(v.world, n, phong_surface(vec3<f32>(1.0), 0.0, material.shininess));
    let highlights = light_surface(v.world, n, phong_surface(vec3<f32>(0.0), material.specular, material.shininess));
    return LitVaryings(v.clip_position, v.uv, v.glow, v.colour, received, highlights);
}

@fragment
fn fs_gouraud(in: LitVaryings) -> @location(0) vec4<f32> {
    let texel = textureSample(albedo_map, surface_sampler, in.uv);
    let lit = albedo_at(in.colour, texel) * in.received + in.highlights;
    return vec4<f32>(lit + glow_at(in.glow, texel), 1.0);
}
// ANCHOR_END: gouraud

// ANCHOR: flat
// Flat shading: one light per face. Chapter 08 gives each face vertices of
// its own carrying the face's normal; a model of a million triangles would
// need three million vertices for that. Here every fragment of a face asks
// the loop the same question instead: the light at the face's first
// corner (the provoking vertex's position, not interpolated), for the
// plane the face lies in. That plane's normal comes from how the world
// position changes from one pixel to the next, `dpdx` and `dpdy` (the
// sampler takes the same derivatives of the texture coordinates to pick a
// mip level). Only the albedo, read per fragment, changes across the face.
struct FlatVaryings {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) world: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) uv: vec2<f32>,
    @location(3) glow: f32,
    @location(4) colour: vec3<f32>,
    @location(5) @interpolate(flat) corner: vec3<f32>,
};

@vertex
fn vs_flat(vertex: Vertex, instance: Instance) -> FlatVaryings {
    let v = vary(vertex, instance, frame.view_proj);
    return FlatVaryings(v.clip_position, v.world, v.normal, v.uv, v.glow, v.colour, v.world);
}

@fragment
fn fs_flat(in: FlatVaryings) -> @location(0) vec4<f32> {
    // Two directions along the face; across them, its normal, turned to
    // the side the model's own normals face. (A face seen exactly edge-on
    // has no width to measure: it keeps the interpolated normal.)
    let across = cross(dpdx(in.world), dpdy(in.world));
    let outwards = select(across, -across, dot(across, in.normal) < 0.0);
    let face = select(normalize(in.normal), normalize(outwards), dot(across, across) > 1e-30);
    let texel = textureSample(albedo_map, surface_sampler, in.uv);
    let physical = physical_at(in.uv, surface_sampler);
    let lit = light_surface(in.corner, face, Surface(albedo_at(in.colour, texel), material.specular, material.shininess, physical.x, physical.y));
    return vec4<f32>(lit + glow_at(in.glow, texel), 1.0);
}
// ANCHOR_END: flat

// The tangent frame as colours: the left third of the picture shows the
// tangent, the middle the bitangent, the right the normal.
@fragment
fn fs_frame(in: Varyings) -> @location(0) vec4<f32> {
    let frame3 = fragment_frame(in);
    let third = u32(3.0 * in.clip_position.x / options.target_width);
    let v = select(select(frame3.n, frame3.b, third == 1u), frame3.t, third == 0u);
    return vec4<f32>(v * 0.5 + 0.5, 1.0);
}
