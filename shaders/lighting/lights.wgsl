// Chapter 08: lights, and the one loop that adds them up.
// A module: the city's shaders (and chapter 09's) `#import lighting::lights`
// and call `light_surface` per fragment (Phong), per vertex (Gouraud) or
// per face (flat). The falloff, cone and cluster arithmetic match lights.rs
// and clusters.rs, which the tests check.
#define_import_path lighting::lights

#import lighting::brdf::{MIN_ROUGHNESS, cook_torrance, fresnel_f0, roughness_from_shininess}
#import lighting::sky_light::{PI, sh_irradiance}

// ANCHOR: frame
struct Frame {
    view_proj: mat4x4<f32>,
    view: mat4x4<f32>,
    eye: vec4<f32>,
    // xyz: towards the sun.
    sun_direction: vec4<f32>,
    // The sun's light and the sky's (ambient), linear RGB.
    sun_colour: vec4<f32>,
    ambient: vec4<f32>,
    // x: lights in use, y: 1 to read cluster lists (0: every light, the
    // naive loop), z: how surfaces reflect (0: Phong's highlight, 1:
    // Blinn-Phong's, 2: Cook-Torrance, brdf.wgsl), w: 1 to show lights per
    // fragment as a heat map.
    options: vec4<u32>,
    // x: near, y: far, z: ln(far / near); w: how much emissive glow shows (night).
    depth: vec4<f32>,
    // Clusters across, down and deep (clusters.rs: GRID).
    grid: vec4<u32>,
};
// A read-only storage buffer, not a uniform one, although it is small and
// the same for every fragment: the loop below runs `options.x` times and
// branches on `options.y` and `.w`, and Mesa's lavapipe (22.3, Debian 12)
// can write the uniform values a large shader reads into a copy of it,
// one copy for each set of values it is bound with, every copy kept (it
// stops where the first copy is not half the size or less, unless the
// values are read often enough for it to insist): megabytes a frame for
// this chapter. See the book's chapter 08 pitfalls.
@group(0) @binding(0) var<storage, read> frame: Frame;

// 64 bytes, as GpuLight in lights.rs. A point light has cos_inner = −2
// and cos_outer = −3: every direction is inside its "cone".
struct Light {
    position: vec3<f32>,
    range: f32,
    colour: vec3<f32>,
    cos_inner: f32,
    direction: vec3<f32>,
    cos_outer: f32,
    padding: vec4<f32>,
};
@group(0) @binding(1) var<storage, read> lights: array<Light>;
// Per cluster: (first index in cluster_lights, how many).
@group(0) @binding(2) var<storage, read> cluster_ranges: array<vec2<u32>>;
@group(0) @binding(3) var<storage, read> cluster_lights: array<u32>;
// The split-sum table (pbr.rs: BrdfTable), for Cook-Torrance's sky light.
@group(0) @binding(4) var brdf_table: texture_2d<f32>;
@group(0) @binding(5) var brdf_sampler: sampler;
// The sky's radiance in nine spherical harmonics (irradiance.rs).
@group(0) @binding(6) var<storage, read> sky_harmonics: array<vec4<f32>, 9>;
// The sky blurred for each roughness, one mip level each (prefilter.wgsl).
@group(0) @binding(7) var sky_cube: texture_cube<f32>;
@group(0) @binding(8) var sky_sampler: sampler;
// ANCHOR_END: frame

// How a surface answers light (chapter 09 fills it from textures): Phong's
// strength and sharpness of the highlight, or Cook-Torrance's roughness
// and metalness, with the albedo as base colour.
struct Surface {
    albedo: vec3<f32>,
    specular: f32,
    shininess: f32,
    roughness: f32,
    metallic: f32,
};

// A surface described the Phong way only: for Cook-Torrance a non-metal,
// with the roughness read from the shininess (pbr.rs says by what rule).
fn phong_surface(albedo: vec3<f32>, specular: f32, shininess: f32) -> Surface {
    return Surface(albedo, specular, shininess, roughness_from_shininess(shininess), 0.0);
}

