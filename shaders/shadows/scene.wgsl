// Chapter 10: the level's surfaces, textured as in chapter 09 and lit as
// in chapter 08, with the sun's light taken away where the shadow map says
// something stands between the surface and the sun.
#import lighting::lights::{frame, Surface, light_surface_sunlit}
#import textures::surface::{Vertex, Instance, Varyings, vary, material, albedo_map, normal_map, surface_frame, mapped_normal}
#import shadows::shadow::sunlit

@group(2) @binding(0) var surface_sampler: sampler;

@vertex
fn vs_main(vertex: Vertex, instance: Instance) -> Varyings {
    return vary(vertex, instance, frame.view_proj);
}

// ANCHOR: fragment
@fragment
fn fs_main(in: Varyings) -> @location(0) vec4<f32> {
    let frame3 = surface_frame(in.normal, in.tangent);
    var n = frame3.n;
    if material.flags.x == 1u {
        n = mapped_normal(frame3, textureSample(normal_map, surface_sampler, in.uv).xyz, false);
    }
    let albedo_texel = textureSample(albedo_map, surface_sampler, in.uv);
    // The shadow is looked up with the surface's own normal, not the
    // normal map's: the map's bumps are finer than a shadow texel.
    let sun = sunlit(in.world, frame3.n, in.clip_position.xy);
    let albedo = material.diffuse * albedo_texel.rgb;
    let lit = light_surface_sunlit(in.world, n, Surface(albedo, material.specular, material.shininess), sun);
    let mask = select(1.0, albedo_texel.a, material.flags.y == 1u);
    return vec4<f32>(lit + material.emissive * mask * in.glow, 1.0);
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
