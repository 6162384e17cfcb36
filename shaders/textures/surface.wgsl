// Chapter 09: a textured surface, as a module. Vertices placed by their
// instances, the material's bindings, the surface's frame (tangent, bitangent, normal) at a fragment, and a
// normal map's texel turned into a direction. Chapter 09's textured.wgsl
// imports it, and so does chapter 10's scene shader.
#define_import_path textures::surface

// ANCHOR: vertex
// A vertex of a model (mesh.rs: TexturedVertex) and the instance that
// places it (ModelInstance): its model matrix by columns, and its normal
// matrix. (Names ending in a digit would be renamed by the import.) The
// vertex's colour is white unless the model's file gives one.
struct Vertex {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) uv: vec2<f32>,
    @location(3) tangent: vec4<f32>,
    @location(12) colour: vec3<f32>,
};

struct Instance {
    @location(4) model_x: vec4<f32>,
    @location(5) model_y: vec4<f32>,
    @location(6) model_z: vec4<f32>,
    @location(7) model_w: vec4<f32>,
    @location(8) normal_x: vec4<f32>,
    @location(9) normal_y: vec4<f32>,
    @location(10) normal_z: vec4<f32>,
    @location(11) glow: f32,
};

// A vertex moved into the world by its instance.
struct Placed {
    world: vec3<f32>,
    normal: vec3<f32>,
    tangent: vec4<f32>,
};

fn place(vertex: Vertex, instance: Instance) -> Placed {
    let model = mat4x4<f32>(instance.model_x, instance.model_y, instance.model_z, instance.model_w);
    let normal_matrix = mat3x3<f32>(instance.normal_x.xyz, instance.normal_y.xyz, instance.normal_z.xyz);
    // A tangent lies along the surface, like an edge: it moves with the
    // model matrix itself. The normal needs the inverse transpose (chapter 02).
    let tangent = (model * vec4<f32>(vertex.tangent.xyz, 0.0)).xyz;
    // A mirroring model matrix turns the frame inside out: flip handedness.
    let mirrored = determinant(mat3x3<f32>(model[0].xyz, model[1].xyz, model[2].xyz)) < 0.0;
    let handedness = select(vertex.tangent.w, -vertex.tangent.w, mirrored);
    let world = (model * vec4<f32>(vertex.position, 1.0)).xyz;
    return Placed(world, normal_matrix * vertex.normal, vec4<f32>(tangent, handedness));
}

// What a textured surface's vertex hands its fragments: where it is on
// screen (through `view_proj`) and in the world, its frame, its texture
// coordinates, its instance's glow and its colour.
struct Varyings {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) world: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) uv: vec2<f32>,
    @location(3) tangent: vec4<f32>,
    @location(4) glow: f32,
    @location(5) colour: vec3<f32>,
};

fn vary(vertex: Vertex, instance: Instance, view_proj: mat4x4<f32>) -> Varyings {
    let placed = place(vertex, instance);
    let clip = view_proj * vec4<f32>(placed.world, 1.0);
    return Varyings(clip, placed.world, placed.normal, vertex.uv, placed.tangent, instance.glow, vertex.colour);
}
// ANCHOR_END: vertex

// ANCHOR: material
// 64 bytes, as MaterialUniform in materials.rs.
struct Material {
    diffuse: vec3<f32>,
    specular: f32,
    emissive: vec3<f32>,
    shininess: f32,
    // x: has a normal map, y: has an albedo map (its alpha masks the
    // emissive light), z: glows only at night, w: the vertices' colours
    // multiply the diffuse colour.
    flags: vec4<u32>,
    // x: roughness, y: metalness, for Cook-Torrance (an MTL's Pr and Pm, or
    // the roughness Ns gives).
    physical: vec4<f32>,
};
@group(1) @binding(0) var albedo_map: texture_2d<f32>;
@group(1) @binding(1) var normal_map: texture_2d<f32>;
// Storage, not uniform: `textured.wgsl` branches on `flags`, and lavapipe
// would compile a new shader for every material bound (lights.wgsl's `frame`).
@group(1) @binding(2) var<storage, read> material: Material;
// ANCHOR: physical_maps
// An MTL's map_Pr and map_Pm, read as data: their red channel (a grey
// image's value) multiplies the roughness and metalness; white where a
// material has none.
@group(1) @binding(3) var roughness_map: texture_2d<f32>;
@group(1) @binding(4) var metallic_map: texture_2d<f32>;

// Roughness and metalness at `uv`: the material's, times its maps'.
fn physical_at(uv: vec2<f32>, maps: sampler) -> vec2<f32> {
    let roughness = textureSample(roughness_map, maps, uv).r;
    let metallic = textureSample(metallic_map, maps, uv).r;
    return material.physical.xy * vec2<f32>(roughness, metallic);
}
// ANCHOR_END: physical_maps
// ANCHOR_END: material

// ANCHOR: tbn
// The surface's frame at a fragment. Interpolation has shortened the
// normal and tilted the tangent off it: normalise the normal, then take
// out of the tangent its part along the normal (Gram–Schmidt) and
// normalise that. The bitangent, "up the image", is w · (N × T).
struct Frame3 {
    t: vec3<f32>,
    b: vec3<f32>,
    n: vec3<f32>,
};

fn surface_frame(normal: vec3<f32>, tangent: vec4<f32>) -> Frame3 {
    let n = normalize(normal);
    let t = normalize(tangent.xyz - n * dot(n, tangent.xyz));
    let b = tangent.w * cross(n, t);
    return Frame3(t, b, n);
}

// A texel of a normal map, from 0..1 back to a direction in that frame.
// `flip_green` reads green as pointing down the image (DirectX's maps).
fn mapped_normal(frame3: Frame3, texel: vec3<f32>, flip_green: bool) -> vec3<f32> {
    var m = texel * 2.0 - 1.0;
    if flip_green {
        m.y = -m.y;
    }
    return normalize(mat3x3<f32>(frame3.t, frame3.b, frame3.n) * m);
}
// ANCHOR_END: tbn