// ANCHOR: falloff
// Inverse-square, windowed to exactly zero at the range (lights.rs explains).
fn attenuation(distance: f32, range: f32) -> f32 {
    let ratio = distance / range;
    let window = clamp(1.0 - ratio * ratio * ratio * ratio, 0.0, 1.0);
    return window * window / (distance * distance + 1.0);
}

fn spot_factor(cos_angle: f32, cos_inner: f32, cos_outer: f32) -> f32 {
    return smoothstep(cos_outer, cos_inner, cos_angle);
}
// ANCHOR_END: falloff

// ANCHOR: reflect
// What a surface with normal n, seen from direction v, reflects of light
// arriving from direction l with `radiance`: Lambert's diffuse, plus a
// highlight, Phong's (the mirror direction against the view) or Blinn's
// (the half vector against the normal). Each highlight is scaled by its
// normalisation, (s + 2) / 2 or (s + 8) / 8, so that a sharper highlight is
// brighter, not only smaller: the light it reflects stays about the same.
fn reflected(surface: Surface, n: vec3<f32>, v: vec3<f32>, l: vec3<f32>, radiance: vec3<f32>) -> vec3<f32> {
    let n_dot_l = dot(n, l);
    // A face turned away from the light gets nothing, highlight included.
    if n_dot_l <= 0.0 {
        return vec3<f32>(0.0);
    }
    if frame.options.z == 2u {
        return radiance * n_dot_l * cook_torrance(n, v, l, surface.albedo, surface.metallic, surface.roughness);
    }
    var highlight: f32;
    let s = surface.shininess;
    if frame.options.z == 1u {
        let h = normalize(l + v);
        highlight = (s + 8.0) / 8.0 * pow(max(dot(n, h), 0.0), s);
    } else {
        let r = reflect(-l, n);
        highlight = (s + 2.0) / 2.0 * pow(max(dot(r, v), 0.0), s);
    }
    return radiance * n_dot_l * (surface.albedo + vec3<f32>(surface.specular * highlight));
}
// ANCHOR_END: reflect

// ANCHOR: sky_light
// The sky's light a surface reflects towards v. For Phong's models, albedo
// times the ambient colour, the same whichever way the surface faces. For
// Cook-Torrance, the sky itself: its body diffuses the irradiance the
// harmonics give for its normal, where it is not a metal; its facets
// reflect the sky seen in the mirror direction, blurred for its roughness
// (the prefiltered cube's level), times what the split-sum table says
// they reflect, f0 × A + B.
fn sky_light(surface: Surface, n: vec3<f32>, v: vec3<f32>) -> vec3<f32> {
    if frame.options.z != 2u {
        return surface.albedo * frame.ambient.rgb;
    }
    let n_dot_v = clamp(dot(n, v), 0.0, 1.0);
    let roughness = clamp(surface.roughness, MIN_ROUGHNESS, 1.0);
    let split = textureSampleLevel(brdf_table, brdf_sampler, vec2<f32>(n_dot_v, roughness), 0.0).xy;
    let specular = fresnel_f0(surface.albedo, surface.metallic) * split.x + split.y;
    let diffuse = (vec3<f32>(1.0) - specular) * (1.0 - clamp(surface.metallic, 0.0, 1.0)) * surface.albedo;
    // Level 0 is a mirror's sky, the last roughness 1's (prefiltered_sky.rs):
    // by the roughness as given, since the cube needs no floor to stay finite.
    let level = clamp(surface.roughness, 0.0, 1.0) * f32(textureNumLevels(sky_cube) - 1u);
    let mirrored = textureSampleLevel(sky_cube, sky_sampler, reflect(-v, n), level).rgb;
    return diffuse * sh_irradiance(sky_harmonics, n) / PI + specular * mirrored;
}
// ANCHOR_END: sky_light

