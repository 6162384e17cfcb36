// Chapter 08: the sky as a light. Its radiance by direction (the gradient
// sky.wgsl draws), that radiance projected on the first nine spherical
// harmonics (irradiance.wgsl does it on the GPU when the sky changes), and
// the irradiance those nine numbers give a surface facing any way
// (Ramamoorthi and Hanrahan 2001). Pure functions, no bindings.
#define_import_path lighting::sky_light

const PI: f32 = 3.14159265358979;

// ANCHOR: radiance
// The sky's light from `direction`: from the horizon's colour to the
// zenith's as the direction rises, and `ground` below the horizon.
fn sky_radiance(direction: vec3<f32>, horizon: vec3<f32>, zenith: vec3<f32>, ground: vec3<f32>) -> vec3<f32> {
    if direction.y < 0.0 {
        return ground;
    }
    return mix(horizon, zenith, smoothstep(0.0, 0.6, direction.y));
}
// ANCHOR_END: radiance

// ANCHOR: basis
// The first nine real spherical harmonics at unit vector d: one constant,
// three linear, five quadratic (l = 0, 1, 2).
fn sh_basis(d: vec3<f32>) -> array<f32, 9> {
    return array<f32, 9>(
        0.282095,
        0.488603 * d.y,
        0.488603 * d.z,
        0.488603 * d.x,
        1.092548 * d.x * d.y,
        1.092548 * d.y * d.z,
        0.315392 * (3.0 * d.z * d.z - 1.0),
        1.092548 * d.x * d.z,
        0.546274 * (d.x * d.x - d.y * d.y),
    );
}

// The light falling on a surface facing n, from a sky whose radiance has
// the coefficients `sh`: each band of the radiance convolved with the
// clamped cosine, whose own coefficients are π, 2π/3 and π/4.
fn sh_irradiance(sh: array<vec4<f32>, 9>, n: vec3<f32>) -> vec3<f32> {
    let y = sh_basis(n);
    let band = array<f32, 9>(PI, 2.0 * PI / 3.0, 2.0 * PI / 3.0, 2.0 * PI / 3.0, PI / 4.0, PI / 4.0, PI / 4.0, PI / 4.0, PI / 4.0);
    var irradiance = vec3<f32>(0.0);
    for (var k = 0u; k < 9u; k++) {
        irradiance += band[k] * y[k] * sh[k].rgb;
    }
    return max(irradiance, vec3<f32>(0.0));
}
// ANCHOR_END: basis
