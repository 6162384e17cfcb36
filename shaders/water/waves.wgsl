// Chapter 07's waves as a module: a sum of eight directional sine waves,
// its height and its slope. Chapter 07's lake and chapter 11's sea both
// call it; waves.rs has the same sums on the CPU.
#define_import_path water::waves

// ANCHOR: waves
// h = Σ A sin(k (d · p − c t)) at point p and time t, and its slope
// Σ A k d cos(k (d · p − c t)), for the normal. Each wave: xy direction,
// z amplitude (m), w wavelength (m); speeds in m/s, four to a vec4.
// Returns (height, slope.x, slope.y).
fn wave_sum(waves: array<vec4<f32>, 8>, speeds: array<vec4<f32>, 2>, p: vec2<f32>, time: f32) -> vec3<f32> {
    var height = 0.0;
    var slope = vec2<f32>(0.0);
    for (var i = 0u; i < 8u; i++) {
        let wave = waves[i];
        let speed = speeds[i / 4u][i % 4u];
        let k = 6.2831853 / wave.w;
        let phase = k * (dot(wave.xy, p) - speed * time);
        height += wave.z * sin(phase);
        slope += wave.z * k * cos(phase) * wave.xy;
    }
    return vec3<f32>(height, slope);
}
// ANCHOR_END: waves