// ANCHOR: cluster
// The cluster a world position falls in, or −1 outside the view (the same
// arithmetic as clusters.rs).
fn cluster_at(world: vec3<f32>) -> i32 {
    let clip = frame.view_proj * vec4<f32>(world, 1.0);
    let depth = -(frame.view * vec4<f32>(world, 1.0)).z;
    if clip.w <= 0.0 || depth < frame.depth.x || depth > frame.depth.y {
        return -1;
    }
    let ndc = clip.xy / clip.w;
    if abs(ndc.x) > 1.0 || abs(ndc.y) > 1.0 {
        return -1;
    }
    let grid = frame.grid;
    let x = min(u32((ndc.x + 1.0) * 0.5 * f32(grid.x)), grid.x - 1u);
    let y = min(u32((1.0 - ndc.y) * 0.5 * f32(grid.y)), grid.y - 1u);
    let slice = floor(log(depth / frame.depth.x) / frame.depth.z * f32(grid.z));
    let z = u32(clamp(slice, 0.0, f32(grid.z - 1u)));
    return i32((z * grid.y + y) * grid.x + x);
}

// The lights to loop over at `world`: (first, count, from a cluster list?).
fn lights_at(world: vec3<f32>) -> vec3<u32> {
    let cluster = cluster_at(world);
    if frame.options.y == 1u && cluster >= 0 {
        let range = cluster_ranges[cluster];
        return vec3<u32>(range.x, range.y, 1u);
    }
    return vec3<u32>(0u, frame.options.x, 0u);
}
// ANCHOR_END: cluster

// ANCHOR: loop
// The light reaching a surface at `world` with normal n, seen from the eye:
// ambient, the sun, and every light that can reach it. The one loop that
// flat, Gouraud and Phong shading all call; only where it is called from
// differs.
fn light_surface(world: vec3<f32>, n: vec3<f32>, surface: Surface) -> vec3<f32> {
    return light_surface_sunlit(world, n, surface, 1.0);
}

// The same, with only `sunlit` of the sun's light arriving (0 in shadow,
// 1 in full sun): chapter 10 passes what its shadow map says.
fn light_surface_sunlit(world: vec3<f32>, n: vec3<f32>, surface: Surface, sunlit: f32) -> vec3<f32> {
    let v = normalize(frame.eye.xyz - world);
    var colour = sky_light(surface, n, v);
    colour += reflected(surface, n, v, frame.sun_direction.xyz, frame.sun_colour.rgb * sunlit);
    let list = lights_at(world);
    for (var k = 0u; k < list.y; k++) {
        var i = k;
        if list.z == 1u {
            i = cluster_lights[list.x + k];
        }
        let light = lights[i];
        let to_light = light.position - world;
        let distance = length(to_light);
        let l = to_light / max(distance, 1e-4);
        let cone = spot_factor(dot(-l, light.direction), light.cos_inner, light.cos_outer);
        let radiance = light.colour * attenuation(distance, light.range) * cone;
        colour += reflected(surface, n, v, l, radiance);
    }
    return colour;
}
// ANCHOR_END: loop

// A colour for the number of lights the loop visits at `world`: black for
// none, through blue and green, to red at 24 and more.
fn heat(world: vec3<f32>) -> vec3<f32> {
    let count = f32(lights_at(world).y);
    let t = clamp(count / 24.0, 0.0, 1.0);
    let cold = mix(vec3<f32>(0.0, 0.0, 0.0), vec3<f32>(0.0, 0.1, 1.0), smoothstep(0.0, 0.05, t));
    let warm = mix(vec3<f32>(0.0, 1.0, 0.3), vec3<f32>(1.0, 0.1, 0.0), smoothstep(0.5, 1.0, t));
    return mix(cold, warm, smoothstep(0.05, 0.5, t));
}
