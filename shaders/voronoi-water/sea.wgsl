// Chapter 11: the endless sea. One fixed grid of vertices follows the
// boat in whole cells; each vertex is lifted by chapter 07's waves at its
// place in the world, so the waves stay where they are while the grid
// moves under them. Its colour is the Voronoi water texture, repeated,
// lit by the sun (less where the boat's shadow falls) and fogged into the
// sky at the horizon.
#import lighting::lights::frame
#import shadows::shadow::sunlit
#import water::waves::wave_sum
#import voronoi_water::atmosphere::fogged

// ANCHOR: uniform
struct Sea {
    waves: array<vec4<f32>, 8>,
    speeds: array<vec4<f32>, 2>,
    // xy: the grid's first vertex, in cells from the world's origin (whole
    // numbers when it snaps); z: metres per cell; w: the waves' time (s).
    grid: vec4<f32>,
    // x: metres per repeat of the water texture; y: 1 to paint it, 0 for
    // one flat colour; z: vertices along each side of the grid.
    look: vec4<f32>,
};
@group(2) @binding(0) var<uniform> sea: Sea;
@group(2) @binding(1) var water_texture: texture_2d<f32>;
@group(2) @binding(2) var repeat_sampler: sampler;
// ANCHOR_END: uniform

struct SeaPoint {
    world: vec3<f32>,
    normal: vec3<f32>,
};

// ANCHOR: vertex
// Vertex `index` of the grid: its column and row, where that puts it in
// the world, and the waves' height and normal there.
fn sea_point(index: u32) -> SeaPoint {
    let side = u32(sea.look.z);
    let cell = vec2<f32>(f32(index % side), f32(index / side)) + sea.grid.xy;
    let p = cell * sea.grid.z;
    let sum = wave_sum(sea.waves, sea.speeds, p, sea.grid.w);
    return SeaPoint(vec3<f32>(p.x, sum.x, p.y), normalize(vec3<f32>(-sum.y, 1.0, -sum.z)));
}
// ANCHOR_END: vertex

struct SeaOutput {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) world: vec3<f32>,
    @location(1) normal: vec3<f32>,
};

@vertex
fn vs_sea(@builtin(vertex_index) index: u32) -> SeaOutput {
    let point = sea_point(index);
    return SeaOutput(frame.view_proj * vec4<f32>(point.world, 1.0), point.world, point.normal);
}

// ANCHOR: fragment
@fragment
fn fs_sea(in: SeaOutput) -> @location(0) vec4<f32> {
    let n = normalize(in.normal);
    var albedo = vec3<f32>(0.03, 0.2, 0.35);
    if sea.look.y == 1.0 {
        albedo = textureSample(water_texture, repeat_sampler, in.world.xz / sea.look.x).rgb;
    }
    let l = frame.sun_direction.xyz;
    let v = normalize(frame.eye.xyz - in.world);
    let light = sunlit(in.world, n, in.clip_position.xy);
    // Toon light: the sun's side of a wave lit, the far side a band darker.
    let facing = mix(0.6, 1.0, smoothstep(-0.05, 0.15, dot(n, l)));
    var colour = albedo * (frame.ambient.rgb + frame.sun_colour.rgb * light * facing);
    // Glints: a hard-edged highlight, bright enough to bloom.
    let h = normalize(l + v);
    let glint = smoothstep(0.992, 0.996, dot(n, h));
    colour += frame.sun_colour.rgb * light * glint * 3.0;
    return vec4<f32>(fogged(colour, in.world), 1.0);
}
// ANCHOR_END: fragment

// The `grid` view: the grid's edges, dark over the bright sea.
@fragment
fn fs_wire(in: SeaOutput) -> @location(0) vec4<f32> {
    return vec4<f32>(0.01, 0.01, 0.05, 1.0);
}

// ANCHOR: probe
// For the tests: vertex i of the grid lands on pixel (i % side, i / side)
// of a side × side target, which records where the vertex shader put it.
struct ProbeOutput {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) world: vec3<f32>,
};

@vertex
fn vs_probe(@builtin(vertex_index) index: u32) -> ProbeOutput {
    let side = f32(u32(sea.look.z));
    let pixel = vec2<f32>(f32(index % u32(side)), f32(index / u32(side))) + 0.5;
    let clip = vec2<f32>(pixel.x / side * 2.0 - 1.0, 1.0 - pixel.y / side * 2.0);
    return ProbeOutput(vec4<f32>(clip, 0.0, 1.0), sea_point(index).world);
}

@fragment
fn fs_probe(in: ProbeOutput) -> @location(0) vec4<f32> {
    return vec4<f32>(in.world, 1.0);
}
// ANCHOR_END: probe
