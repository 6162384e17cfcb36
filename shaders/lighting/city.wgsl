// Chapter 08: the city, lit three ways. Every piece is an instance of one of
// the primitive meshes; its model matrix, normal matrix and material come
// per instance. The three shading models differ only in where they call the
// same `light_surface`: once per face, per vertex, or per fragment.
#import lighting::lights::{frame, Surface, light_surface, heat}

// 64 bytes, as GpuMaterial in city_meshes.rs. Emissive light is already
// scaled by how much it shows now (lamps only at night). The albedo turns
// into albedo_high between the heights high_from and high_to: the
// countryside's sand and grass; other materials have one colour both ways.
struct Material {
    albedo: vec3<f32>,
    specular: f32,
    emissive: vec3<f32>,
    shininess: f32,
    albedo_high: vec3<f32>,
    high_from: f32,
    high_to: f32,
    // Cook-Torrance's: 0 a mirror to 1 chalk, and 0 a non-metal or 1 a metal.
    roughness: f32,
    metallic: f32,
};
@group(1) @binding(0) var<storage, read> materials: array<Material>;

struct Vertex {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) uv: vec2<f32>,
};

// ANCHOR: instance
// One piece of the city: where it is, and the inverse transpose of that for
// its normals (chapter 02), and what it is made of.
struct Instance {
    @location(3) model_0: vec4<f32>,
    @location(4) model_1: vec4<f32>,
    @location(5) model_2: vec4<f32>,
    @location(6) model_3: vec4<f32>,
    @location(7) normal_0: vec3<f32>,
    @location(8) normal_1: vec3<f32>,
    @location(9) normal_2: vec3<f32>,
    @location(10) material: u32,
};
// ANCHOR_END: instance

struct Placed {
    world: vec3<f32>,
    normal: vec3<f32>,
    material: u32,
};

fn place(vertex: Vertex, instance: Instance) -> Placed {
    let model = mat4x4<f32>(instance.model_0, instance.model_1, instance.model_2, instance.model_3);
    let normal_matrix = mat3x3<f32>(instance.normal_0, instance.normal_1, instance.normal_2);
    let world = (model * vec4<f32>(vertex.position, 1.0)).xyz;
    return Placed(world, normalize(normal_matrix * vertex.normal), instance.material);
}

// ANCHOR: by_height
// The surface at a point `world`: its colour blended by height (countryside.rs:
// ground_colour), the same formula for every material.
fn surface_of(material: Material, world: vec3<f32>) -> Surface {
    let high = smoothstep(material.high_from, material.high_to, world.y);
    let albedo = mix(material.albedo, material.albedo_high, high);
    return Surface(albedo, material.specular, material.shininess, material.roughness, material.metallic);
}
// ANCHOR_END: by_height

// ANCHOR: phong
// Phong shading: the normal is interpolated, and each fragment is lit.
struct PhongOutput {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) world: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) @interpolate(flat) material: u32,
};

@vertex
fn vs_phong(vertex: Vertex, instance: Instance) -> PhongOutput {
    let placed = place(vertex, instance);
    return PhongOutput(frame.view_proj * vec4<f32>(placed.world, 1.0), placed.world, placed.normal, placed.material);
}

@fragment
fn fs_phong(in: PhongOutput) -> @location(0) vec4<f32> {
    if frame.options.w == 1u {
        return vec4<f32>(heat(in.world), 1.0);
    }
    let material = materials[in.material];
    let lit = light_surface(in.world, normalize(in.normal), surface_of(material, in.world));
    return vec4<f32>(lit + material.emissive, 1.0);
}
// ANCHOR_END: phong

// ANCHOR: gouraud
// Gouraud shading: each vertex is lit, and the colour is interpolated.
struct LitOutput {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) world: vec3<f32>,
    @location(1) colour: vec3<f32>,
};

fn lit_vertex(vertex: Vertex, instance: Instance) -> LitOutput {
    let placed = place(vertex, instance);
    let material = materials[placed.material];
    let lit = light_surface(placed.world, placed.normal, surface_of(material, placed.world)) + material.emissive;
    return LitOutput(frame.view_proj * vec4<f32>(placed.world, 1.0), placed.world, lit);
}

@vertex
fn vs_gouraud(vertex: Vertex, instance: Instance) -> LitOutput {
    return lit_vertex(vertex, instance);
}

@fragment
fn fs_gouraud(in: LitOutput) -> @location(0) vec4<f32> {
    if frame.options.w == 1u {
        return vec4<f32>(heat(in.world), 1.0);
    }
    return vec4<f32>(in.colour, 1.0);
}
// ANCHOR_END: gouraud

// ANCHOR: flat
// Flat shading: the mesh's vertices are split so each face has its own
// normal (see `faceted` in city_meshes.rs); all three of a face's vertices
// are lit, and the colour of its first, the provoking vertex, is kept for
// the whole face, not interpolated: one colour per face.
struct FlatOutput {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) world: vec3<f32>,
    @location(1) @interpolate(flat) colour: vec3<f32>,
};

@vertex
fn vs_flat(vertex: Vertex, instance: Instance) -> FlatOutput {
    let lit = lit_vertex(vertex, instance);
    return FlatOutput(lit.clip_position, lit.world, lit.colour);
}

@fragment
fn fs_flat(in: FlatOutput) -> @location(0) vec4<f32> {
    if frame.options.w == 1u {
        return vec4<f32>(heat(in.world), 1.0);
    }
    return vec4<f32>(in.colour, 1.0);
}
// ANCHOR_END: flat
