// Chapter 08: physically based shading. A microfacet BRDF: the surface is
// taken to be tiny mirrors whose normals spread by GGX's distribution (D),
// some of which hide others (the visibility V, Smith's height-correlated
// masking and shadowing), each reflecting by Fresnel's law (F, Schlick's
// approximation). pbr.rs holds the same formulas, which the tests integrate.
// Pure functions, no bindings: lights.wgsl shades with them,
// brdf_table.wgsl integrates them into the split-sum table, and
// prefilter.wgsl blurs the sky by them.
#define_import_path lighting::brdf

const PI: f32 = 3.14159265358979;

// ANCHOR: parameters
// Below this roughness a highlight would be a point: α = 0 makes D a
// spike of zero width and infinite height (0/0 at its peak).
const MIN_ROUGHNESS: f32 = 0.045;
// The Fresnel reflectance of non-metals seen head on: 4 %.
const DIELECTRIC_F0: f32 = 0.04;

// GGX's width α from the roughness a learner sets: α = roughness², so that
// equal steps of roughness look like equal steps (Burley 2012).
fn ggx_alpha(roughness: f32) -> f32 {
    let r = clamp(roughness, MIN_ROUGHNESS, 1.0);
    return r * r;
}

// The roughness for a Phong exponent, for surfaces described only by one
// (pbr.rs: roughness_from_shininess says by what rule).
fn roughness_from_shininess(shininess: f32) -> f32 {
    return pow(2.0 / (max(shininess, 0.0) + 2.0), 0.25);
}

// Head-on reflectance: 4 % for non-metals, the base colour for metals.
fn fresnel_f0(base_colour: vec3<f32>, metallic: f32) -> vec3<f32> {
    return mix(vec3<f32>(DIELECTRIC_F0), base_colour, clamp(metallic, 0.0, 1.0));
}
// ANCHOR_END: parameters

// ANCHOR: terms
// D: the density of microfacet normals around h (Trowbridge and Reitz
// 1975, Walter et al. 2007), per steradian of h, normalised so that the
// facets' projected area sums to the surface's.
fn ggx_distribution(n_dot_h: f32, alpha: f32) -> f32 {
    let a2 = alpha * alpha;
    let d = n_dot_h * n_dot_h * (a2 - 1.0) + 1.0;
    return a2 / (PI * d * d);
}

// V = G / (4 n·l n·v): the share of facets both lit and seen, Smith's
// height-correlated form for GGX (Heitz 2014), divided by the
// microfacet model's 4 n·l n·v, which cancels it.
fn smith_visibility(n_dot_v: f32, n_dot_l: f32, alpha: f32) -> f32 {
    let a2 = alpha * alpha;
    let seen = n_dot_l * sqrt(n_dot_v * n_dot_v * (1.0 - a2) + a2);
    let lit = n_dot_v * sqrt(n_dot_l * n_dot_l * (1.0 - a2) + a2);
    return 0.5 / (seen + lit);
}

// F: how much a facet reflects, by the angle between light and facet
// (Schlick 1994): f0 head on, rising to 1 at grazing.
fn fresnel_schlick(f0: vec3<f32>, v_dot_h: f32) -> vec3<f32> {
    let grazing = pow(1.0 - clamp(v_dot_h, 0.0, 1.0), 5.0);
    return f0 + (vec3<f32>(1.0) - f0) * grazing;
}
// ANCHOR_END: terms

// ANCHOR: cook_torrance
// The BRDF times π, for light arriving from l and leaving towards v over
// a surface with normal n (all unit vectors, n·l and n·v positive): the
// course's lights are scaled so that Lambert's diffuse is albedo × light
// × n·l, which is π × albedo/π. The diffuse part is the light that
// Fresnel lets into the surface on the way in, at the light's angle, and
// out again, at the eye's (weighted by F at the facet alone, it would send
// back half as much again as arrives when seen at a grazing angle: the
// white-furnace test catches it). Metals absorb what they refract, so they
// have none.
fn cook_torrance(
    n: vec3<f32>, v: vec3<f32>, l: vec3<f32>, base_colour: vec3<f32>, metallic: f32, roughness: f32,
) -> vec3<f32> {
    let h = normalize(l + v);
    let n_dot_v = max(dot(n, v), 1e-4);
    let n_dot_l = max(dot(n, l), 0.0);
    let alpha = ggx_alpha(roughness);
    let f = fresnel_schlick(fresnel_f0(base_colour, metallic), dot(v, h));
    let specular = f * (ggx_distribution(max(dot(n, h), 0.0), alpha) * smith_visibility(n_dot_v, n_dot_l, alpha) * PI);
    let f0 = fresnel_f0(base_colour, metallic);
    let through = (vec3<f32>(1.0) - fresnel_schlick(f0, n_dot_l)) * (vec3<f32>(1.0) - fresnel_schlick(f0, n_dot_v));
    let diffuse = through * (1.0 - clamp(metallic, 0.0, 1.0)) * base_colour;
    return diffuse + specular;
}
// ANCHOR_END: cook_torrance

// ANCHOR: sampling
// Importance sampling, for the integrals the compute passes take over GGX
// (brdf_table.wgsl, prefilter.wgsl).
// The i-th of n points spread evenly over the unit square (Hammersley):
// i / n across, and i's bits mirrored about the binary point down.
fn hammersley(i: u32, n: u32) -> vec2<f32> {
    return vec2<f32>(f32(i) / f32(n), f32(reverseBits(i)) * 2.3283064365386963e-10);
}

// A half vector drawn with density D(h) n·h about the normal +z: the
// inverse of GGX's cumulative distribution in cos θ (Walter et al. 2007
// give it as θ = arctan(α √u / √(1 − u)), the same).
fn ggx_half_vector(u: vec2<f32>, alpha: f32) -> vec3<f32> {
    let phi = 2.0 * PI * u.x;
    let cos_theta = sqrt((1.0 - u.y) / (1.0 + (alpha * alpha - 1.0) * u.y));
    let sin_theta = sqrt(1.0 - cos_theta * cos_theta);
    return vec3<f32>(sin_theta * cos(phi), sin_theta * sin(phi), cos_theta);
}
// ANCHOR_END: sampling
