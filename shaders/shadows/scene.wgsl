// Chapter 10: the level's surfaces, textured as in chapter 09 and lit as
// in chapter 08, with the sun's light taken away where the shadow map says
// something stands between the surface and the sun, and (`fs_lantern`) a
// lantern's light taken away where its cube shadow map says the same.
#import lighting::lights::{frame, Surface, light_surface_sunlit}
#import textures::surface::{Vertex, Instance, Varyings, vary, material, albedo_map, normal_map, physical_at, surface_frame, mapped_normal}
#import shadows::shadow::sunlit
#import shadows::point_shadow::{point_lit, shadowed_point_light}

@group(2) @binding(0) var surface_sampler: sampler;

@vertex
fn vs_main(vertex: Vertex, instance: Instance) -> Varyings {
    return vary(vertex, instance, frame.view_proj);
}

// ANCHOR: fragment
// A fragment's surface, from its material and textures: what it reflects,
// its own normal and the one it is shaded with, and its own light.
struct Shaded {
    surface: Surface,
    geometric: vec3<f32>,
    n: vec3<f32>,
    emitted: vec3<f32>,
};

fn shaded(in: Varyings) -> Shaded {
    let frame3 = surface_frame(in.normal, in.tangent);
    var n = frame3.n;
    if material.flags.x == 1u {
        n = mapped_normal(frame3, textureSample(normal_map, surface_sampler, in.uv).xyz, false);
    }
    let albedo_texel = textureSample(albedo_map, surface_sampler, in.uv);
    let albedo = material.diffuse * albedo_texel.rgb;
    let mask = select(1.0, albedo_texel.a, material.flags.y == 1u);
    let physical = physical_at(in.uv, surface_sampler);
    let surface = Surface(albedo, material.specular, material.shininess, physical.x, physical.y);
    return Shaded(surface, frame3.n, n, material.emissive * mask * in.glow);
}

@fragment
fn fs_main(in: Varyings) -> @location(0) vec4<f32> {
    let s = shaded(in);
    // The shadow is looked up with the surface's own normal, not the
    // normal map's: the map's bumps are finer than a shadow texel.
    let sun = sunlit(in.world, s.geometric, in.clip_position.xy);
    let lit = light_surface_sunlit(in.world, s.n, s.surface, sun);
    return vec4<f32>(lit + s.emitted, 1.0);
}

// The same, and the lantern, shadowed by its cube.
@fragment
fn fs_lantern(in: Varyings) -> @location(0) vec4<f32> {
    let s = shaded(in);
    let sun = sunlit(in.world, s.geometric, in.clip_position.xy);
    let lit = light_surface_sunlit(in.world, s.n, s.surface, sun);
    let lantern = shadowed_point_light(in.world, s.geometric, s.n, s.surface);
    return vec4<f32>(lit + lantern + s.emitted, 1.0);
}
// ANCHOR_END: fragment

// What the shadow test reads: red is how much sun arrives, green is 1
// where the surface faces the sun (where a shadow is the only reason for
// darkness).
@fragment
fn fs_sunlit(in: Varyings) -> @location(0) vec4<f32> {
    let n = normalize(in.normal);
    let facing = dot(n, frame.sun_direction.xyz) > 0.05;
    return vec4<f32>(sunlit(in.world, n, in.clip_position.xy), select(0.0, 1.0, facing), 0.0, 1.0);
}

// The same, with blue for how much of the lantern's light arrives (its
// cube's answer, 1 where nothing is asked: beyond its range, or with no filter).
@fragment
fn fs_lantern_sunlit(in: Varyings) -> @location(0) vec4<f32> {
    let n = normalize(in.normal);
    let facing = dot(n, frame.sun_direction.xyz) > 0.05;
    return vec4<f32>(sunlit(in.world, n, in.clip_position.xy), select(0.0, 1.0, facing), point_lit(in.world, n), 1.0);
}
